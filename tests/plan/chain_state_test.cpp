// The state where two chained transitions meet at the middle of a CAM line
// (src/plan/chain_state.hpp): the quintics between such states follow the curve the chords
// sample, with the curve's third derivative, not five times it.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "../../src/plan/chain_state.hpp"
#include "nckit/plan/path_segment.hpp"

namespace nckit {
namespace {

using plan_detail::chain_mid_state;
using Vec3 = std::array<double, 3>;

struct Chord {
    Vec3 middle{};
    Vec3 direction{};
    double length = 0;
};

//! Chords between consecutive points.
std::vector<Chord> chords(const std::vector<Vec3>& points) {
    std::vector<Chord> out;
    for (std::size_t k = 0; k + 1 < points.size(); ++k) {
        Chord c;
        Vec3 d{};
        for (std::size_t i = 0; i < 3; ++i) {
            c.middle[i] = 0.5 * (points[k][i] + points[k + 1][i]);
            d[i] = points[k + 1][i] - points[k][i];
        }
        c.length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        for (std::size_t i = 0; i < 3; ++i) c.direction[i] = d[i] / c.length;
        out.push_back(c);
    }
    return out;
}

//! The state at chord k's middle, its neighbours' middles spaced as the planner sees them.
plan_detail::ChainMidState state_at(const std::vector<Chord>& c, std::size_t k) {
    const double before_mm = 0.5 * (c[k - 1].length + c[k].length);
    const double after_mm = 0.5 * (c[k].length + c[k + 1].length);
    return chain_mid_state(c[k - 1].direction, before_mm, c[k].direction, c[k].length, c[k + 1].direction, after_mm);
}

double dot(const Vec3& a, const Vec3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

//! Largest |q'''| on Z of the quintic between the states at chords k and k + 1.
double quintic_d3_z(const std::vector<Chord>& c, std::size_t k, bool corrected) {
    PathPoint a;
    PathPoint b;
    const auto sa = state_at(c, k);
    const auto sb = state_at(c, k + 1);
    for (std::size_t i = 0; i < 3; ++i) {
        a.position[i] = c[k].middle[i] + (corrected ? sa.offset[i] : 0.0);
        b.position[i] = c[k + 1].middle[i] + (corrected ? sb.offset[i] : 0.0);
        a.d1[i] = corrected ? sa.d1[i] : c[k].direction[i];
        b.d1[i] = corrected ? sb.d1[i] : c[k + 1].direction[i];
        a.d2[i] = sa.d2[i];
        b.d2[i] = sb.d2[i];
    }
    double chord = 0;
    for (std::size_t i = 0; i < 3; ++i) chord += (b.position[i] - a.position[i]) * (b.position[i] - a.position[i]);
    const PathSegment q = make_quintic(a, b, std::sqrt(chord), AxisVector{});
    return derivative_bounds(q).d3[2];
}

TEST(ChainState, StraightChainKeepsItsDirectionAndNoCurvature) {
    std::vector<Vec3> points;
    for (int k = 0; k < 5; ++k) points.push_back({0.5 * k, 0.25 * k, -0.1 * k});
    const auto c = chords(points);
    const auto s = state_at(c, 2);
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_NEAR(s.d1[i], c[2].direction[i], 1e-14);
        EXPECT_NEAR(s.d2[i], 0.0, 1e-14);
        EXPECT_NEAR(s.offset[i], 0.0, 1e-14);
    }
}

TEST(ChainState, CircleOfEqualChordsKeepsTheChordDirection) {
    // A circle's third derivative lies along its tangent: the direction does not turn.
    const double r = 20;
    std::vector<Vec3> points;
    for (int k = 0; k < 6; ++k) {
        const double angle = 0.003 * k;
        points.push_back({r * std::sin(angle), r - r * std::cos(angle), 0});
    }
    const auto c = chords(points);
    const auto s = state_at(c, 2);
    for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(s.d1[i], c[2].direction[i], 1e-12);
    EXPECT_NEAR(std::hypot(s.d2[0], s.d2[1]), 1 / r, 1e-6);
    // The middle, 22 nm inside the circle (h²/(8r)), moves out onto it to within 0.1 nm.
    Vec3 on{};
    for (std::size_t i = 0; i < 3; ++i) on[i] = c[2].middle[i] + s.offset[i];
    EXPECT_NEAR(std::hypot(on[0], on[1] - r), r, 1e-10);
    EXPECT_GT(r - std::hypot(c[2].middle[0], c[2].middle[1] - r), 2e-5);
    EXPECT_NEAR(dot(s.d1, s.d2), 0.0, 1e-15);
}

TEST(ChainState, AZigZagKeepsItsMiddlesAndDirections) {
    // A zig-zag (chords at ±0.1 rad, turning 0.2 rad each way) samples no smooth curve: the meeting
    // point stays the middle, in the line's direction (moving it only fails tolerance checks).
    std::vector<Vec3> points;
    for (int k = 0; k < 6; ++k) points.push_back({0.05 * k, 0.005 * (k % 2), 0});
    const auto c = chords(points);
    const auto s = state_at(c, 2);
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(s.d1[i], c[2].direction[i]);
        EXPECT_EQ(s.offset[i], 0.0);
    }
}

TEST(ChainState, CurvatureIsNormalToTheDirection) {
    // Unequal lines on a curve whose curvature changes: the curvature vector loses its part
    // along the direction (|q'| stays 1 where two quintics meet).
    std::vector<Vec3> points;
    double x = 0;
    for (int k = 0; k < 6; ++k) {
        points.push_back({x, 0.3 * std::sin(x), 0.01 * x * x * x});
        x += 0.3 + 0.1 * (k % 3);
    }
    const auto c = chords(points);
    for (std::size_t k = 1; k + 1 < c.size(); ++k) {
        const auto s = state_at(c, k);
        EXPECT_NEAR(dot(s.d1, s.d1), 1.0, 1e-14);
        EXPECT_NEAR(dot(s.d1, s.d2), 0.0, 1e-14);
    }
}

TEST(ChainState, QuinticsFollowTheThirdDerivativeOfTheSampledCurve) {
    // The rows of the 3D raster: 0.5 mm chords of z = 2 sin(x/8), whose third derivative is at
    // most 2/512 = 0.0039 /mm². With the chords' own middles and directions the quintics between
    // them reached about five times that (h²·g'''/12 off at both ends); with the points and
    // directions of chain_mid_state they stay within 1.5 times it.
    const double g3 = 2.0 / 512.0;
    std::vector<Vec3> points;
    for (int k = 0; k <= 100; ++k) {
        const double xk = 0.5 * k;
        points.push_back({xk, 0, 2 * std::sin(xk / 8)});
    }
    const auto c = chords(points);
    double worst_chord = 0;
    double worst_state = 0;
    for (std::size_t k = 1; k + 2 < c.size(); ++k) {
        worst_chord = std::max(worst_chord, quintic_d3_z(c, k, false));
        worst_state = std::max(worst_state, quintic_d3_z(c, k, true));
    }
    EXPECT_GT(worst_chord, 4 * g3);
    EXPECT_LT(worst_state, 1.5 * g3);
}

}  // namespace
}  // namespace nckit
