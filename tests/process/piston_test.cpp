#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "nckit/cam/cam_table.hpp"
#include "nckit/process/piston/piston.hpp"
#include "nckit/process/piston/piston_svg.hpp"

namespace nckit {
namespace {

//! A piston job on stations `z` with D and E linear between the ends given, a shape line and
//! extra [piston] lines.
struct JobSpec {
    double z_from_mm = 0, z_to_mm = 50;
    double d_from_mm = 89.8, d_to_mm = 89.92;
    double e_from_mm = 0.4, e_to_mm = 0.8;
    std::string shape = R"(shape = "ellipse2")";
    std::string extra;  //!< more [piston] lines
    double stroke_mm = 1.0;
    double rpm = 2500;
};

std::string job_text(const JobSpec& s) {
    return fmt::format(
        "[piston]\nrpm = {}\nz_mm = [{}, {}, {}]\nmajor_diameter_mm = [{}, {}, {}]\novality_mm = [{}, {}, {}]\n{}\n{}"
        "[servo]\nnatural_frequency_hz = 135.0\ndamping = 0.3\nstroke_mm = {}\nmodel_error = 0.10\n",
        s.rpm, s.z_from_mm, 0.5 * (s.z_from_mm + s.z_to_mm), s.z_to_mm, s.d_from_mm, 0.5 * (s.d_from_mm + s.d_to_mm),
        s.d_to_mm, s.e_from_mm, 0.5 * (s.e_from_mm + s.e_to_mm), s.e_to_mm, s.shape, s.extra, s.stroke_mm);
}

cam::PistonJob parse(const JobSpec& spec) {
    Result<cam::PistonJob> file = cam::parse_piston_job(job_text(spec), "job.toml");
    if (!file) throw std::runtime_error(format_diagnostic(file.diagnostics().front()));
    return std::move(file).value();
}

//! (max + min) / 2 of the exact drawing over the turn at `z_mm`, every 0.01°.
double exact_mid_mm(const cam::PistonJob& job, double z_mm) {
    double high = -1e300, low = 1e300;
    for (int k = 0; k < 36000; ++k) {
        const double r = job.profile.radius_mm(k * 0.01, z_mm);
        high = std::max(high, r);
        low = std::min(low, r);
    }
    return 0.5 * (high + low);
}

TEST(PistonJob, SourceAndMapping) {
    JobSpec spec;
    spec.extra = "encoder_counts = 720\nfeed_mm_rev = 0.2\n";
    const cam::PistonJob file = parse(spec);
    EXPECT_EQ(file.source.servo.line, 9u);
    EXPECT_EQ(file.source.stroke.line, 12u);
    EXPECT_EQ(file.source.encoder_counts.line, 7u);
    EXPECT_EQ(file.source.servo.file_name(), "job.toml");
    EXPECT_FALSE(file.source.ripple_given);

    const FtsParameters p = piston_fts_parameters(file);
    EXPECT_EQ(p.servo.natural_frequency_hz, 135.0);
    EXPECT_EQ(p.servo.damping, 0.3);
    EXPECT_EQ(p.servo.model_error, 0.10);
    EXPECT_EQ(p.servo.dac_bits, 16);
    EXPECT_EQ(p.servo.stroke_mm, 1.0);
    EXPECT_EQ(p.rpm, 2500);
    EXPECT_EQ(p.encoder_counts, 720);
    EXPECT_EQ(p.feed_mm_rev, 0.2);
    EXPECT_EQ(p.z_start_mm, 0);
    EXPECT_EQ(p.z_end_mm, 50);
    EXPECT_EQ(p.ripple.fraction, SpindleRipple{}.fraction);  // left out: the simulation's default
    EXPECT_EQ(p.learning.harmonics, FtsLearning{}.harmonics);
    EXPECT_EQ(p.where.line, 9u);
}

TEST(PistonJob, RippleAsGivenAndHarmonicsCapped) {
    JobSpec spec;
    spec.extra = "spindle_ripple = 0.0\nencoder_counts = 20\n";
    const cam::PistonJob file = parse(spec);
    EXPECT_TRUE(file.source.ripple_given);
    const FtsParameters p = piston_fts_parameters(file);
    EXPECT_EQ(p.ripple.fraction, 0.0);
    EXPECT_EQ(p.learning.harmonics, 9);  // 2 h + 1 <= 20 counts
    EXPECT_TRUE(check_fts_parameters(p).empty());
}

// Property: on random drawings of every shape the reference is the middle of the turn's radial
// range, so the fast axis swings symmetrically about mid-stroke.
TEST(StrokeReference, MiddleOfTheRangeOnRandomDrawings) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> diameter(40, 140), ovality(0.05, 0.9), slope(-0.2, 0.2), u(0, 1);
    const std::array<std::string, 4> shapes{R"(shape = "ellipse2")", R"(shape = "ellipse")",
                                            "shape = \"ellipse4\"\ne4_mm = 0.01",
                                            R"~(shape_formula = "E/4*(1 - cosd(2*PHI)) + 0.003*(1 - cosd(4*PHI))")~"};
    for (int trial = 0; trial < 40; ++trial) {
        JobSpec spec;
        spec.z_from_mm = -20 * u(rng);
        spec.z_to_mm = spec.z_from_mm + 5 + 60 * u(rng);
        spec.d_from_mm = diameter(rng);
        spec.d_to_mm = spec.d_from_mm + slope(rng);
        spec.e_from_mm = ovality(rng);
        spec.e_to_mm = ovality(rng);
        spec.shape = shapes[static_cast<std::size_t>(trial) % shapes.size()];
        spec.rpm = 500;
        SCOPED_TRACE(job_text(spec));
        const cam::PistonJob file = parse(spec);
        const cam::CamTable table = cam::build_cam_table(file);
        const StrokeReference reference(table, 41);
        for (int k = 0; k <= 12; ++k) {
            const double z = spec.z_from_mm + (spec.z_to_mm - spec.z_from_mm) * k / 12.0;
            EXPECT_NEAR(reference.radius_mm(z), exact_mid_mm(file, z), 2e-6) << "z " << z;
        }
        if (trial % shapes.size() == 0) {  // ellipse2: the mid radius is D/2 − E/4 exactly
            const double z = spec.z_to_mm;
            const double d = file.profile.major_diameter_mm(z), e = file.profile.ovality_mm(z);
            EXPECT_NEAR(reference.radius_mm(z), d / 2 - e / 4, 1e-7);
        }
    }
}

//! A short cut (2 mm) of the issue's piston: every run of it takes a fraction of a second.
JobSpec short_job() {
    JobSpec spec;
    spec.z_from_mm = 48;
    spec.z_to_mm = 50;
    spec.d_from_mm = 89.93;
    spec.d_to_mm = 89.92;
    spec.e_from_mm = 0.78;
    spec.e_to_mm = 0.8;
    return spec;
}

TEST(SimulatePiston, LearningMeetsTheGoal) {
    const cam::PistonJob file = parse(short_job());
    const Result<PistonSimulation> done = simulate_piston(file);
    ASSERT_TRUE(done.ok()) << format_diagnostic(done.diagnostics().front());
    const PistonSimulation& s = *done;
    EXPECT_LE(s.fts.learning.pv_um, 1.0);
    EXPECT_LT(s.fts.learning.pv_um, s.fts.feedforward.pv_um);
    EXPECT_LT(s.fts.feedforward.pv_um, s.fts.uncompensated.pv_um);
    EXPECT_NEAR(s.fit.peak_displacement_mm, 0.2, 1e-6);  // half the radial range E/2 at Z 50
    EXPECT_LE(s.table_error_bound_mm, s.table_tolerance_mm);
    EXPECT_GE(s.settled_turn, 0);
    EXPECT_LT(s.settled_turn, s.parameters.air_turns + 20);
    // The trace's targets are the cam table less the reference: within the swing, centred.
    ASSERT_EQ(s.fts.trace.size(), 3u * 360u + 1u);
    double high = -1, low = 1;
    for (const FtsTraceRow& row : s.fts.trace) {
        high = std::max(high, row.target_mm);
        low = std::min(low, row.target_mm);
    }
    EXPECT_NEAR(high, -low, 2e-3);  // Z moves 0.3 mm over the trace: E/2 changes by 1.5 µm
    EXPECT_LE(std::max(high, -low), s.fit.peak_displacement_mm + 1e-9);
}

// Property: random ovality, speed and model error within what the job reader accepts; the
// learning run always beats feedforward, which beats nothing, and the swing is E/4.
TEST(SimulatePiston, RandomJobsKeepTheOrder) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> ovality(0.2, 0.9), rpm(600, 2500), error(0.0, 0.15);
    for (int trial = 0; trial < 6; ++trial) {
        JobSpec spec = short_job();
        spec.e_from_mm = ovality(rng);
        spec.e_to_mm = spec.e_from_mm;
        spec.rpm = rpm(rng);
        std::string text = job_text(spec);
        text.replace(text.find("model_error = 0.10"), 18, fmt::format("model_error = {}", error(rng)));
        SCOPED_TRACE(text);
        const Result<cam::PistonJob> file = cam::parse_piston_job(text, "random.toml");
        ASSERT_TRUE(file.ok()) << format_diagnostic(file.diagnostics().front());
        PistonRunOptions options;
        options.trace_turns = 0;
        const Result<PistonSimulation> done = simulate_piston(*file, options);
        ASSERT_TRUE(done.ok()) << format_diagnostic(done.diagnostics().front());
        EXPECT_LT(done->fts.learning.pv_um, done->fts.feedforward.pv_um);
        EXPECT_LT(done->fts.feedforward.pv_um, done->fts.uncompensated.pv_um);
        EXPECT_LE(done->fts.learning.pv_um, 1.0);
        EXPECT_NEAR(done->fit.peak_displacement_mm, spec.e_from_mm / 4, 1e-6);
        EXPECT_TRUE(done->fts.trace.empty());
    }
}

