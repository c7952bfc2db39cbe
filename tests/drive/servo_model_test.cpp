#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <stdexcept>

#include <Eigen/Dense>
#include <unsupported/Eigen/MatrixFunctions>
#include <gtest/gtest.h>

#include "nckit/drive/servo_model.hpp"

namespace nckit::drive {
namespace {

constexpr double pi = std::numbers::pi;

//! Unit-step response of k / (T^2 s^2 + 2 zeta T s + 1) from rest, textbook forms.
double analytic_step(const ServoParameters& p, double t) {
    const double w = 1.0 / p.time_constant_s;
    const double z = p.damping;
    if (z < 1.0) {
        const double wd = w * std::sqrt(1.0 - z * z);
        return p.gain *
               (1.0 - std::exp(-z * w * t) * (std::cos(wd * t) + z / std::sqrt(1.0 - z * z) * std::sin(wd * t)));
    }
    if (z == 1.0) return p.gain * (1.0 - std::exp(-w * t) * (1.0 + w * t));
    const double wd = w * std::sqrt(z * z - 1.0);
    if (wd * t < 1.0) {  // the root form cancels when the roots nearly meet
        return p.gain * (1.0 - std::exp(-z * w * t) * (std::cosh(wd * t) + z * w / wd * std::sinh(wd * t)));
    }
    const double r1 = -w * (z - std::sqrt(z * z - 1.0));
    const double r2 = -w * (z + std::sqrt(z * z - 1.0));
    return p.gain * (1.0 - (r2 * std::exp(r1 * t) - r1 * std::exp(r2 * t)) / (r2 - r1));
}

//! Its derivative (velocity), the impulse response scaled by k.
double analytic_step_velocity(const ServoParameters& p, double t) {
    const double w = 1.0 / p.time_constant_s;
    const double z = p.damping;
    if (z < 1.0) {
        const double wd = w * std::sqrt(1.0 - z * z);
        return p.gain * w * w / wd * std::exp(-z * w * t) * std::sin(wd * t);
    }
    if (z == 1.0) return p.gain * w * w * t * std::exp(-w * t);
    const double wd = w * std::sqrt(z * z - 1.0);
    if (wd * t < 1.0) return p.gain * w * w * std::exp(-z * w * t) * std::sinh(wd * t) / wd;
    const double r1 = -w * (z - std::sqrt(z * z - 1.0));
    const double r2 = -w * (z + std::sqrt(z * z - 1.0));
    return p.gain * r1 * r2 * (std::exp(r2 * t) - std::exp(r1 * t)) / (r2 - r1);
}

// The piston axis of docs/processes/piston.md: 135 Hz, 15 kHz updates.
constexpr double axis_hz = 135.0;
constexpr double period_s = 1.0 / 15000.0;

class ServoStep : public testing::TestWithParam<double> {};

TEST_P(ServoStep, MatchesTheAnalyticStepResponseAtTheSamples) {
    const ServoParameters p = ServoParameters::from_natural_frequency(0.8, axis_hz, GetParam());
    ServoModel model(p, period_s);
    for (int n = 1; n <= 3000; ++n) {
        const ServoState x = model.step(1.0);
        const double t = n * period_s;
        ASSERT_NEAR(x.position, analytic_step(p, t), 1e-12) << "n " << n;
        // Velocity is w times larger in scale (w = 848 /s); same relative accuracy.
        ASSERT_NEAR(x.velocity, analytic_step_velocity(p, t), 1e-12 * 848.0) << "n " << n;
    }
    EXPECT_EQ(model.following_error(), 1.0 - model.state().position);
}

// zeta < 1, just below and at 1 (critical branch), above 1 (overdamped), and strongly so.
INSTANTIATE_TEST_SUITE_P(Damping, ServoStep,
                         testing::Values(0.0 + 0.05, 0.3, 0.7, 1.0 - 1e-9, 1.0, 1.0 + 1e-9, 1.5, 4.0));

TEST(ServoModel, TransitionEqualsTheMatrixExponential) {
    for (double zeta : {0.0, 0.2, 1.0, 2.5, 30.0}) {
        for (double h : {1e-5, period_s, 1e-3, 0.02}) {
            const ServoParameters p = ServoParameters::from_natural_frequency(1.3, axis_hz, zeta);
            const ServoModel model(p, h);
            const double w = 1.0 / p.time_constant_s;
            // Augmented [[A, B], [0, 0]]: exp gives Phi and Gamma together.
            Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
            m << 0, 1, 0, -w * w, -2 * zeta * w, p.gain * w * w, 0, 0, 0;
            const Eigen::Matrix3d e = (m * h).exp();
            const auto& phi = model.transition();
            const auto& gamma = model.input_gain();
            const double scale = w;  // velocity rows are w times larger
            // An independent method, but Eigen's Pade scaling-and-squaring itself loses digits
            // (to ~1e-10 at w h = 17); TransitionAgainstHighPrecision holds the closed form to 1e-15.
            const double tol = 1e-9;
            EXPECT_NEAR(phi[0][0], e(0, 0), tol) << zeta << " " << h;
            EXPECT_NEAR(phi[0][1] * scale, e(0, 1) * scale, tol) << zeta << " " << h;
            EXPECT_NEAR(phi[1][0] / scale, e(1, 0) / scale, tol) << zeta << " " << h;
            EXPECT_NEAR(phi[1][1], e(1, 1), tol) << zeta << " " << h;
            EXPECT_NEAR(gamma[0], e(0, 2), tol) << zeta << " " << h;
            EXPECT_NEAR(gamma[1] / scale, e(1, 2) / scale, tol) << zeta << " " << h;
        }
    }
}

// exp(A h) of the augmented model to 40 digits (mpmath.expm): the exactness reference.
// Entries scaled to O(1): Phi00, Phi01 w, Phi10 / w, Phi11, Gamma0, Gamma1 / w; gain 1.3, 135 Hz.
struct HighPrecisionCase {
    double zeta;
    double h;
    std::array<double, 6> expected;
};

TEST(ServoModel, TransitionAgainstHighPrecision) {
    const HighPrecisionCase cases[] = {
        {0.0,
         0.001,
         {0.66131186532365187657, 0.75011106963045954151, -0.75011106963045954151, 0.66131186532365187657,
          0.4402945750792525755, 0.97514439051959743728}},
        {0.2,
         1.0 / 15000.0,
         {0.99841353365298531951, 0.05588411756591453176, -0.05588411756591453176, 0.97605988662661950556,
          0.0020624062511190847116, 0.07264935283568889377}},
        {1.0,
         0.001,
         {0.79136056300555590125, 0.36318844375963698384, -0.36318844375963698384, 0.064983675486281933571,
          0.27123126809277733764, 0.47214497688752809512}},
        {2.5,
         0.001,
         {0.87512240197388289336, 0.17906338124130814415, -0.17906338124130814415, -0.0201945042326578274,
          0.16234087743395224418, 0.23278239561370059535}},
        {2.5,
         0.02,
         {0.030312950961581196648, 0.0063266812444878662133, -0.0063266812444878662133, -0.0013204552608581344186,
          1.2605931637499444874, 0.0082246856178342263583}},
        {30,
         0.02,
         {0.75386350782435862201, 0.01256788384620205603, -0.01256788384620205603, -0.00020952294776473977356,
          0.31997743982833380232, 0.016338249000062673397}},
        {1000,
         0.001,
         {0.99957622470401959641, 0.00049978823729910035976, -0.00049978823729910035976, -2.4989418112311107905e-7,
          0.00055090788477452468006, 0.00064972470848883048989}},
    };
    for (const HighPrecisionCase& c : cases) {
        const ServoParameters p = ServoParameters::from_natural_frequency(1.3, axis_hz, c.zeta);
        const ServoModel model(p, c.h);
        const double w = p.natural_frequency_rad_s();
        const auto& phi = model.transition();
        const auto& gamma = model.input_gain();
        const std::array<double, 6> got{phi[0][0], phi[0][1] * w, phi[1][0] / w, phi[1][1], gamma[0], gamma[1] / w};
        for (std::size_t i = 0; i < got.size(); ++i) {
            EXPECT_NEAR(got[i], c.expected[i], 2e-15 + 1e-13 * std::abs(c.expected[i]))
                << "zeta " << c.zeta << " h " << c.h << " entry " << i;
        }
    }
}

TEST(ServoModel, DampingBranchesMeetContinuously) {
    const double h = period_s;
    const ServoModel critical(ServoParameters::from_natural_frequency(1, axis_hz, 1.0), h);
    for (double dz : {1e-12, 1e-8, 1e-5}) {
        for (double zeta : {1.0 - dz, 1.0 + dz}) {
            const ServoModel near(ServoParameters::from_natural_frequency(1, axis_hz, zeta), h);
            for (int i = 0; i < 2; ++i) {
                for (int j = 0; j < 2; ++j) {
                    // d Phi / d zeta is bounded (about w h), so the gap is O(dz).
                    EXPECT_NEAR(near.transition()[i][j], critical.transition()[i][j],
                                10 * dz *
                                        (i == j   ? 1.0
                                         : i == 0 ? 1e-3
                                                  : 1e3) +
                                    1e-15);
                }
            }
        }
    }
}

TEST(ServoModel, NaturalFrequencyConstructor) {
    const ServoParameters p = ServoParameters::from_natural_frequency(2.0, 135.0, 0.4);
    EXPECT_DOUBLE_EQ(p.time_constant_s, 1.0 / (2.0 * pi * 135.0));
    EXPECT_DOUBLE_EQ(p.natural_frequency_rad_s(), 2.0 * pi * 135.0);
    EXPECT_EQ(p.gain, 2.0);
    EXPECT_EQ(p.damping, 0.4);
    EXPECT_THROW((void)ServoParameters::from_natural_frequency(1, 0.0, 0.5), std::invalid_argument);
}

TEST(ServoModel, RejectsImpossibleParameters) {
    EXPECT_THROW(ServoModel({1, 0.0, 0.5}, 1e-3), std::invalid_argument);
    EXPECT_THROW(ServoModel({1, 1e-3, -0.1}, 1e-3), std::invalid_argument);
    EXPECT_THROW(ServoModel({1, 1e-3, 0.5}, 0.0), std::invalid_argument);
    EXPECT_THROW(ServoModel({NAN, 1e-3, 0.5}, 1e-3), std::invalid_argument);
}

TEST(ServoModel, DcGainAndFollowingError) {
    for (double k : {1.0, 0.95, 2.0}) {
        ServoModel model(ServoParameters::from_natural_frequency(k, 50.0, 0.7), 1e-3);
        for (int n = 0; n < 2000; ++n) model.step(3.0);
        EXPECT_NEAR(model.state().position, 3.0 * k, 1e-12);
        EXPECT_NEAR(model.state().velocity, 0.0, 1e-10);
        EXPECT_NEAR(model.following_error(), 3.0 - 3.0 * k, 1e-12);
    }
    // A period far shorter than the time constant (w h ~ 1e-3) still settles exactly at k u.
    ServoModel fine(ServoParameters::from_natural_frequency(1.7, 200.0, 1.0), 1e-6);
    for (int n = 0; n < 100'000; ++n) fine.step(-0.3);
    EXPECT_NEAR(fine.state().position, -0.3 * 1.7, 1e-15);
    ServoModel fresh(ServoParameters::from_natural_frequency(1, 50.0, 0.7), 1e-3);
    EXPECT_EQ(fresh.following_error(), 0.0);
    fresh.reset({0.5, 0.0}, 2.0);
    EXPECT_EQ(fresh.following_error(), 1.5);
}

// The piston demand: 0.2 mm at twice the spindle frequency. With the setpoint held over
// each period, the sampled steady state is G(jw) times the hold's sinc(w h / 2) e^{-j w h / 2};
// the hold's harmonics near 2 pi / h reach the output only at |G| ~ 1e-6 of their tiny size.
TEST(ServoModel, SineSteadyStateMatchesTheFrequencyResponse) {
    const double h = 1e-5;
    for (double zeta : {0.1, 0.7, 1.0, 2.0}) {
        for (double f_in : {20.0, 100.0, 125.0, 400.0}) {  // whole number of samples per cycle
            const ServoParameters p = ServoParameters::from_natural_frequency(1.0, axis_hz, zeta);
            ServoModel model(p, h);
            const double w_in = 2 * pi * f_in;
            const int per_cycle = static_cast<int>(std::lround(1.0 / (f_in * h)));
            // Settle: 0.3 s is over 70 time constants of the slowest mode here (zeta 2).
            int n = 0;
            for (; n < 30000; ++n) model.step(0.2 * std::sin(w_in * n * h));
            double in_phase = 0, quadrature = 0;
            const int cycles = 4;
            for (int i = 0; i < cycles * per_cycle; ++i, ++n) {
                const double y = model.step(0.2 * std::sin(w_in * n * h)).position;
                // y is the output at (n + 1) h.
                in_phase += y * std::sin(w_in * (n + 1) * h);
                quadrature += y * std::cos(w_in * (n + 1) * h);
            }
            const double scale = 2.0 / (cycles * per_cycle);
            const std::complex<double> measured(in_phase * scale, quadrature * scale);
            const double x = w_in * h / 2;
            const std::complex<double> expected =
                0.2 * frequency_response(p, w_in) * (std::sin(x) / x) * std::polar(1.0, -x);
            EXPECT_NEAR(std::abs(measured), std::abs(expected), 1e-8) << zeta << " " << f_in;
            EXPECT_NEAR(std::arg(measured), std::arg(expected), 1e-7) << zeta << " " << f_in;
        }
    }
    // Against G alone the hold costs w h / 2 of phase: about 1 deg at 83 Hz and 15 kHz.
    const ServoParameters p = ServoParameters::from_natural_frequency(1.0, axis_hz, 0.7);
    const double lag_deg = std::arg(frequency_response(p, 2 * pi * 83.3)) * 180 / pi;
    EXPECT_LT(lag_deg, -40.0);  // tens of degrees uncompensated (docs/processes/piston.md)
    EXPECT_GT(lag_deg, -60.0);
}

// ½ v^2 + ½ w^2 e^2 with e = y - k u is a Lyapunov function: d/dt = -2 zeta w v^2 <= 0, and
// the exact discretisation samples the continuous trajectory, so it holds at every tick.
TEST(ServoModel, EnergyNeverGrowsOverLongRuns) {
    for (double zeta : {0.0, 0.01, 0.7, 1.0, 3.0}) {
        const ServoParameters p = ServoParameters::from_natural_frequency(1.0, axis_hz, zeta);
        const double w = p.natural_frequency_rad_s();
        ServoModel model(p, period_s, {0.1, 50.0});
        auto energy = [&](const ServoState& x) {
            return 0.5 * x.velocity * x.velocity + 0.5 * w * w * x.position * x.position;
        };
        const double start = energy(model.state());
        double previous = start;
        for (int n = 0; n < 1'000'000; ++n) {
            const double now = energy(model.step(0.0));
            ASSERT_LE(now, previous * (1 + 1e-13) + 1e-300) << "zeta " << zeta << " n " << n;
            previous = now;
        }
        if (zeta == 0.0) {
            EXPECT_NEAR(previous / start, 1.0, 1e-9);  // undamped: conserved, no numerical decay
        } else {
            EXPECT_LT(previous, start * 1e-6) << zeta;
        }
    }
}

TEST(ServoModel, BoundedSetpointsGiveBoundedMotion) {
    std::mt19937_64 random(42);
    std::uniform_real_distribution<double> setpoint(-1.0, 1.0);
    for (double zeta : {0.05, 0.7, 1.0, 5.0}) {
        ServoModel model(ServoParameters::from_natural_frequency(1.0, axis_hz, zeta), period_s);
        // Peak gain of a 2nd-order section is below 1 / (2 zeta sqrt(1 - zeta^2)) + 1; the
        // impulse-response L1 norm bounds it for any input: here a generous 1 / zeta + 2.
        const double bound = 1.0 / zeta + 2.0;
        for (int n = 0; n < 200'000; ++n) {
            const ServoState x = model.step(setpoint(random));
            ASSERT_LE(std::abs(x.position), bound) << zeta << " " << n;
            ASSERT_TRUE(std::isfinite(x.velocity));
        }
    }
}

TEST(ServoModel, LongPeriodsStayExact) {
    // A period many time constants long lands on the settled value, as the continuous system does.
    ServoModel slow(ServoParameters::from_natural_frequency(1.5, 10.0, 50.0), 100.0);
    const ServoState x = slow.step(2.0);
    EXPECT_NEAR(x.position, analytic_step({1.5, 1.0 / (2 * pi * 10.0), 50.0}, 100.0) * 2.0, 1e-12);
    EXPECT_TRUE(std::isfinite(x.velocity));
}

}  // namespace
}  // namespace nckit::drive
