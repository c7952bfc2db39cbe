// G2/G3: centre offsets and radius forms, full circles, helices in every plane, travel of the bulge.
#include <cmath>

#include <gtest/gtest.h>

#include "interp_support.hpp"
#include "nckit/interp/arc_geometry.hpp"

namespace nckit::test {
namespace {

TEST(Arc, ClockwiseWithCentreOffsets) {
    Arc arc = the<Arc>("G0 X10 Y0\nG2 X0 Y-10 I-10 J0 F200\n");
    EXPECT_EQ(arc.from, xyz(10, 0, 0));
    EXPECT_EQ(arc.to, xyz(0, -10, 0));
    EXPECT_EQ(arc.center, xyz(0, 0, 0));
    EXPECT_EQ(arc.plane, Plane::xy);
    EXPECT_EQ(arc.direction, ArcDirection::clockwise);
    EXPECT_EQ(arc.full_turns, 0);
    EXPECT_DOUBLE_EQ(arc.feed.mm_per_min, 200.0);
    EXPECT_DOUBLE_EQ(arc_sweep_rad(arc), std::numbers::pi / 2);
}

TEST(Arc, CounterClockwiseText) {
    EXPECT_EQ(
        texts("G0 X10\nG3 X0 Y10 I-10 F100\n"),
        (Texts{"G0 X10.0000 Y0.0000 Z0.0000", "G3 X0.0000 Y10.0000 Z0.0000 CX0.0000 CY0.0000 CZ0.0000 F100.0000"}));
}

TEST(Arc, CentreOffsetsAreIncrementalEvenInG90) {
    Arc arc = the<Arc>("G0 X20 Y20\nG90 G3 X10 Y30 I-10 J0 F100\n");
    EXPECT_EQ(arc.center, xyz(10, 20, 0));
}

TEST(Arc, MissingOffsetIsZero) {
    EXPECT_EQ(the<Arc>("G0 X10\nG2 X-10 I-10 F100\n").center, xyz(0, 0, 0));
    EXPECT_EQ(the<Arc>("G0 Y10\nG2 Y-10 J-10 F100\n").center, xyz(0, 0, 0));
}

TEST(Arc, ModalArcMode) {
    std::vector<Arc> arcs = only<Arc>(moves_of("G0 X10\nG2 X-10 I-10 F100\nX10 I10\n"));
    ASSERT_EQ(arcs.size(), 2U);
    EXPECT_EQ(arcs[1].from, xyz(-10, 0, 0));
    EXPECT_EQ(arcs[1].center, xyz(0, 0, 0));
    EXPECT_EQ(arcs[1].direction, ArcDirection::clockwise);
}

TEST(Arc, PositiveRadiusTakesTheShortWay) {
    Arc cw = the<Arc>("G2 X10 R10 F100\n");
    EXPECT_NEAR(cw.center[Axis::X], 5.0, 1e-12);
    EXPECT_NEAR(cw.center[Axis::Y], -std::sqrt(75.0), 1e-12);
    EXPECT_NEAR(arc_sweep_rad(cw), std::numbers::pi / 3, 1e-12);
    Arc ccw = the<Arc>("G3 X10 R10 F100\n");
    EXPECT_NEAR(ccw.center[Axis::X], 5.0, 1e-12);
    EXPECT_NEAR(ccw.center[Axis::Y], std::sqrt(75.0), 1e-12);
    EXPECT_NEAR(arc_sweep_rad(ccw), std::numbers::pi / 3, 1e-12);
}

TEST(Arc, NegativeRadiusTakesTheLongWay) {
    Arc cw = the<Arc>("G2 X10 R-10 F100\n");
    EXPECT_NEAR(cw.center[Axis::Y], std::sqrt(75.0), 1e-12);
    EXPECT_NEAR(arc_sweep_rad(cw), 5 * std::numbers::pi / 3, 1e-12);
    Arc ccw = the<Arc>("G3 X10 R-10 F100\n");
    EXPECT_NEAR(ccw.center[Axis::Y], -std::sqrt(75.0), 1e-12);
    EXPECT_NEAR(arc_sweep_rad(ccw), 5 * std::numbers::pi / 3, 1e-12);
}

TEST(Arc, HalfCircleByRadius) {
    Arc arc = the<Arc>("G0 X-10\nG2 X10 R10 F100\n");
    EXPECT_NEAR(arc.center[Axis::X], 0.0, 1e-12);
    EXPECT_NEAR(arc.center[Axis::Y], 0.0, 1e-12);
}

TEST(Arc, RadiusJustShortOfHalfTheChordIsStretched) {
    // 0.001 mm short: within LinuxCNC's 0.00127 mm, so the arc becomes a half circle; 0.002 mm
    // short is refused, as rs274 refuses it.
    EXPECT_EQ(error_where("G2 X20 R9.998 F100\n"), "bad-arc 1:8");
    Arc arc = the<Arc>("G2 X20 R9.999 F100\n");
    EXPECT_NEAR(arc.center[Axis::X], 10.0, 1e-12);
    EXPECT_NEAR(arc.center[Axis::Y], 0.0, 1e-12);
}

TEST(Arc, FullCircleWhenTheEndIsTheStart) {
    Arc arc = the<Arc>("G0 X10\nG3 X10 Y0 I-10 F100\n");
    EXPECT_EQ(arc.to, arc.from);
    EXPECT_EQ(arc.center, xyz(0, 0, 0));
    EXPECT_DOUBLE_EQ(arc_sweep_rad(arc), 2 * std::numbers::pi);
}

TEST(Arc, FullCircleWithoutAxisWords) {
    Arc arc = the<Arc>("G0 X10\nG2 I-10 F100\n");
    EXPECT_EQ(arc.to, xyz(10, 0, 0));
    EXPECT_EQ(arc.center, xyz(0, 0, 0));
}

TEST(Arc, EndOffTheCircleWithinToleranceIsAccepted) {
    // End radius 10.005 against 10: 0.005 mm off, inside the 0.01 mm tolerance.
    Arc arc = the<Arc>("G0 X10\nG3 X0 Y10.005 I-10 F100\n");
    EXPECT_NEAR(arc_end_radius(arc) - arc_start_radius(arc), 0.005, 1e-9);
}

TEST(Arc, RelativeToleranceAllowsMoreOnBigArcs) {
    // 0.05 mm off on a 100 mm radius: beyond 0.028 mm but within 0.1 %.
    moves_of("G0 X100\nG3 X0 Y100.05 I-100 F100\n");
    // 0.03 mm off a 10 mm radius: beyond both (as rs274); 0.02 mm off: within the 0.028 mm.
    EXPECT_EQ(error_where("G0 X10\nG3 X0 Y10.03 I-10 F100\n"), "bad-arc 2:1");
    moves_of("G0 X10\nG3 X0 Y10.02 I-10 F100\n");
    // More than 100 times the tolerance is refused whatever the radius.
    EXPECT_EQ(error_where("G0 X5000\nG3 X0 Y5003 I-5000 F100\n",
                          [] {
                              MachineConfig m = default_mill();
                              for (AxisConfig& a : m.axes) {
                                  a.min = -6000;
                                  a.max = 6000;
                              }
                              return m;
                          }()),
              "bad-arc 2:1");
}

TEST(Arc, ToleranceIsAnOption) {
    InterpreterOptions strict;
    strict.arc_radius_tolerance_mm = 0.001;
    // 0.005 mm off a 1 mm radius: past 0.1 % and past the strict 0.001 mm, within the default
    // 0.028 mm.
    const char* program = "G0 X1\nG3 X0 Y1.005 I-1 F100\n";
    moves_of(program);
    RunResult r = run_program(program, default_mill(), strict);
    ASSERT_TRUE(r.error);
    EXPECT_EQ(where(*r.error), "bad-arc 2:1");
}

TEST(Arc, HelixInG17MovesZLinearly) {
    Arc arc = the<Arc>("G0 X10\nG17 G3 X-10 Y0 Z-5 I-10 F100\n");
    EXPECT_EQ(arc.plane, Plane::xy);
    EXPECT_EQ(arc.to, xyz(-10, 0, -5));
    EXPECT_EQ(arc.center, xyz(0, 0, 0)) << "the normal axis of the centre is the start's";
}

TEST(Arc, G18PlaneUsesIAndKWithZFirst) {
    Arc arc = the<Arc>("G0 X10 Z0\nG18 G2 X0 Z10 I-10 K0 F100\n");
    EXPECT_EQ(arc.plane, Plane::zx);
    EXPECT_EQ(arc.center, xyz(0, 0, 0));
    // Looking down -Y... in the Z,X plane (Z first), the start is at angle 90°, the end at 0°.
    EXPECT_NEAR(arc_sweep_rad(arc), std::numbers::pi / 2, 1e-12);
    Arc k_only = the<Arc>("G0 Z10\nG18 G3 Z-10 K-10 F100\n");
    EXPECT_EQ(k_only.center, xyz(0, 0, 0));
}

TEST(Arc, G18HelixMovesY) {
    Arc arc = the<Arc>("G0 Z10\nG18 G2 Z-10 Y5 K-10 F100\n");
    EXPECT_EQ(arc.to, xyz(0, 5, -10));
    EXPECT_EQ(arc.center, xyz(0, 0, 0));
}

TEST(Arc, G19PlaneUsesJAndK) {
    Arc arc = the<Arc>("G0 Y10\nG19 G3 Y0 Z10 J-10 F100\n");
    EXPECT_EQ(arc.plane, Plane::yz);
    EXPECT_EQ(arc.center, xyz(0, 0, 0));
    EXPECT_NEAR(arc_sweep_rad(arc), std::numbers::pi / 2, 1e-12);
}

TEST(Arc, G19HelixMovesX) {
    Arc arc = the<Arc>("G0 Y10\nG19 G2 Y-10 X3 J-10 K0 F100\n");
    EXPECT_EQ(arc.to, xyz(3, -10, 0));
    EXPECT_EQ(arc.center, xyz(0, 0, 0));
}

TEST(Arc, RadiusFormInG18AndG19) {
    Arc zx = the<Arc>("G18 G3 Z10 R10 F100\n");  // ccw from Z toward X: centre on +X side
    EXPECT_NEAR(zx.center[Axis::Z], 5.0, 1e-12);
    EXPECT_NEAR(zx.center[Axis::X], std::sqrt(75.0), 1e-12);
    Arc yz = the<Arc>("G19 G3 Y10 R10 F100\n");  // ccw from Y toward Z: centre on +Z side
    EXPECT_NEAR(yz.center[Axis::Y], 5.0, 1e-12);
    EXPECT_NEAR(yz.center[Axis::Z], std::sqrt(75.0), 1e-12);
}

TEST(Arc, PlaneIsModal) {
    std::vector<Arc> arcs = only<Arc>(moves_of("G18\nG0 X10\nG2 X-10 I-10 F100\nG17 G2 X10 I10\n"));
    ASSERT_EQ(arcs.size(), 2U);
    EXPECT_EQ(arcs[0].plane, Plane::zx);
    EXPECT_EQ(arcs[1].plane, Plane::xy);
}

TEST(Arc, IncrementalEndPoint) {
    Arc arc = the<Arc>("G0 X10 Y10\nG91 G2 X10 Y-10 I0 J-10 F100\n");
    EXPECT_EQ(arc.to, xyz(20, 0, 0));
    EXPECT_EQ(arc.center, xyz(10, 0, 0));
}

// ---- travel -------------------------------------------------------------------------------

TEST(ArcTravel, BulgeInsideTheTravelIsFine) {
    moves_of("G0 X490\nG2 X490 Y0 I5 F100\n");
}

TEST(ArcTravel, BulgeBeyondTheTravelIsAnErrorAtTheBlock) {
    // Both end points at X490, but the full circle around X495 reaches X500.5... with radius 5.25.
    Diagnostic d = error_of("G0 X490 Y0\nG2 X490 Y0 I5.25 F100\n");
    EXPECT_EQ(where(d), "travel-limit 2:4");
    EXPECT_EQ(d.message, "X would move to 500.5000 mm, beyond its travel limit 500.0000 mm");
}

TEST(ArcTravel, HalfCircleBulgeOnAnAxisWithoutAWord) {
    // Ends on Y=495 both times; the clockwise half circle from X-5 to X5 peaks at Y500+.
    EXPECT_EQ(error_where("G0 X-6 Y495\nG2 X6 R6 F100\n"), "travel-limit 2:1");
    moves_of("G0 X-6 Y495\nG3 X6 R6 F100\n");  // the other way it dips to Y489
}

}  // namespace
}  // namespace nckit::test

