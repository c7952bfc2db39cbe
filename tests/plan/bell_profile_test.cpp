// Bells (src/plan/bell_profile.hpp): speed changes with a jerk of their own at each end. A bell
// must cover exactly its distance, keep both end speeds with a = 0 there, keep each side's
// acceleration and jerks, and with one jerk everywhere be the time-optimal S-curve.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "../../src/plan/bell_profile.hpp"

namespace nckit::plan_detail {
namespace {

//! The state after every phase, integrated from the start.
struct Walked {
    double distance_mm = 0;
    double end_velocity = 0;
    double end_acceleration = 0;
    double lowest_velocity = 0;
    double highest_velocity = 0;
};

Walked walk(const Profile& p) {
    Walked w;
    double v = p.start_velocity;
    double a = 0;
    w.lowest_velocity = w.highest_velocity = v;
    for (int i = 0; i < p.phase_count; ++i) {
        const ProfilePhase& ph = p.phases[static_cast<std::size_t>(i)];
        EXPECT_NEAR(ph.acceleration, a, 1e-9 * std::max(1.0, std::abs(a)));  // continuous acceleration
        const double t = ph.duration_s;
        // The speed's extreme inside a phase lies where the acceleration passes through 0.
        if (ph.jerk != 0 && -a / ph.jerk > 0 && -a / ph.jerk < t) {
            const double x = -a / ph.jerk;
            const double v_x = v + x * (a + 0.5 * x * ph.jerk);
            w.lowest_velocity = std::min(w.lowest_velocity, v_x);
            w.highest_velocity = std::max(w.highest_velocity, v_x);
        }
        w.distance_mm += t * (v + t * (0.5 * a + t * ph.jerk / 6.0));
        v += t * (a + 0.5 * t * ph.jerk);
        a += t * ph.jerk;
        w.lowest_velocity = std::min(w.lowest_velocity, v);
        w.highest_velocity = std::max(w.highest_velocity, v);
    }
    w.end_velocity = v;
    w.end_acceleration = a;
    return w;
}

TEST(BellProfile, CoversItsDistanceAndKeepsEndSpeedsAndRates) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> speed(0.0, 60.0);
    std::uniform_real_distribution<double> accel(50.0, 600.0);
    std::uniform_real_distribution<double> jerk(500.0, 60000.0);
    std::uniform_real_distribution<double> length(0.01, 40.0);
    int planned = 0;
    for (int n = 0; n < 2000; ++n) {
        const BellRates r{{accel(rng), jerk(rng), jerk(rng)}, {accel(rng), jerk(rng), jerk(rng)}};
        const double v_start = speed(rng);
        const double v_end = speed(rng);
        const double v_top = std::max(v_start, v_end) + speed(rng);
        const double distance = length(rng);
        Profile p;
        if (!bell_profile(distance, v_start, v_end, v_top, r, p)) continue;
        ++planned;
        const Walked w = walk(p);
        EXPECT_NEAR(w.distance_mm, distance, 1e-9 * std::max(1.0, distance));
        EXPECT_NEAR(w.end_velocity, v_end, 1e-7);
        EXPECT_NEAR(w.end_acceleration, 0.0, 1e-7);
        EXPECT_GE(w.lowest_velocity, std::min(v_start, v_end) - 1e-9);
        EXPECT_LE(w.highest_velocity, v_top * (1 + 1e-12) + 1e-9);
        // Each phase runs at one of its side's jerks (or none), and the acceleration stays
        // within the side's: speeding up before the top, braking after it.
        double a = 0;
        for (int i = 0; i < p.phase_count; ++i) {
            const ProfilePhase& ph = p.phases[static_cast<std::size_t>(i)];
            const double j = std::abs(ph.jerk);
            const bool rise_jerk = j == r.rise.end_jerk || j == r.rise.top_jerk;
            const bool fall_jerk = j == r.fall.end_jerk || j == r.fall.top_jerk;
            EXPECT_TRUE(j == 0 || rise_jerk || fall_jerk) << "jerk " << ph.jerk;
            a += ph.duration_s * ph.jerk;
            EXPECT_LE(a, r.rise.max_acceleration * (1 + 1e-9));
            EXPECT_GE(a, -r.fall.max_acceleration * (1 + 1e-9));
        }
    }
    EXPECT_GT(planned, 1000);
}

TEST(BellProfile, WithOneJerkEverywhereIsTheTimeOptimalSCurve) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> speed(0.0, 80.0);
    std::uniform_real_distribution<double> length(0.5, 60.0);
    int compared = 0;
    for (int n = 0; n < 500; ++n) {
        const ProfileLimits limits{100.0, 500.0, 5000.0};
        const double v_start = speed(rng);
        const double v_end = speed(rng);
        const double distance = length(rng);
        const Profile s_curve = plan_profile(distance, v_start, v_end, limits, ProfileKind::scurve);
        if (s_curve.start_velocity != v_start || s_curve.end_velocity != v_end) continue;  // not reachable
        const BellSide side{limits.max_acceleration, limits.max_jerk, limits.max_jerk};
        Profile bell;
        ASSERT_TRUE(bell_profile(distance, v_start, v_end, limits.max_velocity, {side, side}, bell));
        EXPECT_NEAR(bell.duration_s(), s_curve.duration_s(), 1e-7 * s_curve.duration_s());
        ++compared;
    }
    EXPECT_GT(compared, 200);
}

TEST(BellProfile, RefusesADistanceTooShortForItsSpeedChange) {
    const BellSide side{500.0, 5000.0, 1000.0};
    Profile p;
    // 0 to 40 mm/s with these rates takes more than 0.5 mm.
    EXPECT_FALSE(bell_profile(0.5, 0.0, 40.0, 50.0, {side, side}, p));
    // Nothing to cover and no speed to cover it with: no bell, not a zero-time one.
    EXPECT_FALSE(bell_profile(5.0, 0.0, 0.0, 0.0, {side, side}, p));
    EXPECT_TRUE(bell_profile(5.0, 0.0, 0.0, 30.0, {side, side}, p));
    EXPECT_GT(p.duration_s(), 5.0 / 30.0);
}

}  // namespace
}  // namespace nckit::plan_detail
