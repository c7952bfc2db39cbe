// The fast step solvers against the reference ones: the closed-form arc crossings against Newton
// with the library's sine and cosine, the quadratic-formula profile inverse against Newton on the
// cubic, and whole programs' steps (StepSolver::fast against StepSolver::reference).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <random>
#include <vector>

#include "../../src/drive/arc_crossing.hpp"
#include "../../src/drive/profile_clock.hpp"
#include "nckit/drive/step_generator.hpp"
#include "nckit/plan/planner.hpp"

namespace nckit {
namespace {

using drive_detail::ArcAxisCrossings;

constexpr double two_pi = 2 * std::numbers::pi;

AxisVector xyz(double x, double y, double z) {
    AxisVector p;
    p[Axis::X] = x;
    p[Axis::Y] = y;
    p[Axis::Z] = z;
    return p;
}

// The in-plane axes of a plane, in G2/G3's order, and its normal.
struct PlaneAxes {
    std::size_t first, second, normal;
};
PlaneAxes plane_axes(Plane plane) {
    switch (plane) {
        case Plane::xy:
            return {0, 1, 2};
        case Plane::zx:
            return {2, 0, 1};
        case Plane::yz:
            return {1, 2, 0};
    }
    return {0, 1, 2};
}

// A random arc or helix in a random plane, ending on its circle (or, with `mismatch`, a little
// off it, which make_arc turns into a small in-plane linear rate).
Arc random_arc(std::mt19937_64& rng, double mismatch) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const Plane planes[] = {Plane::xy, Plane::zx, Plane::yz};
    Arc a;
    a.plane = planes[static_cast<int>(unit(rng) * 3) % 3];
    const PlaneAxes p = plane_axes(a.plane);
    a.from = xyz(200 * unit(rng) - 100, 200 * unit(rng) - 100, 200 * unit(rng) - 100);
    const double r = std::pow(10.0, 3 * unit(rng) - 1.5);  // 0.03 .. 30 mm
    const double start = two_pi * unit(rng);
    const double sweep = two_pi * unit(rng);
    a.direction = unit(rng) < 0.5 ? ArcDirection::counterclockwise : ArcDirection::clockwise;
    a.center = a.from;
    a.center[p.first] = a.from[p.first] - r * std::cos(start);
    a.center[p.second] = a.from[p.second] - r * std::sin(start);
    const double end = start + (a.direction == ArcDirection::counterclockwise ? sweep : -sweep);
    const double r_end = r * (1 + mismatch * (2 * unit(rng) - 1));
    a.to = a.from;
    a.to[p.first] = a.center[p.first] + r_end * std::cos(end);
    a.to[p.second] = a.center[p.second] + r_end * std::sin(end);
    if (unit(rng) < 0.5) a.to[p.normal] += 20 * unit(rng) - 10;  // a helix
    a.full_turns = unit(rng) < 0.2 ? 1 + static_cast<int>(unit(rng) * 3) : 0;
    return a;
}

TEST(ArcAxisCrossings, ClosedFormMatchesNewtonOnRandomArcs) {
    std::mt19937_64 rng(2024);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int compared = 0;
    int fallbacks = 0;
    for (int n = 0; n < 4000; ++n) {
        const PathSegment g = make_arc(random_arc(rng, n % 4 == 0 ? 1e-9 : 0.0));
        ASSERT_EQ(g.shape, SegmentShape::arc);
        for (std::size_t i = 0; i < 3; ++i) {
            if (!ArcAxisCrossings::applies(g, i)) continue;
            ArcAxisCrossings arc(g, i);
            std::vector<double> cuts{0.0};
            for (double s : drive_detail::arc_turning_points(g, i)) cuts.push_back(s);
            cuts.push_back(g.length);
            const double spu = 100 + 2000 * unit(rng);
            for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
                const double s_a = cuts[c];
                const double s_b = cuts[c + 1];
                const double x_a = position_at(g, s_a)[i] * spu;
                const double x_b = position_at(g, s_b)[i] * spu;
                if (std::abs(x_b - x_a) < 1e-6) continue;
                arc.set_interval(s_a, s_b);
                const int rising = x_b > x_a ? 1 : -1;
                for (int k = 0; k < 20; ++k) {
                    // A boundary strictly inside the interval's range of x.
                    const double boundary = x_a + (x_b - x_a) * (0.001 + 0.998 * unit(rng));
                    const double fast = arc.crossing(boundary / spu, s_a, s_b);
                    const double newton =
                        drive_detail::arc_crossing_newton(g, i, spu, boundary, s_a, s_b, rising, 0.5 * (s_a + s_b));
                    if (fast < 0) {
                        ++fallbacks;
                        continue;
                    }
                    // Both are roots of the same monotone function to a rounding of q (checked in
                    // long double), so they differ by about that rounding over the slope.
                    auto residual = [&](double at) {
                        const long double theta = static_cast<long double>(g.angle_rate) * at;
                        const long double q = g.origin[i] + static_cast<long double>(g.rate[i]) * at +
                                              g.radius_mm * (std::cos(theta) * g.u[i] + std::sin(theta) * g.v[i]);
                        return static_cast<double>(std::abs(q * spu - boundary));
                    };
                    // q's own rounding, the angle k s's included (a few turns make it the larger).
                    const double q_rounding =
                        4 * 2.2e-16 * (std::abs(g.origin[i]) + g.radius_mm * (1 + g.angle_rate * newton)) * spu;
                    ASSERT_LE(residual(fast), q_rounding + residual(newton))
                        << "arc " << n << " axis " << i << " interval " << c;
                    const double slope = std::abs(point_at(g, newton).d1[i]) * spu;
                    ASSERT_NEAR(fast, newton, 1e-13 * std::max(1.0, g.length) + 2 * q_rounding / slope)
                        << "arc " << n << " axis " << i << " interval " << c;
                    ++compared;
                }
            }
        }
    }
    EXPECT_GT(compared, 100000);
    EXPECT_EQ(fallbacks, 0);
}

