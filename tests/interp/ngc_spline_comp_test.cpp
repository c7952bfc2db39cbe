// LinuxCNC's splines (G5, G5.1, G5.2/G5.3 as its biarcs), its cutter compensation start-up rules,
// its probe parameters and its exact LE/GE, seen from the moves. (tests/real_linuxcnc compares
// the compensation, probe and comparison rules with rs274 on LinuxCNC's own programs; rs274 2.9
// prints only the count of a spline's control points, so the splines are checked here against the
// curve itself.)
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "interp_support.hpp"

namespace nckit::test {
namespace {

struct Point {
    double x = 0;
    double y = 0;
};

Point xy_of(const AxisVector& v) {
    return {v[Axis::X], v[Axis::Y]};
}

//! Unit direction of travel of an arc at its start (at_end = false) or end.
Point arc_direction(const Arc& a, bool at_end) {
    const AxisVector& p = at_end ? a.to : a.from;
    const double rx = p[Axis::X] - a.center[Axis::X];
    const double ry = p[Axis::Y] - a.center[Axis::Y];
    const double r = std::hypot(rx, ry);
    const double s = a.direction == ArcDirection::counterclockwise ? 1.0 : -1.0;
    return {-s * ry / r, s * rx / r};
}

TEST(NgcSpline, QuadraticBiarcsMeetTheCurveAndJoinSmoothly) {
    // G5.1 from (0,0), control point (5,5), to (10,0): the quadratic Bezier B(u) = 2u(1-u)(5,5) +
    // u^2 (10,0). LinuxCNC cuts it into 3 x 4 = 12 steps, a biarc each: 24 arcs; the end of every
    // second arc is B(i/12), e.g. B(1/12) = (0.8333, 0.7639), B(1/2) = (5, 2.5).
    const auto arcs = only<Arc>(moves_of("G21 G17 G90 F100\nG0 X0 Y0\nG5.1 X10 Y0 I5 J5\nM2\n", linuxcnc_mill()));
    ASSERT_EQ(arcs.size(), 24u);
    for (std::size_t i = 1; i <= 12; ++i) {
        const double u = static_cast<double>(i) / 12.0;
        const Point end = xy_of(arcs[2 * i - 1].to);
        EXPECT_NEAR(end.x, 2 * u * (1 - u) * 5 + u * u * 10, 1e-9) << "step " << i;
        EXPECT_NEAR(end.y, 2 * u * (1 - u) * 5, 1e-9) << "step " << i;
    }
    EXPECT_DOUBLE_EQ(arcs.back().to[Axis::X], 10.0);
    // Property: every arc starts where the one before ends, in the same direction (within the
    // central-difference tangent's 1e-5 step).
    for (std::size_t k = 1; k < arcs.size(); ++k) {
        EXPECT_EQ(arcs[k].from, arcs[k - 1].to);
        const Point a = arc_direction(arcs[k - 1], true);
        const Point b = arc_direction(arcs[k], false);
        EXPECT_NEAR(a.x * b.x + a.y * b.y, 1.0, 1e-6) << "joint " << k;
    }
    // The radius of each arc is the same at both ends.
    for (const Arc& a : arcs) {
        EXPECT_NEAR(std::hypot(a.from[Axis::X] - a.center[Axis::X], a.from[Axis::Y] - a.center[Axis::Y]),
                    std::hypot(a.to[Axis::X] - a.center[Axis::X], a.to[Axis::Y] - a.center[Axis::Y]), 1e-9);
    }
}

TEST(NgcSpline, CubicGoesOnAlongItsLastEndAndIsNotModal) {
    // G5 with 4 control points: 16 steps, 32 arcs. The second G5 has no I J: they are the first
    // one's -P -Q, so the curve has no corner at X10 Y0. G5 is not modal in LinuxCNC: the bare
    // X30 after it is a G1 (the mode of before), and P Q on such a block are an error there.
    const auto moves = moves_of("G21 G17 G90 F100\nG0 X0 Y0\nG1 X0\nG5 X10 Y0 I0 J4 P0 Q-4\nG5 X20 Y0 P0 Q4\nX30\nM2\n",
                                linuxcnc_mill());
    const auto arcs = only<Arc>(moves);
    ASSERT_EQ(arcs.size(), 64u);
    EXPECT_NEAR(arcs[31].to[Axis::X], 10.0, 1e-9);
    EXPECT_NEAR(arcs[63].to[Axis::X], 20.0, 1e-9);
    const Point out = arc_direction(arcs[31], true);
    const Point in = arc_direction(arcs[32], false);
    EXPECT_NEAR(out.x * in.x + out.y * in.y, 1.0, 1e-6);
    EXPECT_NEAR(out.y, 1.0, 1e-3);  // up through (10,0): from the control point (10,-4) to (10,4)
    const auto lines = only<Line>(moves);
    ASSERT_FALSE(lines.empty());
    EXPECT_FALSE(lines.back().rapid);
    EXPECT_NEAR(lines.back().to[Axis::X], 30.0, 1e-12);
    EXPECT_NEAR(lines.back().from[Axis::X], 20.0, 1e-9);
    EXPECT_EQ(
        error_of("G21 G17 F100\nG1 X0\nG5 X10 Y0 I0 J4 P0 Q-4\nX20 Y0 P0 Q4\nM2\n", linuxcnc_mill()).location.line, 4u);
}

TEST(NgcSpline, NurbsEndsOnItsLastPointAndStaysInItsPlane) {
    // The same curve in G17 (X Y) and G19 (Y Z): the same arcs with the axes renamed, Z (G17) or
    // X (G19) left where it is.
    const std::string points_xy = "G5.2 P1 L3\nX0 Y1 P1\nX2 Y2 P1\nX2 Y0 P1\nX0 Y0 P2\nG5.3\nM2\n";
    const std::string points_yz = "G5.2 P1 L3\nY0 Z1 P1\nY2 Z2 P1\nY2 Z0 P1\nY0 Z0 P2\nG5.3\nM2\n";
    const auto xy = only<Arc>(moves_of("G21 G17 G90 F100\nG0 X0 Y0 Z3\n" + points_xy, linuxcnc_mill()));
    const auto yz = only<Arc>(moves_of("G21 G19 G90 F100\nG0 X3 Y0 Z0\n" + points_yz, linuxcnc_mill()));
    ASSERT_EQ(xy.size(), 40u);  // 5 points: 20 steps, 2 arcs each
    ASSERT_EQ(yz.size(), xy.size());
    for (std::size_t i = 0; i < xy.size(); ++i) {
        EXPECT_NEAR(yz[i].to[Axis::Y], xy[i].to[Axis::X], 1e-12);
        EXPECT_NEAR(yz[i].to[Axis::Z], xy[i].to[Axis::Y], 1e-12);
        EXPECT_NEAR(yz[i].to[Axis::X], 3.0, 1e-12);
        EXPECT_NEAR(xy[i].to[Axis::Z], 3.0, 1e-12);
        EXPECT_EQ(yz[i].plane, Plane::yz);
    }
    EXPECT_NEAR(xy.back().to[Axis::X], 0.0, 1e-9);
    EXPECT_NEAR(xy.back().to[Axis::Y], 0.0, 1e-9);
}

TEST(NgcSpline, ErrorsAsLinuxCnc) {
    EXPECT_EQ(error_of("G17 F100\nG5.1 X1 Y1 I1\nM2\n", linuxcnc_mill()).message,
              "must specify both I and J with G5.1");
    EXPECT_EQ(error_of("G17 F100\nG5 X1 Y1 I1 J1\nM2\n", linuxcnc_mill()).message, "must specify both P and Q with G5");
    EXPECT_EQ(error_of("G18 F100\nG5.1 X1 Z1 I1 J1\nM2\n", linuxcnc_mill()).message, "splines must be in the XY plane");
    EXPECT_EQ(error_of("G17 F100\nG5.1 X1 Y1 Z1 I1 J1\nM2\n", linuxcnc_mill()).message,
              "splines may not have motion in Z, A, B, or C");
    EXPECT_EQ(error_of("G17 F100\nG5.3\nM2\n", linuxcnc_mill()).message, "cannot use G5.3 without G5.2 first");
    EXPECT_EQ(error_of("G17\nG5.2 P1\nX1 Y1 P1\nM2\n", linuxcnc_mill()).message, "cannot make a NURBS with 0 feedrate");
    EXPECT_EQ(error_of("G17 F100\nG5.2 P1 L4\nX1 Y1 P1\nX2 Y0 P1\nG5.3\nM2\n", linuxcnc_mill()).message,
              "you must specify a number of control points at least equal to the order L = 4");
    EXPECT_EQ(error_of("G17 F100\nG5.2 P1\nX1 Y1\nG5.3\nM2\n", linuxcnc_mill()).message,
              "must specify positive weight P for every control point");
    EXPECT_EQ(error_of("G17 F100\nG5.2 P1\nX1 P1\nG5.3\nM2\n", linuxcnc_mill()).message,
              "you must specify both X and Y coordinates for control points");
    const Diagnostic comp = error_of("G17 F100\nG0 X-5 Y0\nG41.1 D2 G1 X0\nG5.1 X10 Y0 I5 J5\nM2\n", linuxcnc_mill());
    EXPECT_EQ(comp.location.line, 4u);
    EXPECT_EQ(comp.message, "cannot convert spline with cutter radius compensation");
}

TEST(NgcCutterComp, StartUpMoveOneRadiusLongRuns) {
    // LinuxCNC refuses a start-up move *shorter* than the radius only (rs274 runs one exactly r
    // long): radius 1, a start-up of 1 runs and one of 0.999 does not.
    const auto moves =
        moves_of("G21 G17 G90 F100\nG0 X1 Y0\nG41.1 D2 G1 X0 Y0\nG1 X0 Y-5\nG40 G0 X-5\nM2\n", linuxcnc_mill());
    EXPECT_FALSE(moves.empty());
    const Diagnostic shorter =
        error_of("G21 G17 G90 F100\nG0 X0.999 Y0\nG41.1 D2 G1 X0 Y0\nG1 X0 Y-5\nM2\n", linuxcnc_mill());
    EXPECT_EQ(shorter.location.line, 3u);
    // A plunge as the first move after G41 is LinuxCNC's start-up move too: of no length there.
    const Diagnostic plunge = error_of("G21 G17 G90 F100\nG0 X5 Y0\nG41.1 D2\nG1 Z-1\nG1 X0\nM2\n", linuxcnc_mill());
    EXPECT_EQ(plunge.location.line, 4u);
}

TEST(NgcCutterComp, StartUpOnAnArcEndsOneRadiusInsideAboutANewCentre) {
    // From (50,50) G41 G3 to (70,50) about (60,50), radius 1: the tool is inside the arc, so the
    // arc ends at (69,50); its centre lies on y = 50, as far from (50,50) as from (69,50): x 59.5.
    // Then the full circle about (50,50) runs r inside it, at radius 19.
    const auto arcs = only<Arc>(moves_of(
        "G21 G17 G90 F100\nG0 X50 Y50\nG41.1 D2\nG3 X70 Y50 I10 J0\nG3 I-20\nG40 G0 X0 Y0\nM2\n", linuxcnc_mill()));
    ASSERT_GE(arcs.size(), 2u);
    EXPECT_NEAR(arcs[0].from[Axis::X], 50.0, 1e-12);
    EXPECT_NEAR(arcs[0].to[Axis::X], 69.0, 1e-9);
    EXPECT_NEAR(arcs[0].to[Axis::Y], 50.0, 1e-9);
    EXPECT_NEAR(arcs[0].center[Axis::X], 59.5, 1e-9);
    EXPECT_NEAR(arcs[0].center[Axis::Y], 50.0, 1e-9);
    EXPECT_EQ(arcs[0].direction, ArcDirection::counterclockwise);
    EXPECT_NEAR(arcs[1].center[Axis::X], 50.0, 1e-9);
    EXPECT_NEAR(std::hypot(arcs[1].from[Axis::X] - 50.0, arcs[1].from[Axis::Y] - 50.0), 19.0, 1e-9);
}

TEST(NgcProbe, ResultParametersArePlainAndBackOffIsFromTheInterpretersStart) {
    // rs274 backs off 0.01 in from a G38.3 X-1 (to ); the next G38.2 Z-0.1 runs from
    // there, backs off straight up in Z, and the G38.5 after it stays at X-0.99 (no X drift).
    // #5070 = 1 set by the program is read back as 1 until the next probe sets 0.
    const auto lines =
        only<Line>(moves_of("G20\nF20\nG0 X0 Y-1 Z1.1\nG38.3 X-1\nG38.2 Z-0.1\nG38.5 Z1.1\n#5070 = 1\no1 if [#5070 EQ "
                            "1]\nG0 X2\no1 endif\nM2\n",
                            linuxcnc_mill()));
    ASSERT_GE(lines.size(), 5u);
    const Line& up = lines[lines.size() - 2];
    EXPECT_NEAR(up.to[Axis::X], -0.99 * 25.4, 1e-9);
    EXPECT_NEAR(up.to[Axis::Z], 1.1 * 25.4, 1e-9);
    EXPECT_NEAR(lines.back().to[Axis::X], 2 * 25.4, 1e-9);
}

TEST(NgcExpressions, LeAndGeCompareExactlyAsLinuxCnc29) {
    // 0.1 + 0.2 is 0.30000000000000004 in doubles: not LE 0.3 in LinuxCNC 2.9, while EQ (within
    // 1e-6) calls them equal.
    const auto lines =
        only<Line>(moves_of("G21 G90\n#1 = [0.1 + 0.2]\no1 if [#1 LE 0.3]\nG0 X1\no1 else\nG0 X2\no1 endif\n"
                            "o2 if [#1 EQ 0.3]\nG0 Y3\no2 endif\nM2\n",
                            linuxcnc_mill()));
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_NEAR(lines[0].to[Axis::X], 2.0, 1e-12);
    EXPECT_NEAR(lines[1].to[Axis::Y], 3.0, 1e-12);
}

}  // namespace
}  // namespace nckit::test
