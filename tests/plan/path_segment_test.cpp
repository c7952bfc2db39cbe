// Path segments: exact derivatives against finite differences, arc and helix geometry, blends.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "../../src/plan/junction.hpp"
#include "nckit/plan/segment_limits.hpp"
#include <random>
#include "nckit/plan/path_segment.hpp"

namespace nckit {
namespace {

AxisVector point(double x, double y, double z, double a = 0) {
    AxisVector p;
    p[Axis::X] = x;
    p[Axis::Y] = y;
    p[Axis::Z] = z;
    p[Axis::A] = a;
    return p;
}

void expect_derivatives_match(const PathSegment& g) {
    const double h = 1e-4 * g.length;
    for (int k = 1; k < 10; ++k) {
        const double s = g.length * k / 10.0;
        const PathPoint at = point_at(g, s);
        const PathPoint lo = point_at(g, s - h);
        const PathPoint hi = point_at(g, s + h);
        for (std::size_t i = 0; i < axis_count; ++i) {
            EXPECT_NEAR(at.position[i], position_at(g, s)[i], 1e-12);
            const double scale = 1 + std::abs(at.d1[i]) + std::abs(at.d2[i]) * g.length;
            EXPECT_NEAR(at.d1[i], (hi.position[i] - lo.position[i]) / (2 * h), 1e-6 * scale) << i;
            EXPECT_NEAR(at.d2[i], (hi.d1[i] - lo.d1[i]) / (2 * h), 1e-6 * (1 + std::abs(at.d2[i]))) << i;
            EXPECT_NEAR(at.d3[i], (hi.d2[i] - lo.d2[i]) / (2 * h), 1e-6 * (1 + std::abs(at.d3[i]))) << i;
        }
    }
    // The bounds hold everywhere.
    const DerivativeBounds b = derivative_bounds(g);
    for (int k = 0; k <= 100; ++k) {
        const PathPoint at = point_at(g, g.length * k / 100.0);
        for (std::size_t i = 0; i < axis_count; ++i) {
            EXPECT_LE(std::abs(at.d1[i]), b.d1[i] * (1 + 1e-12) + 1e-15);
            EXPECT_LE(std::abs(at.d2[i]), b.d2[i] * (1 + 1e-12) + 1e-15);
            EXPECT_LE(std::abs(at.d3[i]), b.d3[i] * (1 + 1e-12) + 1e-15);
        }
        EXPECT_LE(std::hypot(at.d1[0], at.d1[1], at.d1[2]), b.speed_factor * (1 + 1e-12));
    }
}

TEST(PathSegment, LineIsUnitSpeedInXyz) {
    const PathSegment g = make_line(point(1, 2, 3, 10), point(4, 6, 3, 40));
    EXPECT_DOUBLE_EQ(g.length, 5.0);
    EXPECT_NEAR(end_point(g)[Axis::A], 40, 1e-12);
    EXPECT_NEAR(end_point(g)[Axis::Y], 6, 1e-12);
    expect_derivatives_match(g);
}

TEST(PathSegment, RotaryOnlyMoveMeasuresDegrees) {
    const PathSegment g = make_line(point(1, 2, 3, 10), point(1, 2, 3, -80));
    EXPECT_DOUBLE_EQ(g.length, 90.0);
    EXPECT_DOUBLE_EQ(g.rate[Axis::A], -1.0);
}

TEST(PathSegment, ArcsInEveryPlaneAndDirection) {
    for (Plane plane : {Plane::xy, Plane::zx, Plane::yz}) {
        for (ArcDirection dir : {ArcDirection::clockwise, ArcDirection::counterclockwise}) {
            Arc arc;
            arc.plane = plane;
            arc.direction = dir;
            // Plane axes (first, second): xy (X,Y), zx (Z,X), yz (Y,Z).
            const std::size_t f = plane == Plane::xy ? 0 : plane == Plane::zx ? 2 : 1;
            const std::size_t s = plane == Plane::xy ? 1 : plane == Plane::zx ? 0 : 2;
            arc.from = point(0, 0, 0, 5);
            arc.center = arc.from;
            arc.center[f] = -10;  // radius 10, start at angle 0
            arc.to = arc.from;
            arc.to[f] = -10;
            arc.to[s] = 10;  // quarter (ccw) or three quarters (cw)
            arc.to[Axis::A] = 50;
            const PathSegment g = make_arc(arc);
            const double sweep =
                dir == ArcDirection::counterclockwise ? 0.5 * std::numbers::pi : 1.5 * std::numbers::pi;
            EXPECT_NEAR(g.sweep_rad(), sweep, 1e-12);
            EXPECT_NEAR(g.length, 10 * sweep, 1e-9);
            for (std::size_t i = 0; i < axis_count; ++i) {
                EXPECT_NEAR(end_point(g)[i], arc.to[i], 1e-12) << i;
                EXPECT_NEAR(start_point(g)[i], arc.from[i], 1e-12) << i;
            }
            // Halfway lies on the circle, on the side the direction says.
            const AxisVector mid = position_at(g, 0.5 * g.length);
            EXPECT_NEAR(std::hypot(mid[f] - arc.center[f], mid[s] - arc.center[s]), 10, 1e-9);
            expect_derivatives_match(g);
        }
    }
}

TEST(PathSegment, HelixWithFullTurns) {
    Arc arc;
    arc.plane = Plane::xy;
    arc.direction = ArcDirection::counterclockwise;
    arc.from = point(5, 0, 0);
    arc.center = point(0, 0, 0);
    arc.to = point(5, 0, -3);
    arc.full_turns = 1;  // two turns in all
    const PathSegment g = make_arc(arc);
    EXPECT_NEAR(g.sweep_rad(), 4 * std::numbers::pi, 1e-12);
    EXPECT_NEAR(g.length, std::hypot(5 * 4 * std::numbers::pi, 3.0), 1e-9);
    EXPECT_NEAR(end_point(g)[Axis::Z], -3, 1e-12);
    EXPECT_NEAR(derivative_bounds(g).speed_factor, 1.0, 1e-12);
    expect_derivatives_match(g);
}

TEST(PathSegment, HelixOfRadiusZeroIsItsStraightLine) {
    // LinuxCNC's cutter compensation leaves the tool on the centre of a hole of its own diameter:
    // a helix of radius 0, which in space is the plunge along its axis.
    Arc arc;
    arc.plane = Plane::xy;
    arc.direction = ArcDirection::counterclockwise;
    arc.from = point(2, 3, 0.254);
    arc.center = point(2, 3, 0.254);
    arc.to = point(2, 3, -1.27);
    const PathSegment g = make_arc(arc);
    EXPECT_EQ(g.shape, SegmentShape::line);
    EXPECT_NEAR(g.length, 1.524, 1e-12);
    for (std::size_t i = 0; i < axis_count; ++i) EXPECT_NEAR(end_point(g)[i], arc.to[i], 1e-12) << i;
    expect_derivatives_match(g);
    // The full circle of radius 0 at depth goes nowhere.
    arc.from = arc.to;
    arc.center = arc.to;
    EXPECT_EQ(make_arc(arc).length, 0.0);
}

TEST(PathSegment, BlendIsTangentAndWithinTolerance) {
    for (double turn_deg : {0.01, 1.0, 30.0, 90.0, 150.0, 179.0}) {
        const double phi = turn_deg * std::numbers::pi / 180;
        const AxisVector corner = point(10, 0, 2);
        const PathSegment a = make_line(point(0, 0, 2), corner);
        const PathSegment b = make_line(corner, point(10 + 10 * std::cos(phi), 10 * std::sin(phi), 2));
        const double tol = 0.05;
        auto blend = plan_detail::blend_lines(a, a.length, b, tol);
        ASSERT_TRUE(blend) << turn_deg;
        EXPECT_LE(blend->trim_mm, 5.0 + 1e-12);
        EXPECT_LE(blend->deviation_mm, tol * (1 + 1e-12));
        // Starts at the trimmed end of a, ends at the trimmed start of b, tangent to both.
        const AxisVector s0 = position_at(a, a.length - blend->trim_mm);
        const AxisVector s1 = position_at(b, blend->trim_mm);
        double closest = 1e9;
        for (int k = 0; k <= 1000; ++k) {
            const AxisVector p = position_at(blend->arc, blend->arc.length * k / 1000);
            closest = std::min(closest, std::hypot(p[0] - corner[0], p[1] - corner[1], p[2] - corner[2]));
        }
        EXPECT_NEAR(closest, blend->deviation_mm, 1e-9);
        for (std::size_t i = 0; i < axis_count; ++i) {
            EXPECT_NEAR(start_point(blend->arc)[i], s0[i], 1e-9);
            EXPECT_NEAR(end_point(blend->arc)[i], s1[i], 1e-9);
            EXPECT_NEAR(point_at(blend->arc, 0).d1[i], a.rate[i], 1e-9);
            EXPECT_NEAR(point_at(blend->arc, blend->arc.length).d1[i], b.rate[i], 1e-9);
        }
        expect_derivatives_match(blend->arc);
    }
}

TEST(PathSegment, BlendNeverUsesMoreThanHalfALine) {
    const PathSegment a = make_line(point(0, 0, 0), point(0.01, 0, 0));
    const PathSegment b = make_line(point(0.01, 0, 0), point(0.01, 0.004, 0));
    auto blend = plan_detail::blend_lines(a, a.length, b, 1.0);
    ASSERT_TRUE(blend);
    EXPECT_NEAR(blend->trim_mm, 0.002, 1e-15);
}

TEST(PathSegment, NoBlendForReversalsOrDifferingRotaryRates) {
    const PathSegment a = make_line(point(0, 0, 0), point(10, 0, 0));
    EXPECT_FALSE(plan_detail::blend_lines(a, a.length, make_line(point(10, 0, 0), point(0, 0, 0)), 0.05));
    EXPECT_FALSE(plan_detail::blend_lines(a, a.length, make_line(point(10, 0, 0), point(10, 10, 0, 5)), 0.05));
}

TEST(PathSegment, TangencyTolerance) {
    const PathSegment a = make_line(point(0, 0, 0), point(10, 0, 0));
    EXPECT_TRUE(plan_detail::tangent(a, make_line(point(10, 0, 0), point(20, 1e-6, 0))));
    EXPECT_FALSE(plan_detail::tangent(a, make_line(point(10, 0, 0), point(20, 1e-4, 0))));
}

//! Bounds over an arc's own sweep: valid everywhere on it, and tight (reached at a sampled point
//! up to the sampling), for random partial arcs and helices in every orientation.
TEST(PathSegment, ArcBoundsCoverTheSweepAndAreTight) {
    std::mt19937_64 random(99);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int n = 0; n < 400; ++n) {
        Arc arc;
        arc.plane = static_cast<Plane>(n % 3);
        arc.direction = n % 2 == 0 ? ArcDirection::clockwise : ArcDirection::counterclockwise;
        const double r = std::pow(10.0, -2 + 3 * unit(random));
        const double a0 = 2 * std::numbers::pi * unit(random);
        // Sweeps from a thousandth of a degree to nearly a turn (and sometimes a turn and more).
        const double sweep =
            n % 7 == 0 ? 2 * std::numbers::pi * (1 + unit(random)) : std::pow(10.0, -5 + 5.8 * unit(random));
        const double a1 = a0 + (arc.direction == ArcDirection::counterclockwise ? sweep : -sweep);
        const std::size_t f = arc.plane == Plane::xy ? 0 : arc.plane == Plane::zx ? 2 : 1;
        const std::size_t s = arc.plane == Plane::xy ? 1 : arc.plane == Plane::zx ? 0 : 2;
        arc.center = point(1, 2, 3);
        arc.from = arc.center;
        arc.from[f] += r * std::cos(a0);
        arc.from[s] += r * std::sin(a0);
        arc.to = arc.center;
        arc.to[f] += r * std::cos(a1);
        arc.to[s] += r * std::sin(a1);
        arc.to[3 - f - s] += n % 3 == 0 ? unit(random) - 0.5 : 0.0;  // a helix now and then
        arc.full_turns = sweep >= 2 * std::numbers::pi ? 1 : 0;
        if (arc.full_turns == 1) arc.to = arc.from;
        const PathSegment g = make_arc(arc);
        const DerivativeBounds b = derivative_bounds(g);
        AxisVector seen1, seen2, seen3;
        double seen_speed = 0;
        const int samples = 4000;
        for (int k = 0; k <= samples; ++k) {
            const PathPoint at = point_at(g, g.length * k / samples);
            for (std::size_t i = 0; i < 3; ++i) {
                ASSERT_LE(std::abs(at.d1[i]), b.d1[i] * (1 + 1e-12) + 1e-15) << n << " axis " << i;
                ASSERT_LE(std::abs(at.d2[i]), b.d2[i] * (1 + 1e-12) + 1e-15) << n << " axis " << i;
                ASSERT_LE(std::abs(at.d3[i]), b.d3[i] * (1 + 1e-12) + 1e-15) << n << " axis " << i;
                seen1[i] = std::max(seen1[i], std::abs(at.d1[i]));
                seen2[i] = std::max(seen2[i], std::abs(at.d2[i]));
                seen3[i] = std::max(seen3[i], std::abs(at.d3[i]));
            }
            const double speed = std::hypot(at.d1[0], at.d1[1], at.d1[2]);
            ASSERT_LE(speed, b.speed_factor * (1 + 1e-12)) << n;
            seen_speed = std::max(seen_speed, speed);
        }
        // Tight: the sampling misses a crest by at most (step)²/2 of the amplitude.
        const double step = std::abs(g.sweep_rad()) / samples;
        const double slack = 0.5 * step * step + 1e-9;
        for (std::size_t i = 0; i < 3; ++i) {
            EXPECT_LE(b.d1[i], seen1[i] + slack * (1 + b.d1[i])) << n << " axis " << i;
            EXPECT_LE(b.d2[i], seen2[i] + slack * (1 + b.d2[i])) << n << " axis " << i;
            EXPECT_LE(b.d3[i], seen3[i] + slack * (1 + b.d3[i])) << n << " axis " << i;
        }
        EXPECT_LE(b.speed_factor, seen_speed + slack * (1 + b.speed_factor)) << n;
    }
}

//! A blend between nearly collinear lines along X with a slight Z slope: its X bound is the
//! lines' slope, not the circle's radius, so it keeps nearly the whole acceleration.
TEST(PathSegment, GentleBlendKeepsNearlyTheWholeAcceleration) {
    const PathSegment a = make_line(point(0, 0, 0), point(0.1, 0, 0.02));
    const PathSegment b = make_line(point(0.1, 0, 0.02), point(0.2, 0, 0.0405));
    auto blend = plan_detail::blend_lines(a, a.length, b, 0.01);
    ASSERT_TRUE(blend);
    const DerivativeBounds d = derivative_bounds(blend->arc);
    EXPECT_NEAR(d.d1[0], std::max(std::abs(a.rate[0]), std::abs(b.rate[0])), 1e-9);
    EXPECT_NEAR(d.d1[2], std::max(std::abs(a.rate[2]), std::abs(b.rate[2])), 1e-9);
    MachineConfig m = default_mill();
    for (AxisConfig& axis : m.axes) {
        axis.max_velocity = 100;
        axis.max_acceleration = 500;
        axis.max_jerk = 50000;
    }
    for (ProfileKind kind : {ProfileKind::trapezoid, ProfileKind::scurve}) {
        const ProfileLimits l = segment_limits(blend->arc, m, 50, kind);
        const ProfileLimits line = segment_limits(a, m, 50, kind);
        EXPECT_NEAR(l.max_velocity, 50, 1e-9);
        // (500 − d2·50²)/d1: within a few percent of the line's 500/|rate_x|, not half of it.
        EXPECT_GT(l.max_acceleration, 0.95 * line.max_acceleration) << static_cast<int>(kind);
    }
}

//! segment_limits: for random arcs, helices and blends, every axis limit holds with the
//! triangle-inequality budget (d2·v² + d1·a <= amax, d3·v³ + 3·d2·v·a + d1·j <= jmax), and no
//! limit is below what fixed halves and thirds give.
TEST(SegmentLimits, BudgetHoldsAndBeatsFixedShares) {
    std::mt19937_64 random(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    MachineConfig m = default_mill();
    for (int n = 0; n < 2000; ++n) {
        Arc arc;
        arc.plane = Plane::xy;
        arc.direction = ArcDirection::counterclockwise;
        const double r = std::pow(10.0, -2 + 3 * unit(random));
        const double a0 = 2 * std::numbers::pi * unit(random);
        const double sweep = std::pow(10.0, -4 + 4.7 * unit(random));
        arc.center = point(0, 0, 0);
        arc.from = point(r * std::cos(a0), r * std::sin(a0), 0);
        arc.to = point(r * std::cos(a0 + sweep), r * std::sin(a0 + sweep), n % 2 == 0 ? unit(random) : 0.0);
        const PathSegment g = make_arc(arc);
        const DerivativeBounds b = derivative_bounds(g);
        const double feed = std::pow(10.0, 0.5 + 2.5 * unit(random));
        for (ProfileKind kind : {ProfileKind::trapezoid, ProfileKind::scurve}) {
            for (double share : {0.5, trapezoid_blend_normal_share}) {
                const ProfileLimits l = segment_limits(g, m, feed, kind, share);
                ASSERT_GT(l.max_velocity, 0);
                ASSERT_GT(l.max_acceleration, 0);
                EXPECT_LE(l.max_velocity * b.speed_factor, feed * (1 + 1e-12));
                const double v = l.max_velocity;
                const double a = l.max_acceleration;
                for (const AxisConfig& axis : m.axes) {
                    const std::size_t i = index(axis.axis);
                    EXPECT_LE(b.d1[i] * v, axis.max_velocity * (1 + 1e-12));
                    EXPECT_LE(b.d2[i] * v * v + b.d1[i] * a, axis.max_acceleration * (1 + 1e-12)) << n;
                    if (kind == ProfileKind::scurve) {
                        const double j = l.max_jerk;
                        ASSERT_GT(j, 0);
                        EXPECT_LE(b.d3[i] * v * v * v + 3 * b.d2[i] * v * a + b.d1[i] * j, axis.max_jerk * (1 + 1e-12))
                            << n;
                    }
                }
                if (share != 0.5) continue;
                // Fixed shares: v from d2·v² <= amax/2 (and d3·v³ <= jmax/3), a <= amax/(2·d1),
                // the coupling 3·d2·v·a <= jmax/3, j <= jmax/(3·d1).
                double v_fixed = feed / b.speed_factor;
                double a_fixed = 1e300;
                double j_fixed = 1e300;
                for (const AxisConfig& axis : m.axes) {
                    const std::size_t i = index(axis.axis);
                    if (b.d1[i] > 0) v_fixed = std::min(v_fixed, axis.max_velocity / b.d1[i]);
                    if (b.d2[i] > 0) {
                        v_fixed = std::min(v_fixed, std::sqrt(0.5 * axis.max_acceleration / b.d2[i]));
                        if (kind == ProfileKind::scurve) {
                            v_fixed = std::min(v_fixed, std::cbrt(axis.max_jerk / (3 * b.d3[i])));
                        }
                    }
                }
                for (const AxisConfig& axis : m.axes) {
                    const std::size_t i = index(axis.axis);
                    if (b.d1[i] > 0) {
                        a_fixed = std::min(a_fixed, (b.d2[i] > 0 ? 0.5 : 1.0) * axis.max_acceleration / b.d1[i]);
                        j_fixed = std::min(j_fixed, (b.d2[i] > 0 ? 1.0 / 3 : 1.0) * axis.max_jerk / b.d1[i]);
                    }
                    if (kind == ProfileKind::scurve && b.d2[i] > 0) {
                        a_fixed = std::min(a_fixed, axis.max_jerk / (9 * b.d2[i] * v_fixed));
                    }
                }
                EXPECT_GE(v, v_fixed * (1 - 1e-12)) << n;
                EXPECT_GE(a, a_fixed * (1 - 1e-12)) << n;
                if (kind == ProfileKind::scurve) {
                    EXPECT_GE(l.max_jerk, j_fixed * (1 - 1e-12)) << n;
                }
            }
        }
    }
}

}  // namespace
}  // namespace nckit

