// Fixed reference cases: the worked numbers of docs/planner.md, trapezoid closed forms,
// and the notch run-up.
#include <gtest/gtest.h>

#include <cmath>

#include "nckit/plan/profile.hpp"
#include "profile_check.hpp"

namespace nckit {
namespace {

using plan_test::check_profile;

//! The rest-to-rest duration of docs/planner.md, its four cases as written there.
double reference_rest_to_rest_s(double d, double v, double a, double j) {
    if (v * j >= a * a && d >= v * (v / a + a / j)) return d / v + v / a + a / j;
    if (v * j >= a * a) {
        const double vp = (a / 2) * (-a / j + std::sqrt(a * a / (j * j) + 4 * d / a));
        if (vp >= a * a / j) return 2 * (vp / a + a / j);
    }
    if (v * j < a * a && d >= 2 * v * std::sqrt(v / j)) return d / v + 2 * std::sqrt(v / j);
    return 4 * std::cbrt(d / (2 * j));
}

struct RestToRest {
    double d, v, a, j, duration_s;
};

TEST(ProfileReference, WorkedRestToRestDurations) {
    // The table prints 9 decimals, so it is matched to half its last digit; the closed forms it
    // was computed from are matched to 1e-12 relative.
    const RestToRest cases[] = {
        {100, 50, 1000, 1e5, 2.060000000}, {1, 50, 1000, 1e5, 0.074031242},   {0.05, 50, 1000, 1e5, 0.025198421},
        {10, 200, 500, 1000, 0.683990379}, {100, 20, 5000, 1e4, 5.089442719},
    };
    for (const RestToRest& c : cases) {
        SCOPED_TRACE(testing::Message() << "d=" << c.d << " v=" << c.v << " a=" << c.a << " j=" << c.j);
        const ProfileLimits limits{c.v, c.a, c.j};
        const Profile p = plan_profile(c.d, 0, 0, limits, ProfileKind::scurve);
        EXPECT_NEAR(p.duration_s(), c.duration_s, 5e-10);
        const double exact = reference_rest_to_rest_s(c.d, c.v, c.a, c.j);
        EXPECT_NEAR(p.duration_s(), exact, 1e-12 * exact);
        EXPECT_EQ(check_profile(p, limits, ProfileKind::scurve), "");
        EXPECT_EQ(p.at(p.duration_s()).position, c.d);
    }
}

TEST(ProfileReference, WorkedCasesHaveTheirPhases) {
    // 100/50/1000/1e5: both limits reached and a cruise: all 7 phases.
    EXPECT_EQ(plan_profile(100, 0, 0, {50, 1000, 1e5}, ProfileKind::scurve).phase_count, 7);
    // 1 mm: the acceleration limit but no cruise: +j, a, -j, -j, -a, +j.
    EXPECT_EQ(plan_profile(1, 0, 0, {50, 1000, 1e5}, ProfileKind::scurve).phase_count, 6);
    // 0.05 mm: neither limit: +j, -j, -j, +j.
    EXPECT_EQ(plan_profile(0.05, 0, 0, {50, 1000, 1e5}, ProfileKind::scurve).phase_count, 4);
    // 100/20/5000/1e4: cruise, acceleration limit never reached.
    EXPECT_EQ(plan_profile(100, 0, 0, {20, 5000, 1e4}, ProfileKind::scurve).phase_count, 5);
}

TEST(ProfileReference, RestToRestOverAWideRangeOfDistances) {
    const ProfileLimits limits[] = {{50, 1000, 1e5}, {200, 500, 1000}, {20, 5000, 1e4}, {1000, 3000, 2e6}};
    for (const ProfileLimits& l : limits) {
        for (double d = 1e-4; d < 2000; d *= 1.37) {
            const Profile p = plan_profile(d, 0, 0, l, ProfileKind::scurve);
            const double exact = reference_rest_to_rest_s(d, l.max_velocity, l.max_acceleration, l.max_jerk);
            ASSERT_NEAR(p.duration_s(), exact, 1e-12 * exact) << "d=" << d;
        }
    }
}

TEST(ProfileReference, TrapezoidClosedForms) {
    const ProfileLimits l{100, 400, 0};  // jerk ignored
    const double a = l.max_acceleration;
    const double v = l.max_velocity;
    // Rest to rest with a cruise: d/v + v/a.
    Profile p = plan_profile(50, 0, 0, l, ProfileKind::trapezoid);
    EXPECT_NEAR(p.duration_s(), 50 / v + v / a, 1e-15 * 50);
    EXPECT_EQ(p.phase_count, 3);
    // Without: 2 sqrt(d/a).
    p = plan_profile(10, 0, 0, l, ProfileKind::trapezoid);
    EXPECT_NEAR(p.duration_s(), 2 * std::sqrt(10 / a), 1e-15);
    EXPECT_EQ(p.phase_count, 2);
    // Boundary speeds, no cruise: peak^2 = a d + (v0^2 + v1^2)/2, T = (2 peak - v0 - v1)/a.
    const double v0 = 30, v1 = 70, d = 12;
    const double peak = std::sqrt(a * d + (v0 * v0 + v1 * v1) / 2);
    ASSERT_LT(peak, v);
    p = plan_profile(d, v0, v1, l, ProfileKind::trapezoid);
    EXPECT_NEAR(p.duration_s(), (2 * peak - v0 - v1) / a, 1e-15);
    EXPECT_EQ(check_profile(p, l, ProfileKind::trapezoid), "");
    // With a cruise.
    const double long_d = 40;
    const double ramps_mm = (2 * v * v - v0 * v0 - v1 * v1) / (2 * a);
    p = plan_profile(long_d, v0, v1, l, ProfileKind::trapezoid);
    EXPECT_NEAR(p.duration_s(), (2 * v - v0 - v1) / a + (long_d - ramps_mm) / v, 1e-15 * long_d);
    // Monotone speed-ups and brakings: (v1^2 - v0^2) / (2a).
    EXPECT_NEAR(speed_change_distance(v0, v1, l, ProfileKind::trapezoid), (v1 * v1 - v0 * v0) / (2 * a), 1e-13);
    EXPECT_NEAR(max_end_speed(1, v0, l, ProfileKind::trapezoid), std::sqrt(v0 * v0 + 2 * a), 1e-13);
    EXPECT_NEAR(min_end_speed(1, v0, l, ProfileKind::trapezoid), std::sqrt(v0 * v0 - 2 * a), 1e-13);
    EXPECT_EQ(min_end_speed(2, v0, l, ProfileKind::trapezoid), 0);
}

TEST(ProfileReference, NotchRunUpDistance) {
    // F950 from rest with a = 500, j = 5000: a^2/j = 50 mm/s > F, so the acceleration limit is
    // never reached and the run-up is v sqrt(v/j).
    const double feed = 950.0 / 60.0;
    const ProfileLimits l{feed, 500, 5000};
    const double run_up = speed_change_distance(0, feed, l, ProfileKind::scurve);
    EXPECT_NEAR(run_up, 0.890991, 5e-7);
    EXPECT_NEAR(run_up, feed * std::sqrt(feed / 5000), 1e-15);
    EXPECT_NEAR(max_end_speed(run_up, 0, l, ProfileKind::scurve), feed, 1e-12 * feed);
    // Run up and cut 5 mm at F: speed is exactly F once the run-up distance is behind.
    const Profile p = plan_profile(run_up + 5, 0, feed, l, ProfileKind::scurve);
    EXPECT_EQ(p.end_velocity, feed);
    EXPECT_EQ(p.phase_count, 3);  // +j, -j, cruise
    const double ramp_s = p.phases[0].duration_s + p.phases[1].duration_s;
    EXPECT_NEAR(ramp_s, 2 * std::sqrt(feed / 5000), 1e-15);
    const ProfileState at_cut = p.at(ramp_s);
    EXPECT_NEAR(at_cut.position, 0.890991, 5e-7);
    EXPECT_NEAR(at_cut.velocity, feed, 1e-12);
    EXPECT_NEAR(p.at(ramp_s + 0.1).velocity, feed, 1e-12);
    EXPECT_EQ(check_profile(p, l, ProfileKind::scurve), "");
}

}  // namespace
}  // namespace nckit