namespace nckit::test {
namespace {

TEST(ArcPlane, LatheStartsInTheZXPlane) {
    // No G18 needed on a lathe: I and K name the centre as on a Fanuc lathe control.
    std::vector<Move> moves = moves_of("G0 X20 Z0\nG2 X20 Z-10 K-5 F100\n", lathe());
    ASSERT_EQ(moves.size(), 2U);
    const Arc& arc = std::get<Arc>(moves[1].what);
    EXPECT_EQ(arc.plane, Plane::zx);
    EXPECT_DOUBLE_EQ(arc.center[Axis::Z], -5.0);
    EXPECT_DOUBLE_EQ(arc.center[Axis::X], 10.0);
}

TEST(ArcPlane, MillStartsInTheXYPlane) {
    std::vector<Move> moves = moves_of("G2 X10 Y0 I5 F100\n");
    ASSERT_EQ(moves.size(), 1U);
    EXPECT_EQ(std::get<Arc>(moves[0].what).plane, Plane::xy);
}

TEST(ArcBounds, AnEndOnAQuarterTurnStaysTheEndWhenTheRadiiDiffer) {
    // CAM output rounded to 4 decimals: from (10, 0) about (0, 0) to (0, 10.002), start radius
    // 10, end radius 10.002. The start sits on the +X extreme: the box ends there, not at the
    // larger radius 10.002 beyond it; the +Y extreme is the end point itself.
    Arc arc = the<Arc>("G0 X10 Y0\nG3 X0 Y10.002 I-10 J0 F100\n");
    AxisBox box = arc_bounds(arc);
    EXPECT_DOUBLE_EQ(box.high[Axis::X], 10.0);
    EXPECT_DOUBLE_EQ(box.high[Axis::Y], 10.002);
    // A quarter-turn extreme inside the sweep still counts, at the larger radius.
    Arc half = the<Arc>("G0 X10 Y0\nG3 X-10.002 Y0 I-10 J0 F100\n");
    EXPECT_NEAR(arc_bounds(half).high[Axis::Y], 10.002, 1e-12);
}

}  // namespace
}  // namespace nckit::test
