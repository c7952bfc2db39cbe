// How numbers become millimetres: G20/G21, decimal point input, diameter mode (G7/G8).
#include <gtest/gtest.h>

#include "interp_support.hpp"
#include "nckit/interp/arc_geometry.hpp"

namespace nckit::test {
namespace {

MachineConfig least_increment_mill() {
    MachineConfig m = mill_with_a();
    m.decimal_point_input = DecimalPointInput::least_increment;
    return m;
}

// ---- G20 / G21 ----------------------------------------------------------------------------

TEST(Units, G20ConvertsAxesAndFeed) {
    EXPECT_EQ(texts("G20\nG1 X1 Y-2 Z0.5 F10\n"), (Texts{"G1 X25.4000 Y-50.8000 Z12.7000 F254.0000"}));
    // F beside a G20/G21 that changes the units is refused (never a silent factor of 25.4);
    // beside one that changes nothing it is fine.
    EXPECT_EQ(error_where("G20 G1 X1 F10\n"), "bad-combination 1:11");
    EXPECT_EQ(error_where("G20\nG21 F10 G1 X1\n"), "bad-combination 2:5");
    EXPECT_EQ(texts("G21 G1 X1 F10\n"), (Texts{"G1 X1.0000 Y0.0000 Z0.0000 F10.0000"}));
}

TEST(Units, G21SwitchesBack) {
    EXPECT_EQ(texts("G20 G0 X1\nG21 X1\n"), (Texts{"G0 X25.4000 Y0.0000 Z0.0000", "G0 X1.0000 Y0.0000 Z0.0000"}));
}

TEST(Units, FeedKeepsItsMillimetresAcrossAUnitChange) {
    EXPECT_EQ(texts("G20\nG1 X1 F10\nG21 X2\n"),
              (Texts{"G1 X25.4000 Y0.0000 Z0.0000 F254.0000", "G1 X2.0000 Y0.0000 Z0.0000 F254.0000"}));
}

TEST(Units, G20InTheSameBlockAppliesToItsWords) {
    EXPECT_EQ(texts("F100\nG1 X1 G20\n"), (Texts{"G1 X25.4000 Y0.0000 Z0.0000 F100.0000"}));
}

TEST(Units, G20ConvertsArcOffsetsAndRadius) {
    Arc ij = the<Arc>("G20 G0 X1\nG2 X-1 I-1 F10\n");
    EXPECT_DOUBLE_EQ(ij.from[Axis::X], 25.4);
    EXPECT_DOUBLE_EQ(ij.to[Axis::X], -25.4);
    EXPECT_NEAR(ij.center[Axis::X], 0.0, 1e-12);
    EXPECT_DOUBLE_EQ(ij.feed.mm_per_min, 254.0);
    Arc r = the<Arc>("G20\nG2 X2 R1 F10\n");
    EXPECT_NEAR(r.center[Axis::X], 25.4, 1e-12);
    EXPECT_NEAR(r.center[Axis::Y], 0.0, 1e-12);
}

TEST(Units, G20ConvertsIncrementalMoves) {
    EXPECT_EQ(texts("G20 G91 G0 X1\nX0.5\n"), (Texts{"G0 X25.4000 Y0.0000 Z0.0000", "G0 X38.1000 Y0.0000 Z0.0000"}));
}

TEST(Units, G20LeavesRotaryAxesInDegrees) {
    EXPECT_EQ(texts("G20 G0 X1 A10\n", mill_with_a()), (Texts{"G0 X25.4000 Y0.0000 Z0.0000 A10.0000"}));
}

TEST(Units, G20ConvertsOffsets) {
    EXPECT_EQ(texts("G20 G52 X1\nG92.1\nG0 X0\n"), (Texts{"G0 X25.4000 Y0.0000 Z0.0000"}));
}

// ---- decimal point input ------------------------------------------------------------------

TEST(DecimalPoint, CalculatorReadsWholeNumbersAsMillimetres) {
    EXPECT_EQ(texts("G0 X10 Y10.\n"), (Texts{"G0 X10.0000 Y10.0000 Z0.0000"}));
}

TEST(DecimalPoint, LeastIncrementReadsWholeNumbersAsMicrons) {
    EXPECT_EQ(texts("G0 X10 Y10. Z-1500\n", least_increment_mill()), (Texts{"G0 X0.0100 Y10.0000 Z-1.5000 A0.0000"}));
}

TEST(DecimalPoint, LeastIncrementInInchIsATenThousandth) {
    Line line = the<Line>("G20 G0 X10 Y1.\n", least_increment_mill());
    EXPECT_DOUBLE_EQ(line.to[Axis::X], 10 * 0.0001 * 25.4);
    EXPECT_DOUBLE_EQ(line.to[Axis::Y], 25.4);
}

TEST(DecimalPoint, LeastIncrementOfRotaryAxesIsAThousandthDegree) {
    EXPECT_DOUBLE_EQ(the<Line>("G0 A90000\n", least_increment_mill()).to[Axis::A], 90.0);
    EXPECT_DOUBLE_EQ(the<Line>("G20 G0 A90000\n", least_increment_mill()).to[Axis::A], 90.0);
}

TEST(DecimalPoint, LeastIncrementAppliesToArcOffsetsAndRadius) {
    Arc ij = the<Arc>("G0 X10.\nG2 X-10. I-10000 F100\n", least_increment_mill());
    EXPECT_NEAR(ij.center[Axis::X], 0.0, 1e-12);
    Arc r = the<Arc>("G2 X20. R10000 F100\n", least_increment_mill());
    EXPECT_NEAR(r.center[Axis::X], 10.0, 1e-12);
}

TEST(DecimalPoint, LeastIncrementLeavesFeedAlone) {
    EXPECT_DOUBLE_EQ(the<Line>("G1 X1. F100\n", least_increment_mill()).feed.mm_per_min, 100.0);
}

TEST(DecimalPoint, LeastIncrementAppliesToOffsets) {
    EXPECT_EQ(texts("G10 L2 P1 X5000\nG0 X0\n", least_increment_mill()), (Texts{"G0 X5.0000 Y0.0000 Z0.0000 A0.0000"}));
}

TEST(DecimalPoint, LeastIncrementDwellXIsInMilliseconds) {
    // Fanuc reads G4 X like any X word: without a point it counts least increments (1 ms).
    EXPECT_DOUBLE_EQ(the<Dwell>("G4 X1500\n", least_increment_mill()).seconds, 1.5);
    EXPECT_DOUBLE_EQ(the<Dwell>("G4 X1.5\n", least_increment_mill()).seconds, 1.5);
    EXPECT_DOUBLE_EQ(the<Dwell>("G4 P1500\n", least_increment_mill()).seconds, 1.5);
}

// ---- diameter mode ------------------------------------------------------------------------

TEST(Diameter, LatheXWordsAreDiametersAndMovesCarryRadii) {
    EXPECT_EQ(texts("G0 X100 Z5\nG1 X80 Z-10 F100\n", lathe()),
              (Texts{"G0 X50.0000 Z5.0000", "G1 X40.0000 Z-10.0000 F100.0000"}));
}

TEST(Diameter, IncrementalXIsADiameterChange) {
    EXPECT_EQ(texts("G0 X100\nG91 G0 X-20\n", lathe()), (Texts{"G0 X50.0000 Z0.0000", "G0 X40.0000 Z0.0000"}));
}

TEST(Diameter, ArcOffsetIIsARadius) {
    // From diameter 40 (radius 20) to diameter 60 at Z-10 around X radius 30: I10 is 10 mm of radius.
    Arc arc = the<Arc>("G18 G0 X40 Z0\nG2 X60 Z-10 I10 K0 F100\n", lathe());
    EXPECT_DOUBLE_EQ(arc.from[Axis::X], 20.0);
    EXPECT_DOUBLE_EQ(arc.to[Axis::X], 30.0);
    EXPECT_DOUBLE_EQ(arc.center[Axis::X], 30.0);
    EXPECT_DOUBLE_EQ(arc.center[Axis::Z], 0.0);
}

TEST(Diameter, ArcRadiusIsARadius) {
    Arc arc = the<Arc>("G18 G0 X40 Z0\nG3 X60 Z-10 R10 F100\n", lathe());
    EXPECT_NEAR(arc_start_radius(arc), 10.0, 1e-12);
    EXPECT_NEAR(arc_end_radius(arc), 10.0, 1e-12);
}

TEST(Diameter, G7AndG8SwitchOnAMill) {
    EXPECT_EQ(texts("G7 G0 X20\nG8 X20\n"), (Texts{"G0 X10.0000 Y0.0000 Z0.0000", "G0 X20.0000 Y0.0000 Z0.0000"}));
}

TEST(Diameter, G8OnALatheMakesXARadius) {
    EXPECT_EQ(texts("G8 G0 X20\nG7 X20\n", lathe()), (Texts{"G0 X20.0000 Z0.0000", "G0 X10.0000 Z0.0000"}));
}

TEST(Diameter, OnlyXIsHalved) {
    EXPECT_EQ(texts("G7 G0 X20 Y20 Z20\n"), (Texts{"G0 X10.0000 Y20.0000 Z20.0000"}));
}

TEST(Diameter, WorkOffsetsInDiameters) {
    EXPECT_EQ(texts("G10 L2 P1 X40\nG0 X0\n", lathe()), (Texts{"G0 X20.0000 Z0.0000"}));
}

}  // namespace
}  // namespace nckit::test
