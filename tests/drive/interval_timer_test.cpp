#include <cmath>
#include <cstdint>
#include <random>

#include <gtest/gtest.h>

#include "nckit/drive/interval_timer.hpp"

namespace nckit::drive {
namespace {

// docs/processes/crosshatch.md: 8253 at 1 MHz, 1.5 deg/beat (240 beats/turn), 1:3 gearing.
constexpr double timer_clock_hz = 1'000'000.0;
constexpr double beats_per_turn = 240.0;
constexpr double gear = 3.0;

double step_rate_hz(double shaft_rpm) {
    return shaft_rpm / 60.0 * gear * beats_per_turn;
}

TEST(IntervalTimer, CrosshatchWorkedDivisors) {
    const IntervalTimer timer{timer_clock_hz};
    // Rotation 30/45/60 Hz step rates: exact divisors 33333.33, 22222.22, 16666.67.
    struct Case {
        double rate_hz;
        std::uint32_t divisor;
    };
    for (const Case c : {Case{30.0, 33333}, Case{45.0, 22222}, Case{60.0, 16667}}) {
        const TimerSetting s = timer.setting_for(c.rate_hz);
        ASSERT_TRUE(s.ok()) << s.message();
        EXPECT_EQ(s.divisor, c.divisor);
        EXPECT_DOUBLE_EQ(s.rate_hz, timer_clock_hz / c.divisor);
        // crosshatch.md's error: |divisor_real - round| / round.
        const double exact = timer_clock_hz / c.rate_hz;
        EXPECT_NEAR(std::abs(s.speed_error), std::abs(exact - c.divisor) / c.divisor, 1e-15);
    }
    // Feed screw at 60 rpm through the 1:3 gear: 720 steps/s, divisor 1388.89 -> 1389.
    const TimerSetting feed = timer.setting_for(step_rate_hz(60.0));
    ASSERT_TRUE(feed.ok());
    EXPECT_EQ(feed.divisor, 1389U);
    // Checked details: 83333.3 / V; 2778 at 30 rpm.
    EXPECT_EQ(timer.setting_for(step_rate_hz(30.0)).divisor, 2778U);
}

TEST(IntervalTimer, RangeAtOneMegahertz) {
    const IntervalTimer timer{timer_clock_hz};
    EXPECT_NEAR(timer.min_rate_hz(), 15.259, 1e-3);
    EXPECT_DOUBLE_EQ(timer.max_rate_hz(), 500'000.0);
    EXPECT_EQ(timer.setting_for(500'000.0).divisor, 2U);
    EXPECT_EQ(timer.setting_for(timer_clock_hz / 65535.0).divisor, 65535U);
    // Slowest shaft speed: 83333.3 / 65535 = 1.271566 rpm.
    EXPECT_TRUE(timer.setting_for(step_rate_hz(1.2716)).ok());
    EXPECT_EQ(timer.setting_for(step_rate_hz(1.2715)).status, TimerStatus::too_slow);
}

TEST(IntervalTimer, OutOfRangeIsAnErrorValueNamingTheRange) {
    const IntervalTimer timer{timer_clock_hz};
    const TimerSetting fast = timer.setting_for(500'001.0);
    EXPECT_EQ(fast.status, TimerStatus::too_fast);
    EXPECT_FALSE(fast.ok());
    EXPECT_EQ(fast.divisor, 0U);
    EXPECT_DOUBLE_EQ(fast.max_rate_hz, 500'000.0);
    EXPECT_NE(fast.message().find("faster"), std::string::npos) << fast.message();
    EXPECT_NE(fast.message().find("500000"), std::string::npos) << fast.message();
    EXPECT_NE(fast.message().find("15.25"), std::string::npos) << fast.message();

    const TimerSetting slow = timer.setting_for(15.0);
    EXPECT_EQ(slow.status, TimerStatus::too_slow);
    EXPECT_NE(slow.message().find("slower"), std::string::npos) << slow.message();
    EXPECT_NE(slow.message().find("500000"), std::string::npos) << slow.message();

    for (double bad : {0.0, -10.0, std::nan(""), static_cast<double>(INFINITY)}) {
        EXPECT_EQ(timer.setting_for(bad).status, TimerStatus::invalid_rate) << bad;
    }
}

TEST(IntervalTimer, ZeroMeans65536Convention) {
    const IntervalTimer timer{timer_clock_hz, 2, 65536};
    const TimerSetting s = timer.setting_for(timer_clock_hz / 65536.0);
    ASSERT_TRUE(s.ok());
    EXPECT_EQ(s.divisor, 65536U);
    EXPECT_EQ(IntervalTimer::load_value(s.divisor), 0U);
    EXPECT_EQ(IntervalTimer::load_value(1389), 1389U);
    EXPECT_EQ(IntervalTimer{timer_clock_hz}.setting_for(timer_clock_hz / 65536.0).status, TimerStatus::too_slow);
}

TEST(IntervalTimer, RoundsToTheNearestRateNotTheNearestDivisor) {
    const IntervalTimer timer{timer_clock_hz};
    // Exact divisor 2.49: round() gives 2 (rate 500 kHz) but 3 (333.3 kHz) is nearer to
    // 401.6 kHz; the rates meet at the harmonic mean 2.4 of the divisors.
    const double wanted = timer_clock_hz / 2.49;
    const TimerSetting s = timer.setting_for(wanted);
    EXPECT_EQ(s.divisor, 3U);
    EXPECT_LT(std::abs(timer_clock_hz / 3 - wanted), std::abs(timer_clock_hz / 2 - wanted));
    EXPECT_EQ(timer.setting_for(timer_clock_hz / 2.39).divisor, 2U);
}

// Invariants over many rates: in range, nearest of the neighbours, error consistent.
TEST(IntervalTimer, RandomRatesGiveTheNearestAchievableRate) {
    std::mt19937_64 random(20261123);
    for (double clock : {1'000'000.0, 1'193'182.0, 8'000'000.0}) {
        const IntervalTimer timer{clock};
        std::uniform_real_distribution<double> log_rate(std::log(timer.min_rate_hz()), std::log(timer.max_rate_hz()));
        for (int i = 0; i < 20000; ++i) {
            const double wanted = std::exp(log_rate(random));
            const TimerSetting s = timer.setting_for(wanted);
            ASSERT_TRUE(s.ok()) << s.message();
            ASSERT_GE(s.divisor, 2U);
            ASSERT_LE(s.divisor, 65535U);
            ASSERT_EQ(s.rate_hz, clock / s.divisor);
            ASSERT_NEAR(s.speed_error, s.rate_hz / wanted - 1.0, 1e-15);
            for (std::uint32_t other : {s.divisor - 1, s.divisor + 1}) {
                if (other < 2 || other > 65535) continue;
                ASSERT_LE(std::abs(s.rate_hz - wanted), std::abs(clock / other - wanted))
                    << "wanted " << wanted << " divisor " << s.divisor;
            }
            // Half a count of quantisation at most: |error| <= 1 / (2 n - 1).
            ASSERT_LE(std::abs(s.speed_error), 1.0 / (2.0 * s.divisor - 1.0) + 1e-15);
        }
    }
}

}  // namespace
}  // namespace nckit::drive
