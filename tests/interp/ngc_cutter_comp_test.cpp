// LinuxCNC's cutter compensation corners in the LinuxCNC dialect: the point it takes in an
// inside corner, its gouge checks, and an inside arc of the tool's own radius. The expected
// numbers are what LinuxCNC 2.9's `rs274 -g` prints for the same programs (4 decimals), so the
// comparisons allow half a unit of its last digit (inch programs: 0.00005 in).
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "interp_support.hpp"

namespace nckit::test {
namespace {

//! One motion as rs274 prints it: kind, end point and (arcs) centre in the plane, direction.
struct Expected {
    bool arc = false;
    double x = 0;
    double y = 0;
    double cx = 0;  //!< arcs only
    double cy = 0;
    int turn = 0;  //!< arcs: 1 counter-clockwise, -1 clockwise
};

Expected line_to(double x, double y) {
    return {false, x, y, 0, 0, 0};
}

Expected arc_to(double x, double y, double cx, double cy, int turn) {
    return {true, x, y, cx, cy, turn};
}

//! The moves' ends and centres against rs274's, in program units of `unit_mm` mm.
void expect_moves(const std::vector<Move>& all, const std::vector<Expected>& expected, double unit_mm) {
    const double tolerance = 0.00005 * unit_mm + 1e-9;
    std::vector<Move> moves;
    for (const Move& m : all) {
        if (std::holds_alternative<Line>(m.what) || std::holds_alternative<Arc>(m.what)) moves.push_back(m);
    }
    ASSERT_EQ(moves.size(), expected.size());
    for (std::size_t i = 0; i < moves.size(); ++i) {
        SCOPED_TRACE("move " + std::to_string(i + 1));
        const Expected& e = expected[i];
        if (const auto* arc = std::get_if<Arc>(&moves[i].what)) {
            ASSERT_TRUE(e.arc) << "an arc where rs274 has a line";
            EXPECT_NEAR(arc->to[Axis::X], e.x * unit_mm, tolerance);
            EXPECT_NEAR(arc->to[Axis::Y], e.y * unit_mm, tolerance);
            EXPECT_NEAR(arc->center[Axis::X], e.cx * unit_mm, tolerance);
            EXPECT_NEAR(arc->center[Axis::Y], e.cy * unit_mm, tolerance);
            EXPECT_EQ(arc->direction == ArcDirection::counterclockwise ? 1 : -1, e.turn);
            continue;
        }
        const auto* line = std::get_if<Line>(&moves[i].what);
        ASSERT_NE(line, nullptr);
        ASSERT_FALSE(e.arc) << "a line where rs274 has an arc";
        EXPECT_NEAR(line->to[Axis::X], e.x * unit_mm, tolerance);
        EXPECT_NEAR(line->to[Axis::Y], e.y * unit_mm, tolerance);
    }
}

TEST(NgcCutterComp, ArcToLineInsideCornerTakesLinuxCncsCrossing) {
    // From LinuxCNC's crazy-paths test (radius 0.25 on the right): the small G2 arc is cut from
    // inside, and the line after it turns into it. LinuxCNC moves the arc's end back along its
    // offset circle to (-39.7593, -104.1844), its crossing with the line's offset, chosen by the
    // arc's direction; the other crossing lies 0.4 mm from it.
    const auto moves = moves_of(
        "G21 G17 G90 F100\nG0 X-50 Y-100\nG41.1 D-0.5\nG1 Y-102\n"
        "G2 I4.980439 J-0.441843 X-40.097651 Y-103.322073\nG2 I-0.682919 J-1.106175 X-39.500873 Y-104.657107\n"
        "G1 X-54.500873 Y-94.657107\nG2 I-1.575966 J-2.552711 X-57.872219 Y-99.613276\nG40\n"
        "G1 X-62.872219 Y-114.613276\nM2\n",
        linuxcnc_mill());
    expect_moves(
        moves,
        {line_to(-50.0, -100.0), line_to(-50.25, -102.0), arc_to(-49.7510, -102.0221, -50.0, -102.0, 1),
         arc_to(-40.3437, -103.2781, -45.0196, -102.4418, -1), arc_to(-40.2290, -103.5348, -40.0977, -103.3221, 1),
         arc_to(-39.7593, -104.1844, -40.7806, -104.4282, -1), line_to(-54.3622, -94.4491),
         arc_to(-54.6322, -94.8698, -54.5009, -94.6571, 1), arc_to(-57.7226, -99.4130, -56.0768, -97.2098, -1),
         line_to(-62.8722, -114.6133)},
        1.0);
}

TEST(NgcCutterComp, ArcToArcInsideCornerReadsTheRadiiAtTheArcsEnds) {
    // From LinuxCNC's inside-corners test (G20, radius 0.075 in on the left): the G2 of line 8
    // has radius 0.6093 in at its start and 0.609384 at its end. LinuxCNC crosses its offset
    // circle taken at the end radius with the G3's taken at that arc's compensated end:
    // (1.2235, 1.0250) in; from the start radius the crossing would round to (1.2235, 1.0252).
    const auto moves = moves_of(
        "G20 G17 G90 G94\nF8\nG0 X0 Y0\nG41.1 D0.15\nG1 X0.6767 Y0.2334\nG1 X0.3359 Y0.4419\n"
        "G3 X1.2281 Y1.3456 I0.2921 J0.6039\nG2 X0.1253 Y0.9881 I-0.6093 J0.0000\n"
        "G3 X0.7669 Y1.4548 I0.2437 J0.3394\nG40\nG1 X1 Y0\nM2\n",
        linuxcnc_mill());
    expect_moves(
        moves,
        {line_to(0, 0), line_to(0.5019, 0.2524), line_to(0.2968, 0.3779), arc_to(0.3686, 0.5094, 0.3359, 0.4419, -1),
         arc_to(1.2235, 1.0250, 0.6280, 1.0458, 1), arc_to(0.0646, 0.9441, 0.6188, 1.3456, -1),
         arc_to(0.1690, 1.0490, 0.1253, 0.9881, -1), arc_to(0.6955, 1.4319, 0.3690, 1.3275, 1), line_to(1, 0)},
        25.4);
}

TEST(NgcCutterComp, ArcOfTheToolsRadiusFromInsideIsAnArcOfRadiusZero) {
    // LinuxCNC's useful-subroutines hole: a 1/8 in tool (T1) in a hole of 1/8 in. The tool stays
    // on the hole's centre; rs274 prints each helix as an arc of radius 0 about it going down
    // in Z (ARC_FEED(0, 0, 0, 0, 1, -0.05)).
    MachineConfig machine = linuxcnc_mill();
    ToolEntry tool;
    tool.number = 1;
    tool.radius_mm = 0.0625 * 25.4;
    machine.tools.insert(tool);
    const std::string program =
        "G20 G17 G90\nF60\nT1 M6\nG0 X0.0625 Y0.0625 Z0.01\nG41 D1 G0 X0 Y0.0625\n"
        "G3 X0 Y0.0625 I0 J-0.0625 Z-0.05\nG3 X0 Y0.0625 I0 J-0.0625\nG0 Z0.01\nG40\nG0 X0.1\nM2\n";
    const auto moves = moves_of(program, machine);
    const auto arcs = only<Arc>(moves);
    ASSERT_EQ(arcs.size(), 2u);
    for (const Arc& arc : arcs) {
        EXPECT_EQ(arc.direction, ArcDirection::counterclockwise);
        EXPECT_NEAR(arc.to[Axis::X], 0.0, 1e-9);
        EXPECT_NEAR(arc.to[Axis::Y], 0.0, 1e-9);
        // Radius exactly 0: the centre is the tool's point, at both ends.
        EXPECT_EQ(arc.center[Axis::X], arc.from[Axis::X]);
        EXPECT_EQ(arc.center[Axis::Y], arc.from[Axis::Y]);
        EXPECT_EQ(arc.to[Axis::X], arc.from[Axis::X]);
        EXPECT_EQ(arc.to[Axis::Y], arc.from[Axis::Y]);
    }
    EXPECT_NEAR(arcs[0].from[Axis::Z], 0.01 * 25.4, 1e-9);
    EXPECT_NEAR(arcs[0].to[Axis::Z], -0.05 * 25.4, 1e-9);
    // (The planner takes such an arc as the straight line it is in space: tests/plan.)
    // The Fanuc dialect keeps its own reading: the arc becomes that straight move (its start-up
    // must be longer than the radius there).
    MachineConfig fanuc = machine;
    fanuc.dialect = Dialect::fanuc;
    std::string longer = program;
    longer.replace(longer.find("X0.0625 Y0.0625 Z0.01"), 6, "X0.125");
    EXPECT_TRUE(only<Arc>(moves_of(longer, fanuc)).empty());
}

TEST(NgcCutterComp, LineTooShortForAnInsideCornerIsAGougeAtTheBlockThatSettlesIt) {
    // rs274: "Straight feed in concave corner cannot be reached by the tool without gouging" at
    // line 7, after the line of line 6 (0.5 mm, radius 2) would have to run backwards.
    const Diagnostic d = error_of(
        "G21 G17 G90 F100\nG0 X0 Y-10\nG41.1 D4\nG1 X0 Y0\nG1 X10 Y0\nG1 X10 Y0.5\nG1 X0 Y0.5\nG40 G1 X0 Y-10\nM2\n",
        linuxcnc_mill());
    EXPECT_EQ(d.location.line, 7u);
    EXPECT_EQ(d.code, "cutter-gouge");
}

TEST(NgcCutterComp, ToolChangeAfterG40LeavesTheToolBesideTheContour) {
    // LinuxCNC reads the position back from the machine after M6: the move after G40 then starts
    // where the tool stands, r beside the contour, and keeps its Y (rs274: Z5 to (10, 2, 5), X20
    // to (20, 2, 5)); without the tool change it returns to the programmed Y 0.
    MachineConfig machine = linuxcnc_mill();
    ToolEntry tool;
    tool.number = 1;
    tool.radius_mm = 1.5875;
    machine.tools.insert(tool);
    const std::string with_m6 =
        "G21 G17 G90\nF100\nG0 X0 Y-10\nG41.1 D4\nG1 X0 Y0\nG1 X10 Y0\nG40\nT1 M6\nG0 Z5\nG0 X20\nM2\n";
    expect_moves(
        moves_of(with_m6, machine),
        {line_to(0, -10), line_to(-2, 0), arc_to(0, 2, 0, 0, -1), line_to(10, 2), line_to(10, 2), line_to(20, 2)}, 1.0);
    std::string without = with_m6;
    without.erase(without.find("T1 M6\n"), 6);
    expect_moves(
        moves_of(without, machine),
        {line_to(0, -10), line_to(-2, 0), arc_to(0, 2, 0, 0, -1), line_to(10, 2), line_to(10, 0), line_to(20, 0)}, 1.0);
}

}  // namespace
}  // namespace nckit::test
