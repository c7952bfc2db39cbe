#include <cmath>
#include <random>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "nckit/process/crosshatch/crosshatch.hpp"
#include "nckit/process/crosshatch/crosshatch_scan.hpp"

namespace nckit {
namespace {

std::string job_text(int heads, double lines, double index_deg, std::string extra = "") {
    return fmt::format(R"([crosshatch]
bore_diameter_mm = 92.0
bore_length_mm = 150.0
lead_screw_pitch_mm = 5.0
heads = {}
lines_per_length = {}
feed_screw_rpm = 60.0
step_angle_deg = 1.5
gear_ratio = 3.0
timer_clock_hz = 1000000
index_deg = {}
{}
)",
                       heads, lines, index_deg, extra);
}

CrosshatchPlan plan_of(const std::string& text) {
    Result<CrosshatchJob> job = parse_crosshatch_job(text, "job.toml");
    EXPECT_TRUE(job.ok()) << (job.ok() ? "" : format_diagnostic(job.diagnostics().front()));
    Result<CrosshatchPlan> plan = plan_crosshatch(*job);
    EXPECT_TRUE(plan.ok()) << (plan.ok() ? "" : format_diagnostic(plan.diagnostics().front()));
    return *plan;
}

Diagnostics errors_of(const std::string& text) {
    Result<CrosshatchJob> job = parse_crosshatch_job(text, "job.toml");
    if (!job) return job.diagnostics();
    Result<CrosshatchPlan> plan = plan_crosshatch(*job);
    return plan ? Diagnostics{} : plan.diagnostics();
}

// docs/processes/crosshatch.md, worked: D 92, H 150, L 5, V2 60, N 15, 1.5°, gear 3, 1 MHz.
struct Worked {
    int heads;
    double index_deg;
    double rotation_rpm;
    double angle_deg;
    std::uint32_t rotation_divisor;
    double round_trip_deg;
    double index_move_deg;
};

TEST(Crosshatch, PapersThreeExamplesMatchTheWorkedTable) {
    for (const Worked& w : {Worked{12, 30, 2.5, 45.0952, 33333, 180, -150},
                            Worked{8, 45, 3.75, 30.9432, 22222, 270, 135}, Worked{6, 60, 5.0, 23.4553, 16667, 0, 60}}) {
        SCOPED_TRACE(w.heads);
        const CrosshatchPlan plan = plan_of(job_text(w.heads, 15, w.index_deg));
        EXPECT_NEAR(plan.rotation_rpm, w.rotation_rpm, 1e-12);
        EXPECT_NEAR(plan.feed_mm_min, 300.0, 1e-12);
        EXPECT_NEAR(plan.crosshatch_angle_deg, w.angle_deg, 5e-5);
        EXPECT_EQ(plan.rotation.timer.divisor, w.rotation_divisor);
        EXPECT_EQ(plan.feed.timer.divisor, 1389u);  // 1388.89 rounded
        EXPECT_NEAR(plan.feed.timer.speed_error, 1388.8889 / 1389.0 - 1.0, 1e-7);
        EXPECT_NEAR(plan.round_trip_deg, w.round_trip_deg, 1e-9);
        EXPECT_FALSE(plan.special);
        EXPECT_DOUBLE_EQ(plan.index_move_deg, w.index_move_deg);
        EXPECT_NEAR(plan.line_spacing_mm, 10.0, 1e-12);
        EXPECT_EQ(plan.feed_steps_per_stroke, 21600);
    }
}

TEST(Crosshatch, RoundTripThatEqualsTheIndexIsSpecial) {
    // 2·(16.5/8)·360 = 1485 ≡ 45: the cycles step round by the index on their own.
    const CrosshatchPlan plan = plan_of(job_text(8, 16.5, 45));
    EXPECT_TRUE(plan.special);
    EXPECT_EQ(plan.index_move_steps, 0);
    EXPECT_EQ(build_crosshatch_scan(plan).closure_error_steps, 0.0);
}

TEST(Crosshatch, CorrectionTakesTheShorterWayAndHalfATurnGoesForward) {
    EXPECT_DOUBLE_EQ(plan_of(job_text(12, 15, 0)).index_move_deg, 180.0);    // α = 180: forward
    EXPECT_DOUBLE_EQ(plan_of(job_text(12, 15, 1)).index_move_deg, -179.0);   // α = 179: back
    EXPECT_DOUBLE_EQ(plan_of(job_text(12, 15, 359)).index_move_deg, 179.0);  // α = 181: forward
}

TEST(Crosshatch, StepStreamMatchesTheScanAndCloses) {
    const CrosshatchPlan plan = plan_of(job_text(12, 15, 30));
    const CrosshatchScan scan = build_crosshatch_scan(plan);
    std::int64_t feed = 0;
    std::int64_t rotation = 0;
    std::int64_t feed_steps = 0;
    std::int64_t rotation_steps = 0;
    std::int64_t last_ns = -1;
    for_each_crosshatch_step(plan, [&](const StepEvent& e, std::uint8_t) {
        ASSERT_GE(e.t_ns, last_ns);
        last_ns = e.t_ns;
        (e.axis == crosshatch_feed_axis ? feed : rotation) += e.direction;
        ++(e.axis == crosshatch_feed_axis ? feed_steps : rotation_steps);
        // The feed never leaves the bore: Z stays within [-stroke, 0].
        ASSERT_LE(feed, 0);
        ASSERT_GE(feed, -plan.feed_steps_per_stroke);
    });
    EXPECT_EQ(feed, 0);
    EXPECT_EQ(feed_steps, scan.feed_steps);
    EXPECT_EQ(rotation_steps, scan.rotation_steps);
    EXPECT_EQ(rotation % 720, 0);
    EXPECT_EQ(last_ns, std::llround(scan.duration_s * 1e9));
}

TEST(Crosshatch, PhaseTableBytesFollowTheSeedCodes) {
    const CrosshatchPlan plan = plan_of(job_text(6, 15, 60));
    std::vector<std::uint8_t> rotation_ports;
    for_each_crosshatch_step(plan, [&](const StepEvent& e, std::uint8_t port) {
        if (e.axis == crosshatch_rotation_axis && rotation_ports.size() < 6) rotation_ports.push_back(port);
    });
    // Forward from beat A (0BH): AB, B, BC, C, CA, A.
    EXPECT_EQ(rotation_ports, (std::vector<std::uint8_t>{0x09, 0x0D, 0x0C, 0x0E, 0x0A, 0x0B}));
}

// Property: with whole step counts per stroke and an index of whole steps, every pattern closes.
TEST(Crosshatch, RandomPatternsWithWholeStepCountsClose) {
    std::mt19937 random(20261123);
    std::uniform_int_distribution<int> heads_of(1, 24);
    std::uniform_int_distribution<int> steps_of(60, 4000);
    for (int trial = 0; trial < 300; ++trial) {
        const int heads = heads_of(random);
        // N such that N/I turns are a whole number of the 720 steps per head turn.
        const int steps_per_stroke = steps_of(random);
        const double lines = static_cast<double>(steps_per_stroke) * heads / 720.0;
        const double index = 360.0 / heads;
        Result<CrosshatchJob> job = parse_crosshatch_job(job_text(heads, lines, index), "job.toml");
        ASSERT_TRUE(job.ok()) << format_diagnostic(job.diagnostics().front());
        Result<CrosshatchPlan> plan = plan_crosshatch(*job);
        if (!plan) continue;  // a rotation rate the counter cannot make: checked elsewhere
        const CrosshatchScan scan = build_crosshatch_scan(*plan);
        SCOPED_TRACE(fmt::format("heads {} lines {}", heads, lines));
        EXPECT_EQ(plan->rotation_steps_per_stroke, steps_per_stroke);
        // Absolute index targets: closed even when 360/I is no whole number of steps.
        EXPECT_LT(scan.closure_error_steps, 1e-9);
        EXPECT_NEAR(scan.track_angle_deg, plan->crosshatch_angle_deg, 1e-9);
    }
}

// docs/processes/crosshatch.md: divisors 44444 and 2778 (L 5, H 120): 0.0486° off per stroke.
TEST(Crosshatch, FreeRunningTimersDriftAndTheAngleStaysWithinTheQuantisation) {
    std::string text = job_text(12, 18, 30, "timing = \"free_running_timers\"");
    text.replace(text.find("150.0"), 5, "120.0");
    text.replace(text.find("feed_screw_rpm = 60.0"), 21, "feed_screw_rpm = 30.0");
    const CrosshatchPlan plan = plan_of(text);
    EXPECT_EQ(plan.rotation.timer.divisor, 44444u);
    EXPECT_EQ(plan.feed.timer.divisor, 2778u);
    const CrosshatchScan scan = build_crosshatch_scan(plan);
    EXPECT_NEAR(scan.drift_deg_per_stroke, 0.0486, 5e-5);
    EXPECT_GT(scan.closure_error_steps, 1.0);  // 24 strokes of 0.097 steps
    EXPECT_LE(std::abs(scan.track_angle_error_deg), scan.timer_angle_error_bound_deg * 1.001);
    EXPECT_GT(std::abs(scan.track_angle_error_deg), 0.0);
    // The step stream shows the same drift: the rotation steps of the first stroke.
    std::int64_t first_stroke_rotation = 0;
    const auto stroke_end_ns = static_cast<std::int64_t>(plan.feed_steps_per_stroke) * 2778 * 1000;
    for_each_crosshatch_step(plan, [&](const StepEvent& e, std::uint8_t) {
        if (e.axis == crosshatch_rotation_axis && e.t_ns <= stroke_end_ns) ++first_stroke_rotation;
    });
    EXPECT_EQ(first_stroke_rotation, 1080);  // 1080.097 steps' worth of time
    // The same job on one time base has no drift and closes.
    std::string ratio = text;
    ratio.replace(ratio.find("free_running_timers"), 19, "one_time_base");
    const CrosshatchScan exact = build_crosshatch_scan(plan_of(ratio));
    EXPECT_EQ(exact.drift_deg_per_stroke, 0.0);
    EXPECT_EQ(exact.closure_error_steps, 0.0);
}

TEST(Crosshatch, GcodeCommandsWholeStepsAndTheLaser) {
    const CrosshatchPlan plan = plan_of(job_text(8, 15, 45));
    const std::string program = crosshatch_gcode(plan, "bore.toml");
    EXPECT_NE(program.find("G1 Z-150.0000 A675.0000 F300.0000\nG1 Z0.0000 A1350.0000\nM28\nG1 A1485.0000 F1350.0000\n"),
              std::string::npos)
        << program.substr(0, 800);
    EXPECT_NE(program.find("(cycle 8 of 8)"), std::string::npos);
    EXPECT_NE(program.find("M30"), std::string::npos);
}

TEST(Crosshatch, SvgDrawsEveryTrackWrappedAtTheTurn) {
    const CrosshatchPlan plan = plan_of(job_text(12, 15, 30));
    const std::string svg = crosshatch_svg(plan, build_crosshatch_scan(plan));
    std::size_t lines = 0;
    for (std::size_t at = svg.find("stroke=\"#1f5fa8\""); at != std::string::npos;
         at = svg.find("stroke=\"#1f5fa8\"", at + 1)) {
        ++lines;
    }
    // 12 down strokes of 1.25 turns: each crosses one or two multiples of 360°, so 2 or 3 pieces.
    EXPECT_GE(lines, 24u);
    EXPECT_LE(lines, 36u);
    EXPECT_EQ(svg.rfind("</svg>\n"), svg.size() - 7);
}

TEST(CrosshatchJob, ErrorsPointAtTheKey) {
    auto first = [](const std::string& text) {
        std::string all;
        for (const Diagnostic& d : errors_of(text)) all += format_diagnostic(d) + "\n";
        return all.empty() ? std::string("no error") : all;
    };
    EXPECT_NE(first("[crosshatch]\nbore_diameter_mm = -92.0\n")
                  .find("job.toml:2:20: error: 'bore_diameter_mm' must be positive"),
              std::string::npos);
    // A bore given in metres (0.092 for 92 mm) is refused where it stands.
    std::string tiny = job_text(12, 15, 30);
    tiny.replace(tiny.find("92.0"), 4, "0.092");
    EXPECT_NE(first(tiny).find("job.toml:2:20: error: 'bore_diameter_mm' = 0.092 is below any bore-hardening cell"),
              std::string::npos)
        << first(tiny);
    EXPECT_NE(first(job_text(12, 15, 30, "colour = 3")).find("job.toml:12:1: error: unknown key 'colour'"),
              std::string::npos);
    EXPECT_NE(first(job_text(12, 15, 361)).find("job.toml:11:13: error: 'index_deg' must be 0 to 360"),
              std::string::npos);
    EXPECT_NE(first("[crosshatch]\nheads = 2.5\n").find("job.toml:2:9"), std::string::npos);
    EXPECT_NE(first("[crosshat]\n").find("job.toml:1:2: error: unknown table [crosshat]"), std::string::npos);
    EXPECT_NE(first("[crosshatch\n").find("job.toml:1:12: error: toml syntax error"), std::string::npos);
    // 1 line per length over 150 mm with 12 heads: 0.1 rpm of the head is 1.2 steps/s, below 15.26.
    EXPECT_NE(first(job_text(12, 0.5, 30))
                  .find("job.toml:7:18: error: the rotation motor needs 1 steps/s, slower than the counter makes "
                        "(15.259 to 500000"),
              std::string::npos)
        << first(job_text(12, 0.5, 30));
    EXPECT_NE(first(job_text(12, 15, 30, "laser_off_mcode = 27")).find("both M27"), std::string::npos);
}

}  // namespace
}  // namespace nckit
