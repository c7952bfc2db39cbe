#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <set>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "nckit/drive/servo_model.hpp"
#include "nckit/drive/variable_period_servo.hpp"

namespace nckit::drive {
namespace {

// The fast tool servo's axis: 135 Hz, encoder-rate updates near 15 kHz.
constexpr double axis_hz = 135.0;
constexpr double period_s = 1.0 / 15000.0;

//! Unit-step response of k / (T^2 s^2 + 2 zeta T s + 1) from rest (zeta != 1), textbook forms.
double analytic_step(const ServoParameters& p, double t) {
    const double w = 1.0 / p.time_constant_s;
    const double z = p.damping;
    if (z < 1.0) {
        const double wd = w * std::sqrt(1.0 - z * z);
        return p.gain *
               (1.0 - std::exp(-z * w * t) * (std::cos(wd * t) + z / std::sqrt(1.0 - z * z) * std::sin(wd * t)));
    }
    const double r1 = -w * (z - std::sqrt(z * z - 1.0));
    const double r2 = -w * (z + std::sqrt(z * z - 1.0));
    return p.gain * (1.0 - (r2 * std::exp(r1 * t) - r1 * std::exp(r2 * t)) / (r2 - r1));
}

TEST(VariablePeriodServo, DiscretisationIsServoModelsOwn) {
    for (double zeta : {0.0, 0.3, 1.0, 2.5}) {
        for (double h : {1e-5, period_s, 1e-3}) {
            const ServoParameters p = ServoParameters::from_natural_frequency(0.9, axis_hz, zeta);
            const ServoModel model(p, h);
            const ServoDiscretisation d = discretise(p, h);
            EXPECT_EQ(d.period_s, h);
            EXPECT_EQ(d.transition, model.transition()) << zeta << " " << h;
            EXPECT_EQ(d.input_gain, model.input_gain()) << zeta << " " << h;
        }
    }
}

TEST(VariablePeriodServo, MatchesServoModelBitForBitAtAFixedPeriod) {
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> setpoint(-0.5, 0.5);
    for (double zeta : {0.05, 0.3, 1.0, 3.0}) {
        const ServoParameters p = ServoParameters::from_natural_frequency(1.1, axis_hz, zeta);
        ServoModel fixed(p, period_s, {0.01, -3.0});
        VariablePeriodServo variable(p, {0.01, -3.0});
        for (int n = 0; n < 20000; ++n) {
            const double u = setpoint(random);
            const ServoState a = fixed.step(u);
            const ServoState b = variable.step(u, period_s);
            ASSERT_EQ(a.position, b.position) << zeta << " " << n;
            ASSERT_EQ(a.velocity, b.velocity) << zeta << " " << n;
        }
        EXPECT_EQ(variable.cached_periods(), 1u);
    }
}

// Random periods summing to t land on the continuous step response at t: each step is exact.
TEST(VariablePeriodServo, RandomPeriodsSampleTheContinuousResponse) {
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> period(0.2 * period_s, 3.0 * period_s);
    for (double zeta : {0.1, 0.3, 0.9, 1.7}) {
        const ServoParameters p = ServoParameters::from_natural_frequency(1.0, axis_hz, zeta);
        for (int trial = 0; trial < 20; ++trial) {
            VariablePeriodServo servo(p);
            double t = 0.0;
            for (int n = 0; n < 2000; ++n) {
                const double h = period(random);
                const ServoState x = servo.step(1.0, h);
                t += h;
                ASSERT_NEAR(x.position, analytic_step(p, t), 1e-12) << zeta << " n " << n;
            }
        }
    }
}

// Holding a setpoint over h1 then h2 is holding it over h1 + h2 (the map is exp(A h)).
TEST(VariablePeriodServo, SplittingAHoldChangesNothing) {
    std::mt19937_64 random(3);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int trial = 0; trial < 2000; ++trial) {
        const ServoParameters p = ServoParameters::from_natural_frequency(
            0.5 + unit(random), 50.0 + 300.0 * unit(random), 1.5 * unit(random));
        const ServoState start{unit(random) - 0.5, 100.0 * (unit(random) - 0.5)};
        const double u = unit(random) - 0.5;
        const double h1 = 1e-4 * (0.1 + unit(random));
        const double h2 = 1e-4 * (0.1 + unit(random));
        VariablePeriodServo split(p, start);
        VariablePeriodServo whole(p, start);
        split.step(u, h1);
        const ServoState a = split.step(u, h2);
        const ServoState b = whole.step(u, h1 + h2);
        ASSERT_NEAR(a.position, b.position, 1e-14) << trial;
        ASSERT_NEAR(a.velocity, b.velocity, 1e-11) << trial;
    }
}

TEST(VariablePeriodServo, RepeatedPeriodsAreComputedOnce) {
    const ServoParameters p = ServoParameters::from_natural_frequency(1.0, axis_hz, 0.3);
    std::vector<double> periods;
    for (int k = 0; k < 360; ++k)
        periods.push_back(period_s / (1.0 + 0.002 * std::sin(2 * std::numbers::pi * k / 360)));
    VariablePeriodServo cached(p);
    for (int turn = 0; turn < 5; ++turn) {
        for (double h : periods) cached.step(0.1, h);
    }
    // sin is symmetric about 90 deg: counts k and 180 - k share a period.
    EXPECT_EQ(cached.cached_periods(), std::set<double>(periods.begin(), periods.end()).size());
    EXPECT_GT(cached.cached_periods(), 170u);
    // A fresh model per step (no cache) agrees bit for bit.
    VariablePeriodServo fresh(p);
    ServoState x;
    for (int turn = 0; turn < 5; ++turn) {
        for (double h : periods) {
            VariablePeriodServo one(p);
            one.reset(fresh.state(), 0.1);
            x = one.step(0.1, h);
            fresh.reset(x, 0.1);
        }
    }
    EXPECT_NEAR(x.position, cached.state().position, 1e-15);
    EXPECT_NEAR(x.velocity, cached.state().velocity, 1e-12);
}

TEST(VariablePeriodServo, RejectsImpossibleParametersAndPeriods) {
    EXPECT_THROW(VariablePeriodServo({1, 0.0, 0.5}), std::invalid_argument);
    EXPECT_THROW(VariablePeriodServo({1, 1e-3, -0.1}), std::invalid_argument);
    VariablePeriodServo servo(ServoParameters::from_natural_frequency(1, axis_hz, 0.3));
    EXPECT_THROW(servo.step(0.0, 0.0), std::invalid_argument);
    EXPECT_THROW(servo.step(0.0, -1e-4), std::invalid_argument);
    EXPECT_THROW(servo.step(0.0, NAN), std::invalid_argument);
    EXPECT_THROW((void)discretise({1, 1e-3, 0.5}, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace nckit::drive
