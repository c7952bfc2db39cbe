// Straight motion and the modes around it: G0 G1, G90/G91, G9 G61 G64, G53, G28, G80, G40 G49.
#include <gtest/gtest.h>

#include "interp_support.hpp"

namespace nckit::test {
namespace {

TEST(Motion, RapidAndFeedMoves) {
    EXPECT_EQ(texts("G0 X10 Y20 Z-5\nG1 X15 F300\n"),
              (Texts{"G0 X10.0000 Y20.0000 Z-5.0000", "G1 X15.0000 Y20.0000 Z-5.0000 F300.0000"}));
}

TEST(Motion, LineCarriesFromToRapidAndFeed) {
    std::vector<Line> lines = only<Line>(moves_of("G0 X1 Y2\nG1 Z-3 F250\n"));
    ASSERT_EQ(lines.size(), 2U);
    EXPECT_TRUE(lines[0].rapid);
    EXPECT_EQ(lines[0].from, xyz(0, 0, 0));
    EXPECT_EQ(lines[0].to, xyz(1, 2, 0));
    EXPECT_FALSE(lines[1].rapid);
    EXPECT_EQ(lines[1].from, xyz(1, 2, 0));
    EXPECT_EQ(lines[1].to, xyz(1, 2, -3));
    EXPECT_EQ(lines[1].feed.mode, FeedMode::per_minute);
    EXPECT_DOUBLE_EQ(lines[1].feed.mm_per_min, 250.0);
    EXPECT_DOUBLE_EQ(lines[1].feed.mm_per_rev, 0.0);
}

TEST(Motion, MotionModeAndFeedAreModal) {
    EXPECT_EQ(texts("G1 X1 F100\nY2\nX3 Y3 F200\n"),
              (Texts{"G1 X1.0000 Y0.0000 Z0.0000 F100.0000", "G1 X1.0000 Y2.0000 Z0.0000 F100.0000",
                     "G1 X3.0000 Y3.0000 Z0.0000 F200.0000"}));
}

TEST(Motion, StartsInRapidMode) {
    EXPECT_EQ(texts("X5\n"), (Texts{"G0 X5.0000 Y0.0000 Z0.0000"}));
}

TEST(Motion, BlockWithoutAxisWordsDoesNotMove) {
    EXPECT_TRUE(moves_of("G1 F100\nG0\nG1\n").empty());
}

TEST(Motion, ZeroLengthMoveIsStillAMove) {
    EXPECT_EQ(texts("G1 X0 F100\n"), (Texts{"G1 X0.0000 Y0.0000 Z0.0000 F100.0000"}));
}

TEST(Motion, IncrementalAndAbsoluteDistance) {
    EXPECT_EQ(texts("G0 X10 Y10\nG91 G0 X5 Y-2\nX1\nG90 X0\n"),
              (Texts{"G0 X10.0000 Y10.0000 Z0.0000", "G0 X15.0000 Y8.0000 Z0.0000", "G0 X16.0000 Y8.0000 Z0.0000",
                     "G0 X0.0000 Y8.0000 Z0.0000"}));
}

TEST(Motion, SequenceNumberAndLocationTravelWithTheMove) {
    std::vector<Move> moves = moves_of("(header)\nN10 G0 X1\nG0 X2\nN20 G1 X3 F9\n");
    ASSERT_EQ(moves.size(), 3U);
    EXPECT_EQ(moves[0].sequence_number, 10);
    EXPECT_EQ(moves[0].where.line, 2U);
    EXPECT_EQ(moves[0].where.column, 1U);
    EXPECT_EQ(moves[0].where.file_name(), "test.ngc");
    EXPECT_EQ(moves[1].sequence_number, -1);
    EXPECT_EQ(moves[1].where.line, 3U);
    EXPECT_EQ(moves[2].sequence_number, 20);
    EXPECT_EQ(moves[2].where.line, 4U);
}

TEST(Motion, OWordAloneMakesNothing) {
    EXPECT_EQ(texts("O1000\nG0 X1\n"), (Texts{"G0 X1.0000 Y0.0000 Z0.0000"}));
}

// ---- path control -------------------------------------------------------------------------

TEST(PathControl, DefaultIsBlendingWithoutTolerance) {
    Line line = the<Line>("G1 X1 F100\n");
    EXPECT_FALSE(line.path.exact_stop);
    EXPECT_DOUBLE_EQ(line.path.tolerance_mm, 0.0);
}

TEST(PathControl, G61IsModalExactStop) {
    std::vector<Line> lines = only<Line>(moves_of("G61 G1 X1 F100\nX2\nG64 X3\n"));
    ASSERT_EQ(lines.size(), 3U);
    EXPECT_TRUE(lines[0].path.exact_stop);
    EXPECT_TRUE(lines[1].path.exact_stop);
    EXPECT_FALSE(lines[2].path.exact_stop);
}

TEST(PathControl, G64PSetsTheTolerance) {
    std::vector<Line> lines = only<Line>(moves_of("G64 P0.05 G1 X1 F100\nX2\nG64 X3\nG64 P0.1 Q0.01 X4\n"));
    ASSERT_EQ(lines.size(), 4U);
    EXPECT_DOUBLE_EQ(lines[0].path.tolerance_mm, 0.05);
    EXPECT_DOUBLE_EQ(lines[1].path.tolerance_mm, 0.05);
    EXPECT_DOUBLE_EQ(lines[2].path.tolerance_mm, 0.0);
    EXPECT_DOUBLE_EQ(lines[3].path.tolerance_mm, 0.1);
    EXPECT_FALSE(lines[0].path.exact_stop);
}

TEST(PathControl, G64PIsInProgramUnits) {
    EXPECT_DOUBLE_EQ(the<Line>("G20\nG64 P0.01 G1 X1 F10\n").path.tolerance_mm, 0.254);
}

TEST(PathControl, G61ClearsTheTolerance) {
    Line line = only<Line>(moves_of("G64 P0.2 G1 X1 F100\nG61 X2\n")).back();
    EXPECT_TRUE(line.path.exact_stop);
    EXPECT_DOUBLE_EQ(line.path.tolerance_mm, 0.0);
}

TEST(PathControl, G9StopsExactlyForItsBlockOnly) {
    std::vector<Line> lines = only<Line>(moves_of("G64 P0.1 G1 X1 F100\nG9 X2\nX3\nG9 G0 X4\n"));
    ASSERT_EQ(lines.size(), 4U);
    EXPECT_FALSE(lines[0].path.exact_stop);
    EXPECT_TRUE(lines[1].path.exact_stop);
    EXPECT_DOUBLE_EQ(lines[1].path.tolerance_mm, 0.1);
    EXPECT_FALSE(lines[2].path.exact_stop);
    EXPECT_TRUE(lines[3].path.exact_stop);
}

TEST(PathControl, G9AppliesToArcs) {
    EXPECT_TRUE(the<Arc>("G9 G2 X10 I5 F100\n").path.exact_stop);
    EXPECT_FALSE(the<Arc>("G2 X10 I5 F100\n").path.exact_stop);
}

// ---- G53, G28, G80, G40, G49 ----------------------------------------------------------------

TEST(Motion, G53MovesInMachineCoordinatesForOneBlock) {
    EXPECT_EQ(texts("G10 L2 P1 X100 Y50\nG54 G0 X0 Y0\nG53 G0 X1 Y2\nG0 X0\nG53 G1 Z-1 F100\n"),
              (Texts{"G0 X100.0000 Y50.0000 Z0.0000", "G0 X1.0000 Y2.0000 Z0.0000", "G0 X100.0000 Y2.0000 Z0.0000",
                     "G1 X100.0000 Y2.0000 Z-1.0000 F100.0000"}));
}

TEST(Motion, G53IsAbsoluteEvenUnderG91) {
    // Machine coordinates are absolute by nature; a Fanuc control reads G53 so under G91 too.
    EXPECT_EQ(texts("G0 X5\nG91 G53 G0 X1\n"), (Texts{"G0 X5.0000 Y0.0000 Z0.0000", "G0 X1.0000 Y0.0000 Z0.0000"}));
    EXPECT_EQ(texts("G91 G0 X5\nG90 G53 G0 X1\n"), (Texts{"G0 X5.0000 Y0.0000 Z0.0000", "G0 X1.0000 Y0.0000 Z0.0000"}));
}

TEST(Motion, G53PositionsAtRapidUnderModalG1) {
    EXPECT_EQ(texts("G1 X5 F50\nG53 X1\nX2\n"),
              (Texts{"G1 X5.0000 Y0.0000 Z0.0000 F50.0000", "G0 X1.0000 Y0.0000 Z0.0000",
                     "G1 X2.0000 Y0.0000 Z0.0000 F50.0000"}));
}

TEST(Motion, G28WithoutAxisWordsSendsEveryAxisHome) {
    MachineConfig m = default_mill();
    m.axes[0].home = 100;
    m.axes[1].home = -50;
    m.axes[2].home = 20;
    EXPECT_EQ(texts("G0 X1 Y2 Z3\nG28\n", m), (Texts{"G0 X1.0000 Y2.0000 Z3.0000", "G0 X100.0000 Y-50.0000 Z20.0000"}));
}

TEST(Motion, MachineStartsAtHome) {
    MachineConfig m = default_mill();
    m.axes[2].home = 20;
    EXPECT_EQ(the<Line>("G0 X1\n", m).from, xyz(0, 0, 20));
}

TEST(Motion, G28WithAxisWordsGoesThroughThePointThenHomesOnlyThoseAxes) {
    MachineConfig m = default_mill();
    m.axes[0].home = 100;
    m.axes[2].home = 20;
    EXPECT_EQ(texts("G0 X1 Y2 Z3\nG28 Z10\n", m),
              (Texts{"G0 X1.0000 Y2.0000 Z3.0000", "G0 X1.0000 Y2.0000 Z10.0000", "G0 X1.0000 Y2.0000 Z20.0000"}));
}

TEST(Motion, G28IntermediatePointFollowsIncrementalMode) {
    MachineConfig m = default_mill();
    m.axes[2].home = 20;
    EXPECT_EQ(texts("G0 Z3\nG91 G28 Z0\n", m),
              (Texts{"G0 X0.0000 Y0.0000 Z3.0000", "G0 X0.0000 Y0.0000 Z3.0000", "G0 X0.0000 Y0.0000 Z20.0000"}));
}

TEST(Motion, G28IntermediatePointIsInWorkCoordinates) {
    EXPECT_EQ(texts("G0 X10\nG92 X0\nG28 X5\n"),
              (Texts{"G0 X10.0000 Y0.0000 Z0.0000", "G0 X15.0000 Y0.0000 Z0.0000", "G0 X0.0000 Y0.0000 Z0.0000"}));
}

TEST(Motion, G28DoesNotChangeTheMotionMode) {
    EXPECT_EQ(texts("G1 X1 F100\nG28\nX2\n"),
              (Texts{"G1 X1.0000 Y0.0000 Z0.0000 F100.0000", "G0 X0.0000 Y0.0000 Z0.0000",
                     "G1 X2.0000 Y0.0000 Z0.0000 F100.0000"}));
}

TEST(Motion, G80CancelsMotionMode) {
    EXPECT_EQ(texts("G1 X1 F100\nG80\nG0 X2\n"),
              (Texts{"G1 X1.0000 Y0.0000 Z0.0000 F100.0000", "G0 X2.0000 Y0.0000 Z0.0000"}));
}

TEST(Motion, G40AndG49AreAcceptedAndChangeNothing) {
    EXPECT_EQ(texts("G40 G49 G0 X1\nG40\nG49\n"), (Texts{"G0 X1.0000 Y0.0000 Z0.0000"}));
}

TEST(Motion, RotaryAxisMovesInDegrees) {
    EXPECT_EQ(texts("G0 X1 A90\nG91 A-30\n", mill_with_a()),
              (Texts{"G0 X1.0000 Y0.0000 Z0.0000 A90.0000", "G0 X1.0000 Y0.0000 Z0.0000 A60.0000"}));
}

// ---- travel limits ------------------------------------------------------------------------

TEST(Travel, MoveToTheLimitIsAllowed) {
    EXPECT_EQ(texts("G0 X500 Y-500\n"), (Texts{"G0 X500.0000 Y-500.0000 Z0.0000"}));
}

TEST(Travel, LineBeyondTheLimitIsAnErrorAtItsAxisWord) {
    Diagnostic d = error_of("G0 X1\nG1 Y2 X500.001 F100\n");
    EXPECT_EQ(where(d), "travel-limit 2:7");
    EXPECT_EQ(d.message, "X would move to 500.0010 mm, beyond its travel limit 500.0000 mm");
}

TEST(Travel, LimitBelowTheMinimum) {
    Diagnostic d = error_of("G91 G0 Z-300\nZ-300\n");
    EXPECT_EQ(where(d), "travel-limit 2:1");
    EXPECT_EQ(d.message, "Z would move to -600.0000 mm, beyond its travel limit -500.0000 mm");
}

TEST(Travel, LimitIsInMachineCoordinates) {
    EXPECT_EQ(error_where("G10 L2 P1 X450\nG54 G0 X40\nG0 X60\n"), "travel-limit 3:4");
}

TEST(Travel, RotaryLimitIsInDegrees) {
    Diagnostic d = error_of("G0 A721\n", mill_with_a());
    EXPECT_EQ(d.message, "A would move to 721.0000 deg, beyond its travel limit 720.0000 deg");
}

}  // namespace
}  // namespace nckit::test