namespace nckit {
namespace {

//! A quintic transition cut into pieces (S-curve transitions next to arcs are planned in
//! pieces): every piece is the same curve from its cut on, position and three derivatives.
TEST(PathSegment, TrimmedQuinticIsTheSameCurve) {
    std::mt19937_64 random(14);
    auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(random); };
    for (int trial = 0; trial < 20; ++trial) {
        PathPoint a;
        PathPoint b;
        for (std::size_t i = 0; i < 3; ++i) {
            a.position[i] = uniform(-5, 5);
            b.position[i] = a.position[i] + uniform(-2, 2);
            a.d1[i] = uniform(-1, 1);
            b.d1[i] = uniform(-1, 1);
            a.d2[i] = uniform(-0.5, 0.5);
            b.d2[i] = uniform(-0.5, 0.5);
        }
        const PathSegment curve = make_quintic(a, b, uniform(0.5, 3), AxisVector{});
        const double cut = uniform(0, curve.length);
        const PathSegment piece = trim_start(curve, cut);
        ASSERT_EQ(piece.shape, SegmentShape::quintic);
        EXPECT_NEAR(piece.length, curve.length - cut, 1e-12);
        for (int k = 0; k <= 10; ++k) {
            const double s = piece.length * k / 10;
            const PathPoint want = point_at(curve, cut + s);
            const PathPoint got = point_at(piece, s);
            for (std::size_t i = 0; i < 3; ++i) {
                EXPECT_NEAR(got.position[i], want.position[i], 1e-9) << "trial " << trial;
                EXPECT_NEAR(got.d1[i], want.d1[i], 1e-9) << "trial " << trial;
                EXPECT_NEAR(got.d2[i], want.d2[i], 1e-8) << "trial " << trial;
                EXPECT_NEAR(got.d3[i], want.d3[i], 1e-7) << "trial " << trial;
            }
        }
    }
}

}  // namespace
}  // namespace nckit
