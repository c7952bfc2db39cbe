#include <algorithm>
#include <charconv>
#include <cmath>
#include <memory>
#include <numbers>
#include <ostream>
#include <random>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include <gtest/gtest.h>

#include "nckit/drive/variable_period_servo.hpp"
#include "nckit/process/fts/fast_tool_servo.hpp"

namespace nckit {
namespace {

constexpr double pi = std::numbers::pi;

//! A barrel-shaped oval skirt: D 89.8 .. 89.98 mm, ovality growing from e0 to e1 over 50 mm,
//! r = D/2 - (E/4)(1 - cos 2 phi); the fast axis cuts it about the mean radius D/2 - E/4.
FtsProfile piston(double e0 = 0.4, double e1 = 0.8) {
    return [=](double theta_deg, double z_mm) {
        const double d = 89.98 - 0.18 * std::pow((z_mm - 30.0) / 30.0, 2);
        const double e = e0 + (e1 - e0) * z_mm / 50.0;
        const double r = d / 2 - e / 4 * (1 - std::cos(2 * theta_deg * pi / 180));
        return FtsDemand{r, r - (d / 2 - e / 4)};
    };
}

//! The job of the issue on a short stretch of the piston: 2 mm at the large-ovality end.
FtsParameters short_job(double model_error, double ripple) {
    FtsParameters p;
    p.servo.model_error = model_error;
    p.ripple.fraction = ripple;
    p.z_start_mm = 48.0;
    p.z_end_mm = 50.0;
    return p;
}

struct Case {
    double model_error;
    double ripple;
};

void PrintTo(const Case& c, std::ostream* out) {
    *out << "model error " << c.model_error << ", ripple " << c.ripple;
}

class FtsJob : public testing::TestWithParam<Case> {};

TEST_P(FtsJob, LearningBeatsFeedforwardBeatsNothing) {
    const Result<FtsSimulation> done =
        simulate_fast_tool_servo(short_job(GetParam().model_error, GetParam().ripple), piston());
    ASSERT_TRUE(done.ok()) << format_diagnostic(done.diagnostics().front());
    const FtsSimulation& s = *done;
    EXPECT_EQ(s.cut_ticks, 20 * 360 + 1);
    EXPECT_EQ(s.ticks, 40 * 360 + 1);
    EXPECT_NEAR(s.tick_rate_hz, 15000.0, 1e-9);
    // E = 0.8 at 2500 rpm on 135 Hz, zeta 0.3: |1 - G| ~ 0.74 of 0.2 mm uncompensated; the
    // feedforward is off by what the model is off; learning leaves nm.
    EXPECT_GT(s.uncompensated.pv_um, 250.0);
    EXPECT_GT(s.feedforward.pv_um, 10.0);
    EXPECT_LT(s.feedforward.pv_um, 50.0);
    EXPECT_LT(s.learning.pv_um, 1.0);  // the goal
    EXPECT_LT(s.learning.pv_um, 0.2);  // and what it does
    EXPECT_LT(s.learning.pv_um, s.feedforward.pv_um / 50);
    EXPECT_LT(s.feedforward.pv_um, s.uncompensated.pv_um / 5);
    EXPECT_LT(s.learning.rms_um, s.feedforward.rms_um);
    EXPECT_LT(s.feedforward.rms_um, s.uncompensated.rms_um);
    for (const FtsRunResult* r : {&s.uncompensated, &s.feedforward, &s.learning}) {
        EXPECT_LE(r->rms_um, r->pv_um);
        EXPECT_EQ(r->turn_pv_um.size(), 40u);
        EXPECT_LT(r->peak_command_mm, 0.5);
    }
}

// Error per turn falls turn by turn through the air turns until it meets the DAC's floor.
TEST_P(FtsJob, LearningConvergesTurnByTurn) {
    const Result<FtsSimulation> done =
        simulate_fast_tool_servo(short_job(GetParam().model_error, GetParam().ripple), piston());
    ASSERT_TRUE(done.ok());
    const std::vector<double>& pv = done->learning.turn_pv_um;
    for (std::size_t k = 2; k < 8; ++k) EXPECT_LT(pv[k], 0.75 * pv[k - 1]) << "turn " << k;
    EXPECT_GT(pv[2], 1.0);
    const int settled = settled_turn(pv, 0.1);
    EXPECT_GE(settled, 5);
    EXPECT_LE(settled, 12);
    // Without learning the error never falls below the feedforward's.
    EXPECT_EQ(settled_turn(done->feedforward.turn_pv_um, 1.0), -1);
}

INSTANTIATE_TEST_SUITE_P(ModelErrorAndRipple, FtsJob,
                         testing::Values(Case{0.1, 0.002}, Case{-0.1, 0.002}, Case{0.1, 0.0}, Case{-0.1, 0.0}),
                         [](const testing::TestParamInfo<Case>& param) {
                             return std::string(param.param.model_error > 0 ? "Over10" : "Under10") +
                                    (param.param.ripple > 0 ? "Ripple" : "Steady");
                         });

// Random jobs (seeded): speed, ovality, model error within ±10 %, ripple within 0.3 %, counts.
TEST(FtsSimulation, RandomJobsMeetTheGoal) {
    std::mt19937_64 random(2024);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 12; ++trial) {
        FtsParameters p;
        p.rpm = 1500 + 1000 * unit(random);
        p.encoder_counts = trial % 3 == 0 ? 500 : 360;
        p.servo.model_error = -0.1 + 0.2 * unit(random);
        p.ripple.fraction = 0.003 * unit(random);
        p.ripple.phase_deg = 360 * unit(random);
        p.z_start_mm = 45 * unit(random);
        p.z_end_mm = p.z_start_mm + 1.0;
        const double e = 0.3 + 0.5 * unit(random);
        const Result<FtsSimulation> done = simulate_fast_tool_servo(p, piston(e, e));
        ASSERT_TRUE(done.ok()) << trial;
        EXPECT_LT(done->learning.pv_um, 1.0) << trial;
        EXPECT_LT(done->learning.pv_um, done->feedforward.pv_um) << trial;
        EXPECT_LT(done->feedforward.pv_um, done->uncompensated.pv_um) << trial;
        EXPECT_LT(done->learning_contraction.any_frequency, 1.0) << trial;
    }
}

std::vector<std::vector<double>> parse_csv(const std::string& text, std::string& header) {
    std::istringstream in(text);
    std::getline(in, header);
    std::vector<std::vector<double>> rows;
    std::string line;
    while (std::getline(in, line)) {
        std::vector<double> row;
        const char* at = line.data();
        const char* end = line.data() + line.size();
        while (at < end) {
            double v = 0;
            const auto [next, ec] = std::from_chars(at, end, v);
            EXPECT_EQ(ec, std::errc{});
            row.push_back(v);
            at = next + 1;  // past the comma
        }
        rows.push_back(row);
    }
    return rows;
}

// Anyone can take the CSV, start the true servo at the first row, hold each row's command until
// the next row's time and land on every row's actual position.
TEST(FtsSimulation, TraceReSimulatesFromItsOwnText) {
    for (double ripple : {0.0, 0.002}) {
        FtsParameters p = short_job(0.1, ripple);
        p.ripple.slow_fraction = ripple;  // not synchronous: no two ticks alike
        p.trace_turns = 2;
        const Result<FtsSimulation> done = simulate_fast_tool_servo(p, piston());
        ASSERT_TRUE(done.ok());
        std::string header;
        const auto rows = parse_csv(format_fts_trace_csv(done->trace), header);
        EXPECT_EQ(header, "t_s,theta_deg,z_mm,radius_mm,target_mm,command_mm,actual_mm,actual_mm_s");
        ASSERT_EQ(rows.size(), 2u * 360 + 1);
        EXPECT_NEAR(rows.back()[2], 50.0, 1e-9);  // ends at the end of the cut
        EXPECT_NEAR(rows.front()[2], 49.8, 1e-9);
        drive::VariablePeriodServo servo(drive::ServoParameters::from_natural_frequency(1.0, 135.0, 0.3),
                                         {rows[0][6], rows[0][7]});
        double worst = 0.0;
        for (std::size_t n = 0; n + 1 < rows.size(); ++n) {
            ASSERT_EQ(rows[n].size(), 8u);
            const double h = rows[n + 1][0] - rows[n][0];
            ASSERT_GT(h, 0.0);
            const drive::ServoState x = servo.step(rows[n][5], h);
            worst = std::max(worst, std::abs(x.position - rows[n + 1][6]));
            // target is the radius minus the mean radius (D/2 - E/4) of the section: cos 2 phi.
            const double e = 0.4 + 0.4 * rows[n][2] / 50;
            EXPECT_NEAR(rows[n][4], e / 4 * std::cos(2 * rows[n][1] * pi / 180), 1e-9);
        }
        EXPECT_LT(worst, 1e-9) << ripple;
        // The trace is the learned run: well within a µm of the target.
        for (const auto& row : rows) EXPECT_NEAR(row[6], row[4], 1e-3);
    }
}

// Commands leave the controller through the DAC: whole codes, 15.26 nm apart for 16 bits over
// 1 mm; a coarse DAC sets a floor the learning cannot go under.
TEST(FtsSimulation, DacQuantisationIsVisible) {
    FtsParameters p = short_job(0.1, 0.002);
    p.trace_turns = 1;
    const Result<FtsSimulation> fine = simulate_fast_tool_servo(p, piston());
    ASSERT_TRUE(fine.ok());
    EXPECT_EQ(fine->dac_step_mm, 1.0 / 65536);
    std::size_t odd_codes = 0;
    for (const FtsTraceRow& row : fine->trace) {
        const double codes = row.command_mm / fine->dac_step_mm;
        EXPECT_EQ(codes, std::round(codes));
        odd_codes += static_cast<std::int64_t>(codes) % 2 != 0;
    }
    EXPECT_GT(odd_codes, fine->trace.size() / 4);  // the last bit is in use
    p.servo.dac_bits = 11;                         // 0.49 µm steps
    const Result<FtsSimulation> coarse = simulate_fast_tool_servo(p, piston());
    ASSERT_TRUE(coarse.ok());
    // Converged air turns: the coarse DAC's floor is near its step, the fine one's far below.
    const double fine_floor = fine->learning.turn_pv_um[18];
    const double coarse_floor = coarse->learning.turn_pv_um[18];
    EXPECT_LT(fine_floor, 0.02);
    EXPECT_GT(coarse_floor, 5 * fine_floor);
    EXPECT_GT(coarse->learning.pv_um, 2 * fine->learning.pv_um);
}

TEST(FtsSimulation, SpindleRippleNeedsTheLearning) {
    FtsParameters steady = short_job(0.1, 0.0);
    FtsParameters rippled = short_job(0.1, 0.02);  // 2 %: exaggerated so it stands out
    const Result<FtsSimulation> a = simulate_fast_tool_servo(steady, piston());
    const Result<FtsSimulation> b = simulate_fast_tool_servo(rippled, piston());
    ASSERT_TRUE(a.ok() && b.ok());
    // The feedforward runs at the nominal period: ripple adds to its error; learning in the
    // angle domain removes a once-per-turn ripple with the rest.
    EXPECT_GT(b->feedforward.pv_um, a->feedforward.pv_um + 2.0);
    EXPECT_GT(b->uncompensated.pv_um, a->uncompensated.pv_um);
    EXPECT_LT(b->learning.pv_um, 0.2);
    EXPECT_GT(b->duration_s, a->duration_s);  // slower on average: mean 1 / (1 + a sin) > 1
}

TEST(FtsSimulation, StrokeTooShortIsAnError) {
    FtsParameters p = short_job(0.1, 0.002);
    p.servo.stroke_mm = 0.3;  // ±0.15 mm cannot make ±0.2 mm
    p.where = make_location(std::make_shared<const std::string>("piston.toml"), 12, 1);
    const Result<FtsSimulation> done = simulate_fast_tool_servo(p, piston());
    ASSERT_FALSE(done.ok());
    EXPECT_EQ(done.diagnostics().front().code, "fts-stroke");
    EXPECT_EQ(format_diagnostic(done.diagnostics().front()).rfind("piston.toml:12:1: error: the uncompensated run", 0),
              0u)
        << format_diagnostic(done.diagnostics().front());
}

// A model 30 % under the axis puts the learning past its stability limit: it grows until the DAC
// clamps, and the error says why.
TEST(FtsSimulation, DivergingLearningIsReported) {
    FtsParameters p = short_job(-0.3, 0.002);
    p.z_start_mm = 0.0;
    p.z_end_mm = 4.0;
    const Result<FtsSimulation> done = simulate_fast_tool_servo(p, piston());
    ASSERT_FALSE(done.ok());
    EXPECT_EQ(done.diagnostics().front().code, "fts-stroke");
    EXPECT_NE(done.diagnostics().front().message.find("the learning diverges"), std::string::npos)
        << done.diagnostics().front().message;
}

TEST(FtsSimulation, ProfileMustBeFinite) {
    const FtsProfile broken = [](double theta_deg, double z_mm) {
        return FtsDemand{45.0, theta_deg > 100 && z_mm > 49 ? NAN : 0.0};
    };
    const Result<FtsSimulation> done = simulate_fast_tool_servo(short_job(0.1, 0.0), broken);
    ASSERT_FALSE(done.ok());
    EXPECT_EQ(done.diagnostics().front().code, "fts-profile");
}

TEST(FtsSimulation, ParametersAreChecked) {
    EXPECT_TRUE(check_fts_parameters(FtsParameters{}).empty());
    FtsParameters p;
    p.servo.natural_frequency_hz = 0;
    p.servo.damping = -0.1;
    p.servo.model_error = -1.0;
    p.servo.dac_bits = 40;
    p.servo.stroke_mm = 0;
    p.rpm = -5;
    p.ripple.fraction = 0.6;
    p.feed_mm_rev = 0;
    p.z_end_mm = p.z_start_mm;
    p.learning.gain = 2.5;
    p.learning.harmonics = 200;
    const Diagnostics problems = check_fts_parameters(p);
    EXPECT_EQ(problems.size(), 11u);
    for (const Diagnostic& d : problems) EXPECT_EQ(d.code, "fts-parameter");
    EXPECT_FALSE(simulate_fast_tool_servo(p, piston()).ok());
    FtsParameters long_job;
    long_job.feed_mm_rev = 1e-6;
    EXPECT_EQ(check_fts_parameters(long_job).size(), 1u);
}

TEST(FtsSimulation, SettledTurn) {
    EXPECT_EQ(settled_turn({5, 2, 0.5, 0.8, 0.3}, 1.0), 2);
    EXPECT_EQ(settled_turn({5, 2, 0.5, 1.8, 0.3}, 1.0), 4);
    EXPECT_EQ(settled_turn({5, 2, 0.5, 0.8, 1.3}, 1.0), -1);
    EXPECT_EQ(settled_turn({0.1}, 1.0), 0);
    EXPECT_EQ(settled_turn({}, 1.0), -1);
}

}  // namespace
}  // namespace nckit
