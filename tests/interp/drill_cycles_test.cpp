// Drilling cycles expanded into moves: levels, G98/G99, G91, pecks, repeats, cancel rules.
#include <string>

#include <gtest/gtest.h>

#include "interp_support.hpp"

namespace nckit::test {
namespace {

TEST(DrillCycles, G81G98ReturnsToTheInitialLevel) {
    EXPECT_EQ(texts("G0 Z20\nG98 G81 X10 Y10 Z-5 R2 F100\nX20\nG80\n"),
              (Texts{"G0 X0.0000 Y0.0000 Z20.0000", "G0 X10.0000 Y10.0000 Z20.0000", "G0 X10.0000 Y10.0000 Z2.0000",
                     "G1 X10.0000 Y10.0000 Z-5.0000 F100.0000", "G0 X10.0000 Y10.0000 Z20.0000",
                     "G0 X20.0000 Y10.0000 Z20.0000", "G0 X20.0000 Y10.0000 Z2.0000",
                     "G1 X20.0000 Y10.0000 Z-5.0000 F100.0000", "G0 X20.0000 Y10.0000 Z20.0000"}));
}

TEST(DrillCycles, G99StaysAtRAndRepeatsInPlace) {
    EXPECT_EQ(
        texts("G0 Z20\nG99 G81 X30 Z-5 R2 F100 L2\n"),
        (Texts{"G0 X0.0000 Y0.0000 Z20.0000", "G0 X30.0000 Y0.0000 Z20.0000", "G0 X30.0000 Y0.0000 Z2.0000",
               "G1 X30.0000 Y0.0000 Z-5.0000 F100.0000", "G0 X30.0000 Y0.0000 Z2.0000", "G0 X30.0000 Y0.0000 Z2.0000",
               "G1 X30.0000 Y0.0000 Z-5.0000 F100.0000", "G0 X30.0000 Y0.0000 Z2.0000"}));
}

TEST(DrillCycles, IncrementalRepeatsStepAndCountFromTheInitialLevel) {
    EXPECT_EQ(texts("G0 Z10\nG91 G99 G81 X1 Z-3 R-2 K2 F50\n"),
              (Texts{"G0 X0.0000 Y0.0000 Z10.0000", "G0 X1.0000 Y0.0000 Z10.0000", "G0 X1.0000 Y0.0000 Z8.0000",
                     "G1 X1.0000 Y0.0000 Z5.0000 F50.0000", "G0 X1.0000 Y0.0000 Z8.0000", "G0 X2.0000 Y0.0000 Z8.0000",
                     "G1 X2.0000 Y0.0000 Z5.0000 F50.0000", "G0 X2.0000 Y0.0000 Z8.0000"}));
}

TEST(DrillCycles, G83PecksBackToRAndDownToJustAboveTheLastDepth) {
    EXPECT_EQ(
        texts("G0 Z1\nG99 G83 Z-3 R1 Q1.2 F50\n"),
        (Texts{"G0 X0.0000 Y0.0000 Z1.0000", "G0 X0.0000 Y0.0000 Z1.0000", "G1 X0.0000 Y0.0000 Z-0.2000 F50.0000",
               "G0 X0.0000 Y0.0000 Z1.0000", "G0 X0.0000 Y0.0000 Z0.0540", "G1 X0.0000 Y0.0000 Z-1.4000 F50.0000",
               "G0 X0.0000 Y0.0000 Z1.0000", "G0 X0.0000 Y0.0000 Z-1.1460", "G1 X0.0000 Y0.0000 Z-2.6000 F50.0000",
               "G0 X0.0000 Y0.0000 Z1.0000", "G0 X0.0000 Y0.0000 Z-2.3460", "G1 X0.0000 Y0.0000 Z-3.0000 F50.0000",
               "G0 X0.0000 Y0.0000 Z1.0000"}));
}

TEST(DrillCycles, WordsStayForTheNextHoleUntilG80) {
    EXPECT_EQ(texts("G0 Z5\nG99 G82 X1 Z-1 R1 P500 F60\nX2\nG80\nG0 X3\n").size(), 11u);
    EXPECT_EQ(error_where("G0 Z5\nG81 X1 Z-1 R1 F60\nG80\nG81 X2\n"), "missing-word 4:1");
}

TEST(DrillCycles, G0G80InOneBlockMovesAndCancels) {
    EXPECT_EQ(texts("G0 Z5\nG81 X1 Z-1 R1 F60\nG0 G80 Z50\nX4\n").back(), "G0 X4.0000 Y0.0000 Z50.0000");
    EXPECT_EQ(texts("G80 G0 Z50\n"), (Texts{"G0 X0.0000 Y0.0000 Z50.0000"}));
}

TEST(DrillCycles, TappingReversesTheSpindle) {
    EXPECT_EQ(
        texts("S500 M3\nG0 Z5\nG98 G84 Z-3 R1 F100\n"),
        (Texts{"S500", "M3", "G0 X0.0000 Y0.0000 Z5.0000", "G0 X0.0000 Y0.0000 Z5.0000", "G0 X0.0000 Y0.0000 Z1.0000",
               "G1 X0.0000 Y0.0000 Z-3.0000 F100.0000", "M4", "G1 X0.0000 Y0.0000 Z5.0000 F100.0000", "M3"}));
}

TEST(DrillCycles, FineBoringOrientsAndLeavesTheWallByQ) {
    EXPECT_EQ(
        texts("S800 M3\nG0 Z20\nG98 G76 X10 Z-12 R2 Q0.5 P500 F100\n"),
        (Texts{"S800", "M3", "G0 X0.0000 Y0.0000 Z20.0000", "G0 X10.0000 Y0.0000 Z20.0000",
               "G0 X10.0000 Y0.0000 Z2.0000", "G1 X10.0000 Y0.0000 Z-12.0000 F100.0000", "G4 P0.5000", "M19",
               "G0 X10.5000 Y0.0000 Z-12.0000", "G0 X10.5000 Y0.0000 Z20.0000", "G0 X10.0000 Y0.0000 Z20.0000", "M3"}));
}

TEST(DrillCycles, BackBoringGoesDownShiftedAndBoresUpwards) {
    EXPECT_EQ(texts("S800 M3\nG0 Z30\nG98 G87 X40 Z-5 R-20 Q1 P200 F80\n"),
              (Texts{"S800", "M3", "G0 X0.0000 Y0.0000 Z30.0000", "G0 X40.0000 Y0.0000 Z30.0000", "M19",
                     "G0 X41.0000 Y0.0000 Z30.0000", "G0 X41.0000 Y0.0000 Z-20.0000", "G0 X40.0000 Y0.0000 Z-20.0000",
                     "M3", "G1 X40.0000 Y0.0000 Z-5.0000 F80.0000", "G4 P0.2000", "M19", "G0 X41.0000 Y0.0000 Z-5.0000",
                     "G0 X41.0000 Y0.0000 Z30.0000", "G0 X40.0000 Y0.0000 Z30.0000", "M3"}));
}

TEST(DrillCycles, MalformedCyclesAreLocated) {
    EXPECT_EQ(error_where("G0 Z5\nG81 X1 Z-1 F60\n"), "missing-word 2:1");  // no R
    EXPECT_EQ(error_where("G0 Z5\nG81 X1 R1 F60\n"), "missing-word 2:1");   // no Z
    EXPECT_EQ(error_where("G0 Z5\nG83 X1 Z-1 R1 F60\n"), "bad-value 2:1");  // no Q
    EXPECT_EQ(error_where("G0 Z5\nG81 X1 Z-1 R1 F60 K2.5\n"), "bad-value 2:19");
    EXPECT_EQ(error_where("G0 Z5\nG81 X1 Z3 R1 F60\n"), "bad-cycle 2:11");  // R below the bottom
    EXPECT_EQ(error_where("G0 Z5\nG81 X1 Z-1 R1\n"), "no-feed 2:1");
    EXPECT_EQ(error_where("G0 Z5\nG83 X1 Z-100 R1 Q0.0001 F60\n"), "bad-value 2:17");
}

}  // namespace
}  // namespace nckit::test

