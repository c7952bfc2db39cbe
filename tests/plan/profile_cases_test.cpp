// Every case of plan_profile by name: the regimes of each half, degenerate requests, clamping.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "nckit/plan/profile.hpp"
#include "profile_check.hpp"

namespace nckit {
namespace {

using plan_test::check_profile;
using plan_test::ref_change_distance;
using plan_test::ref_change_time;

constexpr ProfileKind scurve = ProfileKind::scurve;
constexpr ProfileKind trapezoid = ProfileKind::trapezoid;

//! Duration of a peak profile through vp with a cruise at vp covering what is left, or +inf
//! when the ramps alone are longer than d: the brute force compared against.
double peak_profile_s(double d, double v0, double v1, double vp, const ProfileLimits& l, ProfileKind kind) {
    const double a = l.max_acceleration;
    const double j = plan_test::jerk_of(l, kind);
    const double ramps = ref_change_distance(v0, vp, a, j) + ref_change_distance(v1, vp, a, j);
    const double left = d - ramps;
    if (left < -1e-12 * d || (vp == 0 && left > 0)) return plan_test::inf;
    return ref_change_time(vp - v0, a, j) + ref_change_time(vp - v1, a, j) + std::max(0.0, left) / vp;
}

//! The fastest peak profile on a fine grid of peak speeds, refined around the best.
double brute_force_s(double d, double v0, double v1, const ProfileLimits& l, ProfileKind kind) {
    double lo = std::max(v0, v1);
    double hi = l.max_velocity;
    double best = plan_test::inf;
    for (int round = 0; round < 4; ++round) {
        double best_v = lo;
        for (int i = 0; i <= 400; ++i) {
            const double vp = lo + (hi - lo) * i / 400.0;
            const double t = peak_profile_s(d, v0, v1, vp, l, kind);
            if (t < best) {
                best = t;
                best_v = vp;
            }
        }
        const double step = (hi - lo) / 400.0;
        lo = std::max(lo, best_v - step);
        hi = std::min(hi, best_v + step);
    }
    return best;
}

void expect_valid_and_fast(double d, double v0, double v1, const ProfileLimits& l, ProfileKind kind) {
    SCOPED_TRACE(testing::Message() << "d=" << d << " v0=" << v0 << " v1=" << v1);
    const Profile p = plan_profile(d, v0, v1, l, kind);
    EXPECT_EQ(p.end_velocity, v1);
    EXPECT_EQ(check_profile(p, l, kind), "");
    EXPECT_LE(p.duration_s(), brute_force_s(d, v0, v1, l, kind) * (1 + 1e-12));
    EXPECT_GE(p.duration_s(), brute_force_s(d, v0, v1, l, kind) * (1 - 1e-6));
}

// a^2/j = 10 mm/s with these limits: speed changes below it never reach the acceleration limit.
const ProfileLimits mill{200, 1000, 1e5};

TEST(ProfileCases, EqualBoundarySpeeds) {
    for (double v : {0.0, 3.0, 50.0, 199.0}) {
        for (double d : {1e-4, 0.01, 0.5, 5.0, 500.0}) expect_valid_and_fast(d, v, v, mill, scurve);
    }
}

TEST(ProfileCases, SpeedUpWithEveryHalfInEveryRegime) {
    // Lower half (from v0) and upper half (to v1) each below or at the acceleration limit.
    const double v0 = 20;
    for (double v1 : {21.0, 25.0, 35.0, 120.0}) {
        for (double extra : {0.0, 1e-9, 1e-3, 0.05, 0.4, 3.0, 40.0, 400.0}) {
            const double d = speed_change_distance(v0, v1, mill, scurve) + extra;
            expect_valid_and_fast(d, v0, v1, mill, scurve);
            expect_valid_and_fast(d, v1, v0, mill, scurve);  // and braking, mirrored
        }
    }
}

TEST(ProfileCases, FromAndToRest) {
    for (double v : {0.5, 9.0, 11.0, 150.0, 200.0}) {
        for (double extra : {0.0, 1e-6, 0.1, 10.0, 300.0}) {
            const double d = speed_change_distance(0, v, mill, scurve) + extra;
            expect_valid_and_fast(d, 0, v, mill, scurve);
            expect_valid_and_fast(d, v, 0, mill, scurve);
            expect_valid_and_fast(d, 0, v, mill, trapezoid);
            expect_valid_and_fast(d, v, 0, mill, trapezoid);
        }
    }
}

TEST(ProfileCases, ExactlyTheMonotoneDistanceHasNoPeak) {
    const double d = speed_change_distance(30, 80, mill, scurve);
    const Profile p = plan_profile(d, 30, 80, mill, scurve);
    EXPECT_NEAR(p.end_velocity, 80, 1e-12);
    EXPECT_EQ(p.phase_count, 3);
    EXPECT_NEAR(p.duration_s(), ref_change_time(50, 1000, 1e5), 1e-15);
}

TEST(ProfileCases, CruiseOnly) {
    const Profile p = plan_profile(7, 200, 200, mill, scurve);
    ASSERT_EQ(p.phase_count, 1);
    EXPECT_EQ(p.phases[0].duration_s, 7.0 / 200);
    EXPECT_EQ(p.at(0.01).position, 2.0);
    EXPECT_EQ(check_profile(p, mill, scurve), "");
}

TEST(ProfileCases, ZeroDistance) {
    for (ProfileKind kind : {scurve, trapezoid}) {
        Profile p = plan_profile(0, 0, 0, mill, kind);
        EXPECT_EQ(p.phase_count, 0);
        EXPECT_EQ(p.duration_s(), 0);
        // Over no distance the speed cannot change: v_end becomes v_start.
        p = plan_profile(0, 40, 10, mill, kind);
        EXPECT_EQ(p.end_velocity, 40);
        EXPECT_EQ(p.duration_s(), 0);
        EXPECT_EQ(p.at(1).position, 0);
        EXPECT_EQ(plan_profile(-3, 40, 60, mill, kind).end_velocity, 40);
        EXPECT_EQ(plan_profile(std::nan(""), 40, 60, mill, kind).distance, 0);
    }
}

TEST(ProfileCases, SpeedsOutsideTheLimitsAreClamped) {
    Profile p = plan_profile(100, 500, 0, mill, scurve);
    EXPECT_EQ(p.start_velocity, 200);
    EXPECT_EQ(check_profile(p, mill, scurve), "");
    p = plan_profile(100, -5, 1e9, mill, scurve);
    EXPECT_EQ(p.start_velocity, 0);
    EXPECT_EQ(p.end_velocity, 200);
    EXPECT_EQ(check_profile(p, mill, scurve), "");
}

TEST(ProfileCases, TooShortToSpeedUpEndsAtTheHighestReachableSpeed) {
    for (ProfileKind kind : {scurve, trapezoid}) {
        const Profile p = plan_profile(0.3, 10, 150, mill, kind);
        EXPECT_EQ(p.end_velocity, max_end_speed(0.3, 10, mill, kind));
        EXPECT_LT(p.end_velocity, 150);
        EXPECT_EQ(check_profile(p, mill, kind), "");
        EXPECT_NEAR(speed_change_distance(10, p.end_velocity, mill, kind), 0.3, 1e-12 * 0.3);
    }
}

TEST(ProfileCases, TooShortToBrakeEndsAtTheLowestReachableSpeed) {
    for (ProfileKind kind : {scurve, trapezoid}) {
        const Profile p = plan_profile(0.3, 150, 0, mill, kind);
        EXPECT_EQ(p.end_velocity, min_end_speed(0.3, 150, mill, kind));
        EXPECT_GT(p.end_velocity, 0);
        EXPECT_EQ(check_profile(p, mill, kind), "");
        EXPECT_NEAR(speed_change_distance(p.end_velocity, 150, mill, kind), 0.3, 1e-12 * 0.3);
    }
}

TEST(ProfileCases, BrakingToAStopTakesLessThanBrakingToNearlyAStop) {
    // Jerk-limited, acceleration never reached (a is huge): braking from 10 mm/s by dv covers
    // (10 - dv/2) 2 sqrt(dv/j), which peaks at dv = 2/3 of 10 and falls to 10 sqrt(10) = 31.62
    // for a full stop. Over 32 mm the reachable end speeds below 10 are [0, v_a] and [v_b = 6, 10].
    const ProfileLimits l{100, 1e6, 1};
    EXPECT_NEAR(speed_change_distance(0, 10, l, scurve), 10 * std::sqrt(10.0), 1e-12);
    EXPECT_NEAR(speed_change_distance(1, 10, l, scurve), 33, 1e-12);
    EXPECT_NEAR(speed_change_distance(6, 10, l, scurve), 32, 1e-12);
    EXPECT_EQ(min_end_speed(32, 10, l, scurve), 0);
    EXPECT_EQ(plan_profile(32, 10, 0, l, scurve).end_velocity, 0);
    EXPECT_EQ(plan_profile(32, 10, 6, l, scurve).end_velocity, 6);
    // 3 mm/s is out of reach: the end speed becomes v_a, the highest reachable below 3.
    const Profile p = plan_profile(32, 10, 3, l, scurve);
    EXPECT_GT(p.end_velocity, 0.2);
    EXPECT_LT(p.end_velocity, 0.3);
    EXPECT_NEAR(speed_change_distance(p.end_velocity, 10, l, scurve), 32, 1e-12);
    EXPECT_EQ(check_profile(p, l, scurve), "");
    // Over 31 mm not even a stop fits: the lowest reachable speed is v_b.
    const double v_b = min_end_speed(31, 10, l, scurve);
    EXPECT_GT(v_b, 6);
    EXPECT_NEAR(speed_change_distance(v_b, 10, l, scurve), 31, 1e-12);
    EXPECT_EQ(plan_profile(31, 10, 0, l, scurve).end_velocity, v_b);
    // The same hump with the acceleration limit reached: braking by dv near a full stop.
    const ProfileLimits m{300, 1000, 1e5};  // a^2/j = 10 mm/s
    const double stop = speed_change_distance(0, 100, m, scurve);
    EXPECT_GT(speed_change_distance(2, 100, m, scurve), stop);
    // Near a stop the braking distance falls by a/(2j) = 0.005 s per mm/s of end speed.
    const Profile q = plan_profile(stop + 0.005, 100, 2, m, scurve);
    EXPECT_GT(q.end_velocity, 0.5);
    EXPECT_LT(q.end_velocity, 2);
    EXPECT_NEAR(speed_change_distance(q.end_velocity, 100, m, scurve), stop + 0.005, 1e-12 * stop);
    EXPECT_EQ(check_profile(q, m, scurve), "");
}

TEST(ProfileCases, InfiniteJerkIsATrapezoid) {
    const ProfileLimits hard{200, 1000, std::numeric_limits<double>::infinity()};
    for (double d : {0.01, 1.0, 100.0}) {
        const Profile s = plan_profile(d, 30, 70, hard, scurve);
        const Profile t = plan_profile(d, 30, 70, mill, trapezoid);
        EXPECT_EQ(s.phase_count, t.phase_count);
        EXPECT_NEAR(s.duration_s(), t.duration_s(), 1e-15 * t.duration_s());
    }
}

TEST(ProfileCases, SCurveTendsToTrapezoidAsJerkGrows) {
    const double trap = plan_profile(10, 20, 40, mill, trapezoid).duration_s();
    for (double j : {1e6, 1e8, 1e10}) {
        const double s = plan_profile(10, 20, 40, {200, 1000, j}, scurve).duration_s();
        EXPECT_GT(s, trap);
        EXPECT_LT(s - trap, 2.0 * 1000 / j);  // at most a/j per speed change
    }
}

TEST(ProfileCases, DurationIsContinuousAcrossRegimeBoundaries) {
    // The lower half reaches the acceleration limit at one distance, the upper half at
    // another, the velocity limit at a third; the duration has no jump at any. (Infeasible
    // requests are left out: their clamped end speed jumps where a full stop starts to fit.)
    for (double v0 : {0.0, 4.0, 25.0}) {
        double previous = 0;
        for (double d = speed_change_distance(v0, 2.0, mill, scurve); d < 300; d *= 1.001) {
            const double t = plan_profile(d, v0, 2.0, mill, scurve).duration_s();
            if (previous > 0) {
                ASSERT_LT(std::abs(t - previous), 2e-3 * previous) << "d=" << d;
            }
            previous = t;
        }
    }
}

TEST(ProfileCases, StartPositionOffsetsEveryState) {
    Profile p = plan_profile(10, 5, 0, mill, scurve);
    const ProfileState a = p.at(0.05);
    p.start_position = 1000;
    EXPECT_NEAR(p.at(0.05).position, 1000 + a.position, 1e-12);
    EXPECT_EQ(p.at(1e9).position, 1010);
    EXPECT_EQ(p.at(-1).position, 1000);
}

TEST(ProfileCases, TrapezoidAccelerationJumps) {
    const Profile p = plan_profile(100, 0, 0, mill, trapezoid);
    ASSERT_EQ(p.phase_count, 3);
    EXPECT_EQ(p.phases[0].acceleration, 1000);
    EXPECT_EQ(p.phases[1].acceleration, 0);
    EXPECT_EQ(p.phases[2].acceleration, -1000);
    EXPECT_EQ(p.at(0.1).acceleration, 1000);
    EXPECT_EQ(p.at(p.duration_s()).acceleration, 0);
}

}  // namespace
}  // namespace nckit