TEST(ArcAxisCrossings, DeclinesARateThatMovesTheTurningPoints) {
    // A quarter circle whose end lies 1 % off the radius: the linear part is far from a rounding.
    Arc a;
    a.from = xyz(10, 0, 0);
    a.center = xyz(0, 0, 0);
    a.to = xyz(0, 10.1, 0);
    a.direction = ArcDirection::counterclockwise;
    const PathSegment g = make_arc(a);
    EXPECT_TRUE(ArcAxisCrossings::applies(g, 0));   // X ends on the circle: a rounding-sized rate
    EXPECT_FALSE(ArcAxisCrossings::applies(g, 1));  // Y takes the 0.1 mm: Newton
    EXPECT_FALSE(ArcAxisCrossings::applies(g, 2));  // off the circle: moves linearly (not at all here)
}

TEST(ProfileClock, QuadraticFormulaMatchesNewton) {
    std::mt19937_64 rng(99);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int compared = 0;
    for (int n = 0; n < 3000; ++n) {
        const ProfileLimits limits{1 + 200 * unit(rng), 10 + 5000 * unit(rng), 100 + 1e6 * unit(rng)};
        const ProfileKind kind = n % 2 == 0 ? ProfileKind::trapezoid : ProfileKind::scurve;
        const double distance = std::pow(10.0, 4 * unit(rng) - 2);
        const Profile profile = plan_profile(distance, limits.max_velocity * unit(rng) * (n % 3 == 0 ? 0 : 1),
                                             limits.max_velocity * unit(rng) * (n % 5 == 0 ? 0 : 1), limits, kind);
        drive_detail::ProfileClock fast(profile, drive_detail::PhaseSolver::closed_form);
        drive_detail::ProfileClock newton(profile, drive_detail::PhaseSolver::newton);
        std::vector<double> positions(200);
        for (double& p : positions) p = profile.distance * unit(rng);
        std::sort(positions.begin(), positions.end());
        for (double p : positions) {
            const double t_fast = fast.time_at(p);
            const double t_newton = newton.time_at(p);
            // The time a position is reached, to far below a ns, and the position at that time.
            ASSERT_NEAR(t_fast, t_newton, 1e-11 + 1e-12 * profile.duration_s()) << "profile " << n << " p " << p;
            ASSERT_NEAR(profile.at(t_fast).position - profile.start_position, p, 1e-12 + 1e-13 * distance);
            ++compared;
        }
    }
    EXPECT_EQ(compared, 600000);
}

