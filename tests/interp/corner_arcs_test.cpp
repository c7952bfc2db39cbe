// ,R and ,C corners where an arc takes part: on a G2/G3 block (the corner at the arc's end) and
// before one. What is checked is what makes a corner right: the fillet is r from both moves'
// lines or circles, starts where the first move now ends and ends where the next now starts;
// a chamfer's ends are c from the corner and on both moves.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "interp_support.hpp"

namespace nckit::test {
namespace {

double dist(const AxisVector& a, double x, double y) {
    return std::hypot(a[Axis::X] - x, a[Axis::Y] - y);
}

TEST(CornerArcs, RoundingAfterAnArcIsTangentToBoth) {
    // G3 from (0,0) about (0,10), R10, to (10,10), heading +Y; then left along Y10: a left turn
    // toward the arc's centre, so the fillet's centre is 10 - 2 from it and 2 below Y10.
    const std::vector<Move> moves = moves_of("G0 X0 Y0\nG3 X10 Y10 I0 J10 F100 ,R2\nG1 X0\n");
    const auto arcs = only<Arc>(moves);
    const auto lines = only<Line>(moves);
    ASSERT_EQ(arcs.size(), 2U);
    const Arc& first = arcs[0];
    const Arc& fillet = arcs[1];
    EXPECT_NEAR(fillet.center[Axis::Y], 8.0, 1e-9);
    EXPECT_NEAR(dist(fillet.center, 0, 10), 8.0, 1e-9);
    EXPECT_EQ(first.to, fillet.from);
    EXPECT_NEAR(dist(first.to, 0, 10), 10.0, 1e-9);  // still on the programmed circle
    EXPECT_EQ(fillet.direction, ArcDirection::counterclockwise);
    ASSERT_EQ(lines.size(), 2U);
    EXPECT_EQ(lines[1].from, fillet.to);
    EXPECT_NEAR(lines[1].from[Axis::X], std::sqrt(64.0 - 4.0), 1e-9);
    EXPECT_NEAR(lines[1].from[Axis::Y], 10.0, 1e-12);
    EXPECT_NEAR(dist(fillet.from, fillet.center[Axis::X], fillet.center[Axis::Y]), 2.0, 1e-9);
}

TEST(CornerArcs, RoundingBetweenTwoArcs) {
    // Two G2 arcs of R10 meeting at (10,0) at a cusp-free corner: about (0,0) from (0,10), then
    // about (20,0)... turning right from heading -Y into heading +Y is straight back; use a
    // second centre off the axis instead: about (10,-10) from (10,0), heading +X, a left turn.
    const std::vector<Move> moves = moves_of("G0 X0 Y10\nG2 X10 Y0 I0 J-10 F100 ,R1\nG2 X20 Y-10 I0 J-10\n");
    const auto arcs = only<Arc>(moves);
    ASSERT_EQ(arcs.size(), 3U);
    const Arc& fillet = arcs[1];
    // Left turn: the left of a clockwise arc is outside it, so the centre is R + r from both.
    EXPECT_NEAR(dist(fillet.center, 0, 0), 11.0, 1e-9);
    EXPECT_NEAR(dist(fillet.center, 10, -10), 11.0, 1e-9);
    EXPECT_EQ(arcs[0].to, fillet.from);
    EXPECT_EQ(fillet.to, arcs[2].from);
    EXPECT_NEAR(dist(arcs[0].to, 0, 0), 10.0, 1e-9);
    EXPECT_NEAR(dist(arcs[2].from, 10, -10), 10.0, 1e-9);
    EXPECT_EQ(fillet.direction, ArcDirection::counterclockwise);
}

TEST(CornerArcs, ChamferBeforeAnArcEndsAChordFromTheCorner) {
    const std::vector<Move> moves = moves_of("G0 X0 Y10\nG1 X-10 F100 ,C2\nG3 X-20 Y20 I-10 J0\n");
    const auto lines = only<Line>(moves);
    const auto arcs = only<Arc>(moves);
    ASSERT_EQ(lines.size(), 3U);  // the rapid, the shortened line, the chamfer
    ASSERT_EQ(arcs.size(), 1U);
    EXPECT_NEAR(lines[1].to[Axis::X], -8.0, 1e-12);
    EXPECT_EQ(lines[2].from, lines[1].to);
    EXPECT_EQ(lines[2].to, arcs[0].from);
    EXPECT_NEAR(dist(arcs[0].from, -10, 10), 2.0, 1e-9);   // c from the corner
    EXPECT_NEAR(dist(arcs[0].from, -20, 10), 10.0, 1e-9);  // on the arc
    EXPECT_GT(arcs[0].from[Axis::Y], 10.0);                // after the corner, not before it
}

TEST(CornerArcs, ChamferOnAnArcBlock) {
    const std::vector<Move> moves = moves_of("G0 X0 Y0\nG3 X10 Y10 I0 J10 F100 ,C1\nG1 X0\n");
    const auto arcs = only<Arc>(moves);
    const auto lines = only<Line>(moves);
    ASSERT_EQ(arcs.size(), 1U);
    ASSERT_EQ(lines.size(), 3U);
    EXPECT_NEAR(dist(arcs[0].to, 10, 10), 1.0, 1e-9);
    EXPECT_NEAR(dist(arcs[0].to, 0, 10), 10.0, 1e-9);
    EXPECT_LT(arcs[0].to[Axis::Y], 10.0);
    EXPECT_EQ(lines[1].from, arcs[0].to);
    EXPECT_NEAR(lines[1].to[Axis::X], 9.0, 1e-12);
    EXPECT_EQ(lines[2].from, lines[1].to);
}

TEST(CornerArcs, Errors) {
    // ,R not smaller than the arc's radius where the fillet sits inside it.
    EXPECT_EQ(error_where("G0 X0 Y0\nG3 X10 Y10 I0 J10 F100 ,R10\nG1 X0\n"), "bad-corner 2:24");
    // A chord longer than the arc's diameter.
    EXPECT_EQ(error_where("G0 X0 Y10\nG1 X-10 F100 ,C2\nG3 X-10.5 Y10 I-0.25 J0\n"), "bad-corner 2:14");
    // A helix takes no corner.
    EXPECT_EQ(error_where("G0 X0 Y0\nG3 X10 Y10 Z-1 I0 J10 F100 ,R2\nG1 X0\n"), "bad-corner 2:28");
    // The arc leaves the line tangentially: no corner.
    EXPECT_EQ(error_where("G0 X0 Y0\nG1 X10 F100 ,R1\nG3 X20 Y10 I0 J10\n"), "bad-corner 2:13");
    // G0 with a corner word.
    EXPECT_EQ(error_where("G0 X10 ,R2\nY10\n"), "bad-corner 1:8");
}

}  // namespace
}  // namespace nckit::test
