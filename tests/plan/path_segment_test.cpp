// Path segments: exact derivatives against finite differences, arc and helix geometry, blends.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "../../src/plan/junction.hpp"
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
            const double sweep = dir == ArcDirection::counterclockwise ? 0.5 * std::numbers::pi : 1.5 * std::numbers::pi;
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

}  // namespace
}  // namespace nckit