TEST(SimulatePiston, StrokeAndEncoderDiagnostics) {
    JobSpec spec = short_job();
    spec.stroke_mm = 0.4;  // exactly the 0.4 mm range: the top DAC code is a step short of +0.2
    Result<PistonSimulation> done = simulate_piston(parse(spec));
    ASSERT_FALSE(done.ok());
    EXPECT_EQ(done.diagnostics().front().code, "piston-stroke");
    EXPECT_EQ(done.diagnostics().front().location.line, 10u);
    EXPECT_EQ(done.diagnostics().front().location.column, 13u);

    spec = short_job();
    spec.extra = "encoder_counts = 6\n";
    done = simulate_piston(parse(spec));
    ASSERT_FALSE(done.ok());
    EXPECT_EQ(done.diagnostics().front().code, "piston-encoder");
    EXPECT_EQ(done.diagnostics().front().location.line, 7u);
}

TEST(PistonSvg, PlotsOfEveryStationAndRun) {
    JobSpec spec = short_job();
    const cam::PistonJob file = parse(spec);
    const std::string section = piston_section_svg(file);
    EXPECT_EQ(section.rfind("<svg", 0), 0u);
    EXPECT_NE(section.find("</svg>"), std::string::npos);
    std::size_t polylines = 0;
    for (std::size_t at = section.find("<polyline"); at != std::string::npos; at = section.find("<polyline", at + 1)) {
        ++polylines;
    }
    EXPECT_EQ(polylines, 3u);
    // 0.4 mm of drop on a 45 mm radius drawn at most 30 % of the base circle: ×25 (1-2-2.5-5).
    EXPECT_NE(section.find("magnified ×25<"), std::string::npos);

    const std::string drawing = piston_drawing_svg(file);
    std::size_t circles = 0;
    for (std::size_t at = drawing.find("<circle"); at != std::string::npos; at = drawing.find("<circle", at + 1)) {
        ++circles;
    }
    EXPECT_EQ(circles, 6u);  // D and E at 3 stations

    PistonRunOptions options;
    options.trace_turns = 0;
    const Result<PistonSimulation> done = simulate_piston(file, options);
    ASSERT_TRUE(done.ok());
    const std::string turns = piston_turn_error_svg(done->fts, options.air_turns);
    for (const std::string& text : {section, drawing, turns}) {
        EXPECT_EQ(text.find("nan"), std::string::npos);
        EXPECT_EQ(text.find("inf"), std::string::npos);
    }
}

}  // namespace
}  // namespace nckit
