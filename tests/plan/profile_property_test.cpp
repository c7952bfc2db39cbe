// Randomised invariants (Ruckig's habit): 100,000 requests with a fixed seed, distances
// 1e-4..1000 mm and limits over several decades, both kinds, feasible or not.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

#include "nckit/plan/profile.hpp"
#include "profile_check.hpp"

namespace nckit {
namespace {

using plan_test::check_profile;
using plan_test::inf;
using plan_test::ref_change_distance;
using plan_test::ref_change_time;

struct Request {
    double distance = 0;
    double v_start = 0;
    double v_end = 0;
    ProfileLimits limits;
    ProfileKind kind = ProfileKind::scurve;
};

class RequestSource {
public:
    explicit RequestSource(std::uint64_t seed) : random_(seed) {}

    Request next() {
        Request r;
        r.kind = uniform(0, 1) < 0.7 ? ProfileKind::scurve : ProfileKind::trapezoid;
        r.limits.max_velocity = decade(0, 3.5);    // 1 .. 3000 mm/s
        r.limits.max_acceleration = decade(1, 5);  // 10 .. 1e5 mm/s^2
        r.limits.max_jerk = decade(2, 8);          // 100 .. 1e8 mm/s^3
        r.distance = decade(-4, 3);                // 1e-4 .. 1000 mm
        r.v_start = speed(r.limits.max_velocity);
        const double choice = uniform(0, 1);
        if (choice < 0.5) {
            r.v_end = speed(r.limits.max_velocity);  // often infeasible
        } else {
            // Within the reachable range, which the hump can still make infeasible.
            const double lo = min_end_speed(r.distance, r.v_start, r.limits, r.kind);
            const double hi = max_end_speed(r.distance, r.v_start, r.limits, r.kind);
            r.v_end = choice < 0.6 ? lo : choice < 0.7 ? hi : uniform(lo, hi);
        }
        return r;
    }

private:
    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(random_); }
    double decade(double lo, double hi) { return std::pow(10.0, uniform(lo, hi)); }
    //! 0 and v_max exactly, tiny speeds, and uniform ones.
    double speed(double v_max) {
        const double c = uniform(0, 1);
        if (c < 0.15) return 0;
        if (c < 0.25) return v_max;
        if (c < 0.35) return v_max * decade(-6, -1);
        return uniform(0, v_max);
    }
    std::mt19937_64 random_;
};

//! The brute-force competitor: the fastest profile on a grid of peak speeds (with a cruise at
//! the peak) and of valley speeds (braking below both ends, cruising, speeding up again).
double brute_force_s(const Request& q, double v0, double v1) {
    const double a = q.limits.max_acceleration;
    const double j = plan_test::jerk_of(q.limits, q.kind);
    const double d = q.distance;
    double best = inf;
    auto consider = [&](double ramps_mm, double ramps_s, double cruise_v) {
        if (ramps_mm <= d && cruise_v > 0) best = std::min(best, ramps_s + (d - ramps_mm) / cruise_v);
    };
    const double hi = std::max(v0, v1);
    const double vmax = q.limits.max_velocity;
    for (int i = 0; i <= 300; ++i) {
        const double vp = hi + (vmax - hi) * i / 300.0;
        consider(ref_change_distance(v0, vp, a, j) + ref_change_distance(v1, vp, a, j),
                 ref_change_time(vp - v0, a, j) + ref_change_time(vp - v1, a, j), vp);
    }
    const double lo = std::min(v0, v1);
    for (int i = 0; i <= 100; ++i) {
        const double u = lo * i / 100.0;
        consider(ref_change_distance(u, v0, a, j) + ref_change_distance(u, v1, a, j),
                 ref_change_time(v0 - u, a, j) + ref_change_time(v1 - u, a, j), u);
    }
    return best;
}

TEST(ProfileProperty, HundredThousandRandomRequests) {
    RequestSource source(20240611);
    int failures = 0;
    int infeasible = 0;
    int with_cruise = 0;
    int hump_clamps = 0;
    int brute_forced = 0;
    int regimes[2][2] = {};  // [rise reaches a][fall reaches a], S-curves without cruise
    for (int n = 0; n < 100000 && failures < 10; ++n) {
        const Request q = source.next();
        const Profile p = plan_profile(q.distance, q.v_start, q.v_end, q.limits, q.kind);
        auto fail = [&](const std::string& what) {
            ADD_FAILURE() << "request " << n << ": d=" << q.distance << " v0=" << q.v_start << " v1=" << q.v_end
                          << " v=" << q.limits.max_velocity << " a=" << q.limits.max_acceleration
                          << " j=" << q.limits.max_jerk << " kind=" << static_cast<int>(q.kind) << ": " << what;
            ++failures;
        };
        const std::string broken = check_profile(p, q.limits, q.kind);
        if (!broken.empty()) {
            fail(broken);
            continue;
        }
        const double a = q.limits.max_acceleration;
        const double j = plan_test::jerk_of(q.limits, q.kind);
        const double v0 = q.v_start;
        const double v1 = p.end_velocity;
        // Feasibility by the test's own formula; near the edge either answer is right.
        const double need = ref_change_distance(std::min(v0, q.v_end), std::max(v0, q.v_end), a, j);
        if (q.distance >= need * (1 + 1e-12)) {
            if (v1 != q.v_end) fail("feasible request clamped");
        } else if (q.distance < need * (1 - 1e-12)) {
            ++infeasible;
            if (v1 == q.v_end) fail("infeasible request planned as asked");
            if (v1 > q.v_end && v1 != min_end_speed(q.distance, v0, q.limits, q.kind))
                fail("clamped above the request");
            if (v1 < q.v_end && v0 > q.v_end) ++hump_clamps;
        }
        if (ref_change_distance(std::min(v0, v1), std::max(v0, v1), a, j) > q.distance * (1 + 1e-9)) {
            fail("planned end speed out of reach");
        }
        // The look-ahead's test: max_end_speed both ways is feasibility.
        const bool both_ways = q.v_end <= max_end_speed(q.distance, v0, q.limits, q.kind) &&
                               v0 <= max_end_speed(q.distance, q.v_end, q.limits, q.kind);
        if (q.distance >= need * (1 + 1e-9) && !both_ways) fail("feasible but not within max_end_speed both ways");
        if (q.distance < need * (1 - 1e-9) && both_ways) fail("infeasible but within max_end_speed both ways");
        // Optimality: no brute-force profile is faster (every 40th request).
        if (n % 40 == 0) {
            ++brute_forced;
            const double best = brute_force_s(q, v0, v1);
            if (p.duration_s() > best * (1 + 1e-9)) {
                fail("slower than brute force: " + std::to_string(p.duration_s()) + " > " + std::to_string(best));
            }
        }
        // max_end_speed and min_end_speed against plan_profile.
        const double hi = max_end_speed(q.distance, v0, q.limits, q.kind);
        const double lo = min_end_speed(q.distance, v0, q.limits, q.kind);
        if (!(lo <= v0 && v0 <= hi)) fail("min/max end speed do not bracket v_start");
        if (plan_profile(q.distance, v0, hi, q.limits, q.kind).end_velocity != hi) fail("max_end_speed not reachable");
        if (plan_profile(q.distance, v0, lo, q.limits, q.kind).end_velocity != lo) fail("min_end_speed not reachable");
        // Exact to 1e-12 of the speed: d lies between the distances of the speed changes to
        // v -+ 1e-12 v (no nearer than v_start). A tolerance on the distance alone cannot be met
        // by any double when the speed change is tiny: the distance grows like its square root.
        auto brackets = [&](double v, double from) {
            const double dv = 1e-12 * std::max(v, from);
            const double nearer = v > from ? std::max(from, v - dv) : std::min(from, v + dv);
            const double farther = v > from ? v + dv : std::max(0.0, v - dv);
            const double d1 = ref_change_distance(std::min(from, nearer), std::max(from, nearer), a, j);
            const double d2 = ref_change_distance(std::min(from, farther), std::max(from, farther), a, j);
            return d1 <= q.distance * (1 + 1e-12) && d2 >= q.distance * (1 - 1e-12);
        };
        if (hi < q.limits.max_velocity) {
            if (!brackets(hi, v0)) fail("max_end_speed inexact");
            if (plan_profile(q.distance, v0, hi * (1 + 1e-6), q.limits, q.kind).end_velocity != hi) {
                fail("beyond max_end_speed not clamped to it");
            }
        }
        if (lo > 0) {
            if (!brackets(lo, v0)) fail("min_end_speed inexact");
            if (plan_profile(q.distance, v0, lo * (1 - 1e-6), q.limits, q.kind).end_velocity != lo) {
                fail("below min_end_speed not clamped to it");
            }
        }
        // Coverage bookkeeping.
        bool cruise = false;
        for (int k = 0; k < p.phase_count; ++k) {
            const ProfilePhase& ph = p.phases[static_cast<std::size_t>(k)];
            if (ph.jerk == 0 && ph.acceleration == 0) cruise = true;
        }
        with_cruise += cruise;
        if (q.kind == ProfileKind::scurve && !cruise) {
            double rise_a = 0, fall_a = 0;
            for (int k = 0; k < p.phase_count; ++k) {
                const double acc = p.phases[static_cast<std::size_t>(k)].acceleration;
                rise_a = std::max(rise_a, acc);
                fall_a = std::min(fall_a, acc);
            }
            ++regimes[rise_a >= a * (1 - 1e-12)][-fall_a >= a * (1 - 1e-12)];
        }
    }
    EXPECT_EQ(failures, 0);
    // The draw reaches every case, so the invariants above were tested on each.
    EXPECT_GT(infeasible, 5000);
    EXPECT_GT(hump_clamps, 10);
    EXPECT_GT(with_cruise, 5000);
    EXPECT_GT(brute_forced, 2000);
    for (auto& row : regimes) {
        for (int count : row) EXPECT_GT(count, 500);
    }
    std::printf("infeasible %d (hump %d), cruise %d, no-cruise S-curves by regime %d %d %d %d, brute-forced %d\n",
                infeasible, hump_clamps, with_cruise, regimes[0][0], regimes[0][1], regimes[1][0], regimes[1][1],
                brute_forced);
}

}  // namespace
}  // namespace nckit