// Lines, blends, arcs, helices and arcs with a radius mismatch.
std::vector<Move> random_program(std::mt19937_64& rng, int count) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Move> moves;
    AxisVector at = xyz(0.1, -0.2, 0.3);
    for (int n = 0; n < count; ++n) {
        const Feed feed{FeedMode::per_minute, 200 + 5000 * unit(rng), 0};
        Move m;
        if (unit(rng) < 0.5) {
            Arc a = random_arc(rng, unit(rng) < 0.2 ? 1e-7 : 0.0);
            const AxisVector shift = at - a.from;
            a.from = at;
            a.to = a.to + shift;
            a.center = a.center + shift;
            a.full_turns = std::min(a.full_turns, 1);
            a.feed = feed;
            m.what = a;
            at = a.to;
        } else {
            AxisVector to = at;
            for (std::size_t i = 0; i < 3; ++i) to[i] = at[i] + 6 * unit(rng) - 3;
            PathControl path;
            path.exact_stop = unit(rng) < 0.2;
            m.what = Line{at, to, feed, false, path};
            at = to;
        }
        moves.push_back(m);
    }
    return moves;
}

// Per axis, the fast solvers' steps against the reference: the same steps in the same order,
// each within 1 ns, and at most 1 in 10,000 not to the ns (the exact times agree to ~1e-14 s; only
// one within that of a half ns rounds the other way).
void expect_same_steps(const std::vector<StepEvent>& fast, const std::vector<StepEvent>& reference, std::size_t axes) {
    ASSERT_EQ(fast.size(), reference.size());
    std::int64_t differing = 0;
    for (std::size_t axis = 0; axis < axes; ++axis) {
        std::vector<StepEvent> f;
        std::vector<StepEvent> r;
        for (const StepEvent& e : fast) {
            if (e.axis == axis) f.push_back(e);
        }
        for (const StepEvent& e : reference) {
            if (e.axis == axis) r.push_back(e);
        }
        ASSERT_EQ(f.size(), r.size()) << "axis " << axis;
        for (std::size_t k = 0; k < f.size(); ++k) {
            ASSERT_EQ(f[k].direction, r[k].direction) << "axis " << axis << " step " << k;
            ASSERT_EQ(f[k].backlash, r[k].backlash);
            ASSERT_LE(std::llabs(f[k].t_ns - r[k].t_ns), 1) << "axis " << axis << " step " << k;
            if (f[k].t_ns != r[k].t_ns) ++differing;
        }
    }
    EXPECT_LT(differing, static_cast<std::int64_t>(fast.size() / 10000) + 1);
}

TEST(StepSolver, FastStepsEqualReferenceStepsOnRandomPrograms) {
    for (ProfileKind kind : {ProfileKind::scurve, ProfileKind::trapezoid}) {
        MachineConfig machine = default_mill();
        machine.profile = kind;
        machine.axes[0].steps_per_unit = 800.0;
        machine.axes[1].steps_per_unit = 1234.5678;
        machine.axes[2].steps_per_unit = 333.3;
        for (std::uint64_t seed = 1; seed <= 4; ++seed) {
            std::mt19937_64 rng(seed);
            const PlanResult plan = plan_moves(random_program(rng, 300), machine);
            ASSERT_TRUE(plan.diagnostics.empty());
            const std::vector<StepEvent> fast = generate_steps(plan.trajectory, machine, StepSolver::fast);
            const std::vector<StepEvent> reference = generate_steps(plan.trajectory, machine, StepSolver::reference);
            EXPECT_GT(fast.size(), 100000U);
            expect_same_steps(fast, reference, machine.axes.size());
        }
    }
}

TEST(StepSolver, FastStepsEqualReferenceStepsWithBacklash) {
    MachineConfig machine = default_mill();
    for (AxisConfig& axis : machine.axes) {
        axis.steps_per_unit = 400.0;
        axis.backlash = 0.02;
    }
    std::mt19937_64 rng(77);
    const PlanResult plan = plan_moves(random_program(rng, 200), machine);
    ASSERT_TRUE(plan.diagnostics.empty());
    expect_same_steps(generate_steps(plan.trajectory, machine, StepSolver::fast),
                      generate_steps(plan.trajectory, machine, StepSolver::reference), machine.axes.size());
}

}  // namespace
}  // namespace nckit
