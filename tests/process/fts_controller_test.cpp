#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "nckit/drive/servo_model.hpp"
#include "nckit/process/fts/fts_controller.hpp"
#include "nckit/process/fts/fts_spindle.hpp"

namespace nckit {
namespace {

constexpr double pi = std::numbers::pi;
constexpr double tick_s = 60.0 / (2500.0 * 360.0);  // one encoder count at 2500 rpm: 15 kHz

drive::ServoParameters axis(double scale = 1.0) {
    return drive::ServoParameters::from_natural_frequency(scale, 135.0 * scale, 0.3 * scale);
}

TEST(FtsDac, SixteenBitsOverOneMillimetre) {
    const Dac dac{16, 1.0};
    EXPECT_EQ(dac.step_mm(), 1.0 / 65536.0);
    EXPECT_NEAR(dac.step_mm() * 1e6, 15.2587890625, 1e-12);  // nm
    EXPECT_EQ(dac.convert(0.0).code, 32768);
    EXPECT_EQ(dac.convert(0.0).command_mm, 0.0);
    EXPECT_EQ(dac.convert(0.4 * dac.step_mm()).code, 32768);
    EXPECT_EQ(dac.convert(0.6 * dac.step_mm()).code, 32769);
    EXPECT_EQ(dac.convert(-0.6 * dac.step_mm()).code, 32767);
    EXPECT_EQ(dac.convert(0.2).command_mm, std::round(0.2 * 65536) / 65536);
    EXPECT_FALSE(dac.convert(-0.5).clamped);
    EXPECT_EQ(dac.convert(-0.5).code, 0);
    EXPECT_TRUE(dac.convert(0.5).clamped);  // the top code is one step short of +stroke/2
    EXPECT_EQ(dac.convert(0.5).code, 65535);
    EXPECT_TRUE(dac.convert(-0.51).clamped);
    EXPECT_EQ(dac.convert(1e300).code, 65535);
    EXPECT_THROW((void)dac.convert(NAN), std::invalid_argument);
}

TEST(FtsDac, CommandsAreWithinHalfAStepOfTheWantedValue) {
    std::mt19937_64 random(5);
    for (int bits : {8, 12, 16, 20}) {
        const Dac dac{bits, 0.8};
        std::uniform_real_distribution<double> wanted(-0.4, 0.4 - dac.step_mm());
        for (int i = 0; i < 20000; ++i) {
            const double w = wanted(random);
            const Dac::Output out = dac.convert(w);
            ASSERT_FALSE(out.clamped);
            ASSERT_LE(std::abs(out.command_mm - w), 0.5 * dac.step_mm() * (1 + 1e-12)) << bits;
            ASSERT_EQ(out.command_mm, static_cast<double>(out.code - (1 << (bits - 1))) * dac.step_mm());
        }
    }
}

// The discrete frequency response is what a held sine actually produces at the ticks.
TEST(FtsController, DiscreteResponseMatchesTheSimulatedSteadyState) {
    for (double w : {0.01, 0.0349, 0.2, 1.0}) {
        const drive::ServoParameters p = axis();
        drive::ServoModel model(p, tick_s);
        const std::complex<double> g = discrete_response(drive::discretise(p, tick_s), w);
        const int settle = 20000;
        std::complex<double> sum = 0.0;
        const int cycles = 50;
        const int count = static_cast<int>(std::round(cycles * 2 * pi / w));
        for (int n = 0; n < settle + count; ++n) {
            // y[n] before the step at n: the command held over tick n-1 and earlier.
            if (n >= settle) sum += model.state().position * std::polar(1.0, -w * n);
            model.step(std::cos(w * n));
        }
        // A whole number of samples over a not-quite-whole number of cycles: leakage ~ 1 / count.
        const std::complex<double> measured = 2.0 * sum / static_cast<double>(count);
        EXPECT_NEAR(std::abs(measured - g), 0.0, 5.0 / count) << w;
    }
}

TEST(FtsZpetc, TapsSumToTheInverseDcGain) {
    for (double k : {0.9, 1.0, 1.1}) {
        const ZpetcFeedforward ff(drive::ServoParameters::from_natural_frequency(k, 135, 0.3), tick_s);
        const auto& t = ff.taps();
        EXPECT_NEAR(t[0] + t[1] + t[2] + t[3], 1.0 / k, 1e-9);
        // The sampling zero sits just inside -1 at 15 kHz: the reason for ZPETC.
        EXPECT_GT(ff.zero_ratio(), 0.95);
        EXPECT_LT(ff.zero_ratio(), 1.0);
        const double flat[4] = {0.3, 0.3, 0.3, 0.3};
        EXPECT_NEAR(ff.command(flat), 0.3 / k, 1e-13);
    }
}

// Driving the model with its own ZPETC leaves no phase error and a gain error of at most
// beta W^2 / (1 + beta)^2 at W rad per tick, for any sine (random frequencies and phases).
TEST(FtsZpetc, TracksSinesOfItsOwnModelWithZeroPhase) {
    std::mt19937_64 random(21);
    std::uniform_real_distribution<double> frequency(0.005, 0.3);
    std::uniform_real_distribution<double> phase(0.0, 2 * pi);
    const drive::ServoParameters p = axis();
    const ZpetcFeedforward ff(p, tick_s);
    const double beta = ff.zero_ratio();
    for (int trial = 0; trial < 40; ++trial) {
        const double w = frequency(random);
        const double phi = phase(random);
        auto wanted = [&](int n) { return 0.2 * std::sin(w * n + phi); };
        drive::ServoModel model(p, tick_s);
        std::complex<double> error_sum = 0.0, target_sum = 0.0;
        const int settle = 20000;
        const int count = 40000;
        for (int n = 0; n < settle + count; ++n) {
            if (n >= settle) {
                error_sum += (model.state().position - wanted(n)) * std::polar(1.0, -w * n);
                target_sum += wanted(n) * std::polar(1.0, -w * n);
            }
            const double window[4] = {wanted(n - 1), wanted(n), wanted(n + 1), wanted(n + 2)};
            model.step(ff.command(window));
        }
        const std::complex<double> ratio = error_sum / target_sum;  // y / y_d - 1
        const double predicted = beta * (2 - 2 * std::cos(w)) / ((1 + beta) * (1 + beta));
        EXPECT_NEAR(ratio.real(), -predicted, 1e-3 * predicted + 1e-7) << w;
        EXPECT_NEAR(ratio.imag(), 0.0, 1e-6) << w;  // zero phase
    }
}

TEST(FtsLearning, LowPassIsExactAtEveryHarmonicOfTheTurn) {
    for (int counts : {360, 361, 100}) {
        const ZpetcFeedforward ff(axis(), tick_s);
        const RepetitiveLearning learning(ff, counts, {0.6, 12}, 0);
        const auto& q = learning.low_pass();
        const int half = static_cast<int>(q.size() / 2);
        double sum = 0.0;
        for (double tap : q) sum += tap;
        EXPECT_NEAR(sum, 1.0, 1e-12);
        for (int m = 0; m <= counts / 2; ++m) {
            double response = 0.0;
            for (int i = -half; i <= half; ++i)
                response += q[static_cast<std::size_t>(i + half)] * std::cos(2 * pi * m * i / counts);
            EXPECT_NEAR(response, m <= 12 ? 1.0 : 0.0, 1e-12) << counts << " m " << m;
        }
        for (int i = 1; i <= half; ++i)
            EXPECT_EQ(q[static_cast<std::size_t>(half + i)], q[static_cast<std::size_t>(half - i)]);
    }
}

TEST(FtsLearning, ContractsForTenPercentModelErrorsEitherWay) {
    const drive::ServoDiscretisation plant = drive::discretise(axis(), tick_s);
    for (double e : {-0.1, -0.05, 0.0, 0.05, 0.1}) {
        const ZpetcFeedforward ff(axis(1.0 + e), tick_s);
        const RepetitiveLearning learning(ff, 360, {}, 0);
        const RepetitiveLearning::Contraction c = learning.contraction(plant);
        EXPECT_LT(c.any_frequency, 0.7) << e;
        EXPECT_LE(c.learned_harmonics, c.any_frequency) << e;
        if (e == 0.0) {
            // An exact model leaves only ZPETC's gain error, largest at the top harmonic (24).
            const double w = 2 * pi * 24 / 360;
            const double beta = ff.zero_ratio();
            const double gain = 1 - beta * (2 - 2 * std::cos(w)) / ((1 + beta) * (1 + beta));
            EXPECT_NEAR(c.learned_harmonics, 1 - FtsLearning{}.gain * gain, 1e-9);
        }
    }
    // A model that badly underrates the axis turns the learning unstable, and the number says so.
    const RepetitiveLearning wild(ZpetcFeedforward(axis(0.4), tick_s), 360, {1.5, 24}, 0);
    EXPECT_GT(wild.contraction(plant).any_frequency, 1.0);
}

// The learning loop alone on a periodic demand: the error per turn falls by about the predicted
// factor each turn, to rounding, for model errors either way.
TEST(FtsLearning, ConvergesTurnByTurnOnARepeatingDemand) {
    const int counts = 360;
    for (double e : {-0.1, 0.1}) {
        const drive::ServoParameters plant = axis();
        const ZpetcFeedforward ff(axis(1.0 + e), tick_s);
        RepetitiveLearning learning(ff, counts, {}, counts);
        const double factor = learning.contraction(drive::discretise(plant, tick_s)).any_frequency;
        drive::ServoModel servo(plant, tick_s);
        auto wanted = [&](int n) {
            const double a = 2 * pi * n / counts;
            return 0.2 * std::cos(2 * a) + 0.01 * std::cos(4 * a) + 0.003 * std::sin(a);
        };
        std::vector<double> turn_peak;
        for (int turn = 0; turn < 40; ++turn) {
            double peak = 0.0;
            for (int c = 0; c < counts; ++c) {
                const int n = turn * counts + c;
                const double error = servo.state().position - wanted(n);
                peak = std::max(peak, std::abs(error));
                const double window[4] = {wanted(n - 1), wanted(n), wanted(n + 1), wanted(n + 2)};
                servo.step(ff.command(window) + learning.next(error));
            }
            turn_peak.push_back(peak);
        }
        // Turns 3 .. 25: each below the one before by at least the predicted factor (plus slack
        // for the transients a change of correction starts); then at rounding level.
        for (int turn = 3; turn < 25; ++turn) {
            EXPECT_LT(turn_peak[turn], turn_peak[turn - 1] * std::min(0.95, factor + 0.15)) << e << " turn " << turn;
        }
        EXPECT_GT(turn_peak[1], 1e-3) << e;    // 1 µm and more before learning
        EXPECT_LT(turn_peak[39], 1e-10) << e;  // 0.1 pm after
    }
}

TEST(FtsSpindle, PeriodsRepeatEveryTurnAndAverageToTheNominalSpeed) {
    const SpindleClock steady(2500, 360, {0.0, 1, 0.0, 0.0, 0.0});
    EXPECT_DOUBLE_EQ(steady.nominal_period_s(), tick_s);
    EXPECT_EQ(steady.tick_period_s(17, 3.0), tick_s);
    EXPECT_DOUBLE_EQ(steady.angle_deg(90), 90.0);
    for (double a : {0.002, 0.01, 0.05}) {
        const SpindleClock clock(2500, 360, {a, 1, 30.0, 0.0, 0.0});
        double turn_s = 0.0;
        double shortest = 1.0, longest = 0.0;
        for (int c = 0; c < 360; ++c) {
            const double h = clock.tick_period_s(c, turn_s);
            EXPECT_EQ(h, clock.tick_period_s(c, turn_s + 1.234));  // the angle alone sets it
            turn_s += h;
            shortest = std::min(shortest, h);
            longest = std::max(longest, h);
        }
        // The mean of 1 / (1 + a sin) over a cycle is 1 / sqrt(1 - a^2).
        EXPECT_NEAR(turn_s, 0.024 / std::sqrt(1 - a * a), 1e-12) << a;
        EXPECT_NEAR(longest / shortest, (1 + a) / (1 - a), 1e-3 * a) << a;
    }
    const SpindleClock slow(2500, 360, {0.0, 1, 0.0, 0.01, 1.0});
    EXPECT_NEAR(slow.tick_period_s(0, 0.25), tick_s / 1.01, 1e-15);
    EXPECT_THROW(SpindleClock(0.0, 360, {}), std::invalid_argument);
    EXPECT_THROW(SpindleClock(2500, 360, {0.6, 1, 0.0, 0.5, 1.0}), std::invalid_argument);
}

}  // namespace
}  // namespace nckit
