// Coordinate systems and offsets: G54–G59, G10 L2/L20, G92/G92.1, G50 (as G92), G52.
#include <string>

#include <gtest/gtest.h>

#include "interp_support.hpp"

namespace nckit::test {
namespace {

TEST(WorkOffsets, G10L2SetsG54) {
    EXPECT_EQ(texts("G10 L2 P1 X10 Y20 Z-5\nG54 G0 X0 Y0 Z0\nX1\n"),
              (Texts{"G0 X10.0000 Y20.0000 Z-5.0000", "G0 X11.0000 Y20.0000 Z-5.0000"}));
}

TEST(WorkOffsets, G54IsActiveFromTheStart) {
    EXPECT_EQ(texts("G10 L2 P1 X10\nG0 X0\n"), (Texts{"G0 X10.0000 Y0.0000 Z0.0000"}));
}

TEST(WorkOffsets, PNumbersOneToSixAreG54ToG59) {
    for (int p = 1; p <= 6; ++p) {
        std::string program = "G10 L2 P" + std::to_string(p) + " X" + std::to_string(10 * p) + "\nG" +
                              std::to_string(53 + p) + " G0 X1\nG54 X1\n";
        EXPECT_EQ(texts(program), (Texts{"G0 X" + std::to_string(10 * p + 1) + ".0000 Y0.0000 Z0.0000",
                                         p == 1 ? "G0 X11.0000 Y0.0000 Z0.0000" : "G0 X1.0000 Y0.0000 Z0.0000"}))
            << program;
    }
}

TEST(WorkOffsets, P0SetsTheActiveSystem) {
    EXPECT_EQ(texts("G56\nG10 L2 P0 X7\nG0 X0\nG54 X0\n"),
              (Texts{"G0 X7.0000 Y0.0000 Z0.0000", "G0 X0.0000 Y0.0000 Z0.0000"}));
}

TEST(WorkOffsets, G10ChangesOnlyTheNamedAxes) {
    EXPECT_EQ(texts("G10 L2 P1 X5 Y6\nG10 L2 P1 X1\nG0 X0 Y0\n"), (Texts{"G0 X1.0000 Y6.0000 Z0.0000"}));
}

TEST(WorkOffsets, G10L2InG91AddsToTheOffset) {
    EXPECT_EQ(texts("G10 L2 P1 X5\nG91 G10 L2 P1 X2\nG90 G0 X0\n"), (Texts{"G0 X7.0000 Y0.0000 Z0.0000"}));
}

TEST(WorkOffsets, G10MakesNoMove) {
    EXPECT_TRUE(moves_of("G10 L2 P1 X5 Y5\nG10 L20 P2 Z1\n").empty());
}

TEST(WorkOffsets, G10L20MakesTheCurrentPositionTheGivenValue) {
    EXPECT_EQ(texts("G0 X30 Y40\nG10 L20 P1 X10 Y0\nG0 X10 Y0\nX0\n"),
              (Texts{"G0 X30.0000 Y40.0000 Z0.0000", "G0 X30.0000 Y40.0000 Z0.0000", "G0 X20.0000 Y40.0000 Z0.0000"}));
}

TEST(WorkOffsets, G10L20OfAnotherSystem) {
    EXPECT_EQ(texts("G0 X30\nG10 L20 P2 X10\nG0 X0\nG55 X0\n"),
              (Texts{"G0 X30.0000 Y0.0000 Z0.0000", "G0 X0.0000 Y0.0000 Z0.0000", "G0 X20.0000 Y0.0000 Z0.0000"}));
}

TEST(WorkOffsets, G10L20AccountsForG52) {
    // G52 X5 makes X30 machine 35; L20 X10 there puts G54 at 20; X0 is then 20 + 5.
    EXPECT_EQ(texts("G52 X5\nG0 X30\nG10 L20 P1 X10\nG0 X10\nX0\n"),
              (Texts{"G0 X35.0000 Y0.0000 Z0.0000", "G0 X35.0000 Y0.0000 Z0.0000", "G0 X25.0000 Y0.0000 Z0.0000"}));
}

TEST(WorkOffsets, G10IsInProgramUnits) {
    EXPECT_EQ(texts("G20 G10 L2 P1 X1\nG21 G0 X0\n"), (Texts{"G0 X25.4000 Y0.0000 Z0.0000"}));
}

TEST(WorkOffsets, EachSystemKeepsItsOffset) {
    EXPECT_EQ(texts("G10 L2 P1 X1\nG10 L2 P2 X2\nG10 L2 P6 X6\nG55 G0 X0\nG54 X0\nG59 X0\nG55 X0\n"),
              (Texts{"G0 X2.0000 Y0.0000 Z0.0000", "G0 X1.0000 Y0.0000 Z0.0000", "G0 X6.0000 Y0.0000 Z0.0000",
                     "G0 X2.0000 Y0.0000 Z0.0000"}));
}

TEST(WorkOffsets, RotaryAxisOffset) {
    EXPECT_EQ(texts("G10 L2 P1 A90\nG0 A0\n", mill_with_a()), (Texts{"G0 X0.0000 Y0.0000 Z0.0000 A90.0000"}));
}

// ---- G92 / G92.1 / G50 --------------------------------------------------------------------------

TEST(G92, MakesTheCurrentPositionTheGivenValue) {
    EXPECT_EQ(texts("G0 X10 Y10\nG92 X0 Y0\nG0 X5 Y5\n"),
              (Texts{"G0 X10.0000 Y10.0000 Z0.0000", "G0 X15.0000 Y15.0000 Z0.0000"}));
}

TEST(G92, MakesNoMove) {
    EXPECT_TRUE(moves_of("G92 X10 Y10 Z3\n").empty());
}

TEST(G92, IsAbsoluteEvenInG91) {
    EXPECT_EQ(texts("G0 X10\nG91 G92 X0\nG90 G0 X1\n"),
              (Texts{"G0 X10.0000 Y0.0000 Z0.0000", "G0 X11.0000 Y0.0000 Z0.0000"}));
}

TEST(G92, StacksOnTheWorkOffset) {
    EXPECT_EQ(texts("G10 L2 P1 X100\nG0 X0\nG92 X50\nG0 X60\nG92.1\nG0 X0\n"),
              (Texts{"G0 X100.0000 Y0.0000 Z0.0000", "G0 X110.0000 Y0.0000 Z0.0000", "G0 X100.0000 Y0.0000 Z0.0000"}));
}

TEST(G92, G92Point1ClearsEveryAxis) {
    EXPECT_EQ(texts("G0 X10 Y10 Z-1\nG92 X0 Y0 Z0\nG92.1\nG0 X1 Y1 Z-2\n"),
              (Texts{"G0 X10.0000 Y10.0000 Z-1.0000", "G0 X1.0000 Y1.0000 Z-2.0000"}));
}

TEST(G92, G92Point1WithAxisWordsMovesInTheModalMode) {
    EXPECT_EQ(texts("G0 X10\nG92 X0\nG92.1 X1\n"),
              (Texts{"G0 X10.0000 Y0.0000 Z0.0000", "G0 X1.0000 Y0.0000 Z0.0000"}));
}

TEST(G50, SetsCoordinatesLikeG92InDiameters) {
    // X100 is a 50 mm radius; G50 X50 says that point is now diameter 50 (radius 25).
    EXPECT_EQ(texts("G0 X100 Z5\nG50 X50 Z0\nG0 X50 Z-10\n", lathe()),
              (Texts{"G0 X50.0000 Z5.0000", "G0 X50.0000 Z-5.0000"}));
}

TEST(G50, AxisSettingAndSpeedClampInOneBlock) {
    std::vector<Move> moves = moves_of("G0 X100\nG50 X0 S1500\nG96 S100 M3\nG0 X10\n", lathe());
    ASSERT_EQ(moves.size(), 4U);
    EXPECT_EQ(std::get<Line>(moves[3].what).to[Axis::X], 55.0);
    const Io& m3 = std::get<Io>(moves[2].what);
    EXPECT_DOUBLE_EQ(m3.rpm_clamp, 1500.0);
}

// ---- G52 ----------------------------------------------------------------------------------

TEST(G52, ShiftsEveryWorkSystem) {
    EXPECT_EQ(texts("G10 L2 P2 X100\nG52 X10 Y5\nG0 X0 Y0\nG55 X0\nG52 X0 Y0\nG0 X0 Y0\n"),
              (Texts{"G0 X10.0000 Y5.0000 Z0.0000", "G0 X110.0000 Y5.0000 Z0.0000", "G0 X100.0000 Y0.0000 Z0.0000"}));
}

TEST(G52, ReplacesThePreviousShiftAxisByAxis) {
    EXPECT_EQ(texts("G52 X10 Y5\nG52 X3\nG0 X0 Y0\n"), (Texts{"G0 X3.0000 Y5.0000 Z0.0000"}));
}

TEST(G52, MakesNoMove) {
    EXPECT_TRUE(moves_of("G52 X10\n").empty());
}

TEST(Offsets, ArcCentreFollowsTheOffsets) {
    Arc arc = the<Arc>("G10 L2 P1 X100 Y100\nG52 X10\nG0 X10 Y0\nG2 X-10 I-10 F100\n");
    EXPECT_EQ(arc.from, xyz(120, 100, 0));
    EXPECT_EQ(arc.center, xyz(110, 100, 0));
    EXPECT_EQ(arc.to, xyz(100, 100, 0));
}

}  // namespace
}  // namespace nckit::test