namespace nckit::test {
namespace {

TEST(ModalRules, G901TakesAbsoluteCentres) {
    Arc a = the<Arc>("G10 L2 P1 X100\nG0 X10 Y0\nG90.1 G3 X0 Y10 I0 J0 F100\n");
    EXPECT_DOUBLE_EQ(a.center[Axis::X], 100.0);
    EXPECT_DOUBLE_EQ(a.center[Axis::Y], 0.0);
}

TEST(ModalRules, G53AloneAndUnderG91) {
    EXPECT_EQ(texts("G53\nG1 X1 F100\nG91 G53 Z-10\n"),
              (Texts{"G1 X1.0000 Y0.0000 Z0.0000 F100.0000", "G0 X1.0000 Y0.0000 Z-10.0000"}));
}

TEST(ModalRules, SettingCodesNeedAxisWords) {
    EXPECT_EQ(error_where("G92\n"), "missing-word 1:1");
    EXPECT_EQ(error_where("G0 X1\nG52\n"), "missing-word 2:1");
    EXPECT_EQ(error_where("G10 L2 P1\n"), "missing-word 1:1");
}

TEST(ModalRules, ColonProgramNumbersAndLabelledTapeMarks) {
    EXPECT_EQ(texts("%MPF100 part 7\n:1234 (PART)\nG0 X1\n%\n"), (Texts{"G0 X1.0000 Y0.0000 Z0.0000"}));
}

TEST(ModalRules, WhIsWhile) {
    EXPECT_EQ(texts("#1=0\nWH [#1 LT 2] DO1\n#1=#1+1\nG0 X#1\nEND1\n").size(), 2u);
}

}  // namespace
}  // namespace nckit::test

namespace nckit::test {
namespace {

TEST(RunawayMain, M99LoopWithoutOutputStopsAtOnce) {
    Diagnostic d = error_of("#1 = 1\nM99\n");
    EXPECT_EQ(where(d), "macro-alarm 2:1");
    EXPECT_EQ(d.alarm, 100);
    // A pass that moves is a real loop: the block budget stops it.
    InterpreterOptions small;
    small.max_blocks = 50;
    RunResult r = run_program("G91 G0 X0.001\nM99\n", default_mill(), small);
    ASSERT_TRUE(r.error);
    EXPECT_GT(r.moves.size(), 10u);
}

TEST(BlockOrder, SpindleBeforeCoolantAndNoFeedBesideAUnitChange) {
    EXPECT_EQ(texts("M8 M3 S100\n"), (Texts{"S100", "M3", "M8"}));
    EXPECT_EQ(error_where("G20 F10 G1 X1\n"), "bad-combination 1:5");
}

}  // namespace
}  // namespace nckit::test
