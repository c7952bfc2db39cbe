// Errors found before anything in a block runs: unknown and conflicting codes, duplicate and
// unused words, wrong axes. Each test states the error's code, line and column.
#include <gtest/gtest.h>

#include "interp_support.hpp"

namespace nckit::test {
namespace {

// ---- G and M codes ------------------------------------------------------------------------

TEST(BlockErrors, NegativeOrOddGCodeIsUnknown) {
    Diagnostic d = error_of("G0 X1\nG-1\n");
    EXPECT_EQ(where(d), "unknown-gcode 2:1");
    EXPECT_EQ(d.message, "G-1 is not a G code");
    EXPECT_EQ(error_where("G1.05 X1\n"), "unknown-gcode 1:1");
}

TEST(BlockErrors, UnsupportedGCode) {
    Diagnostic d = error_of("G0 X1 G12\n");
    EXPECT_EQ(where(d), "unsupported-gcode 1:7");
    EXPECT_EQ(d.message, "G12 is not supported");
    EXPECT_EQ(error_of("G92.2\n").message, "G92.2 is not supported");
    EXPECT_EQ(error_where("G43.4 H1\n"), "unsupported-gcode 1:1");
    EXPECT_EQ(error_where("G81.1 X1 Y1 Z-1 R1\n"), "unsupported-gcode 1:1");
    EXPECT_EQ(error_where("G1.5\n"), "unsupported-gcode 1:1");
}

TEST(BlockErrors, TwoGCodesOfOneModalGroupInTheLinuxCncDialect) {
    // RS-274/NGC and LinuxCNC refuse two codes of one group; the Fanuc dialect takes the last
    // one (fanuc_groups_test.cpp).
    const MachineConfig ngc = linuxcnc_mill();
    Diagnostic d = error_of("G0 G1 X1\n", ngc);
    EXPECT_EQ(where(d), "modal-conflict 1:4");
    EXPECT_EQ(d.message, "G0 and G1 are in the same modal group");
    EXPECT_EQ(error_where("G90 X1 G91\n", ngc), "modal-conflict 1:8");
    EXPECT_EQ(error_where("G17 G18\n", ngc), "modal-conflict 1:5");
    EXPECT_EQ(error_where("G54 G59\n", ngc), "modal-conflict 1:5");
    EXPECT_EQ(error_where("G20 G21\n", ngc), "modal-conflict 1:5");
    EXPECT_EQ(error_where("G94 G95\n", ngc), "modal-conflict 1:5");
    EXPECT_EQ(error_where("G61 G64\n", ngc), "modal-conflict 1:5");
    EXPECT_EQ(error_where("G1 G1 X1 F1\n", ngc), "modal-conflict 1:4");
    EXPECT_EQ(error_where("G81 G82 X1 Z-1 R1 F1\n", ngc), "modal-conflict 1:5");
}

TEST(BlockErrors, TwoOneShotGCodesConflictInBothDialects) {
    EXPECT_EQ(error_of("G4 P1 G92 X0\n").message, "G4 and G92 are in the same modal group");
    for (const MachineConfig& machine : {default_mill(), linuxcnc_mill()}) {
        EXPECT_EQ(error_of("G92 X0 G92.1\n", machine).message, "G92 and G92.1 are in the same modal group");
        EXPECT_EQ(error_where("G28 G92 X0\n", machine), "modal-conflict 1:5");
    }
}

TEST(BlockErrors, NegativeOrOddMCodeIsABadValue) {
    Diagnostic d = error_of("M-3\n");
    EXPECT_EQ(where(d), "bad-value 1:1");
    EXPECT_EQ(d.message, "M must be a whole number from 0 to 99999999");
    EXPECT_EQ(error_where("S100 M3.5\n"), "bad-value 1:6");
}

TEST(BlockErrors, CodeWordsOutOfRangeAreBadValues) {
    EXPECT_EQ(error_where("M3000000000\n"), "bad-value 1:1");
    EXPECT_EQ(error_where("T123456789\n"), "bad-value 1:1");
    EXPECT_EQ(error_where("N1.5 G0 X1\n"), "macro-alarm 1:1");  // N must be a whole number (alarm 114)
    EXPECT_EQ(error_where("G0 X1 T-1\n"), "bad-value 1:7");
    EXPECT_EQ(error_where("G1000 X1\n"), "unknown-gcode 1:1");
}

TEST(BlockErrors, TwoMCodesOfOneGroup) {
    Diagnostic d = error_of("M3 M4\n");
    EXPECT_EQ(where(d), "modal-conflict 1:4");
    EXPECT_EQ(d.message, "M3 and M4 cannot be in one block");
    EXPECT_EQ(error_where("M8 M9\n"), "modal-conflict 1:4");
    EXPECT_EQ(error_where("M9 M7\n"), "modal-conflict 1:4");
    EXPECT_EQ(error_where("M0 M30\n"), "modal-conflict 1:4");
    EXPECT_EQ(error_where("M6 T1 M6\n"), "modal-conflict 1:7");
    EXPECT_EQ(error_where("M100 M100\n"), "modal-conflict 1:6");
}

TEST(BlockErrors, MCodesOfDifferentGroupsMayShareABlock) {
    EXPECT_EQ(moves_of("M7 M8\nM3 M8 M6 M100 M30\n").size(), 7U);
}

TEST(BlockErrors, MoreThanFiveMCodes) {
    Diagnostic d = error_of("M100 M101 M102 M103 M104 M105\n");
    EXPECT_EQ(where(d), "too-many-mcodes 1:26");
    EXPECT_EQ(d.message, "more than 5 M codes in one block");
}

// ---- words --------------------------------------------------------------------------------

TEST(BlockErrors, DuplicateWord) {
    Diagnostic d = error_of("G1 X1 X2 F1\n");
    EXPECT_EQ(where(d), "duplicate-word 1:7");
    EXPECT_EQ(d.message, "X appears twice in one block");
    EXPECT_EQ(error_where("G1 X1 F1 F2\n"), "duplicate-word 1:10");
    EXPECT_EQ(error_where("S1 S2\n"), "duplicate-word 1:4");
    EXPECT_EQ(error_where("N1 N2\n"), "duplicate-word 1:4");
}

TEST(BlockErrors, AxisTheMachineDoesNotHave) {
    Diagnostic d = error_of("G0 X1 A1\n");
    EXPECT_EQ(where(d), "unknown-axis 1:7");
    EXPECT_EQ(d.message, "the machine has no A axis");
    EXPECT_EQ(error_where("G0 Y1\n", lathe()), "unknown-axis 1:4");
    EXPECT_EQ(error_where("G92 U0\n"), "unknown-axis 1:5");
    EXPECT_EQ(error_where("G80 W1\n"), "unknown-axis 1:5");
}

TEST(BlockErrors, SequenceNumberMustStartTheBlock) {
    Diagnostic d = error_of("G0 N10 X1\n");
    EXPECT_EQ(where(d), "syntax 1:4");
    EXPECT_EQ(d.message, "N word must start the block");
    EXPECT_EQ(error_of("G0 O100\n").message, "O word must start the block");
    moves_of("N10 G0 X1\n(comment) N20 G0 X2\n/N30 G0 X3\n");
}

TEST(BlockErrors, UnsupportedLetter) {
    Diagnostic d = error_of("G0 X1 V1\n");
    EXPECT_EQ(where(d), "unknown-axis 1:7");
    // D and H alone set the modal offset numbers (#4107, #4111); they must be whole numbers.
    moves_of("G0 X1 D1\nH2\n");
    EXPECT_EQ(error_where("G0 X1 D1.5\n"), "bad-value 1:7");
    EXPECT_EQ(error_where("H-2\n"), "bad-value 1:1");
}

TEST(BlockErrors, TwoCodesThatBothUseAxisWords) {
    Diagnostic d = error_of("G1 G92 X0 F1\n");
    EXPECT_EQ(where(d), "modal-conflict 1:1");
    EXPECT_EQ(d.message, "two G codes in this block both use the axis words");
    EXPECT_EQ(error_where("G10 L2 P1 G0 X1\n"), "modal-conflict 1:11");
    moves_of("G28 G0 X0\n");  // Fanuc: the G0 only sets the mode, G28 takes the axis words
    EXPECT_EQ(error_where("G28 G2 X0 I1 F1\n"), "modal-conflict 1:5");
    EXPECT_EQ(error_where("G52 G1 X0 F1\n"), "modal-conflict 1:5");
    moves_of("G1 G28 F1\n");  // no axis words: no conflict
}

// ---- unused words -------------------------------------------------------------------------

TEST(UnusedWords, AxisWordsUnderG80InTheLinuxCncDialect) {
    // G80 is a motion mode of its own in RS-274/NGC; in the Fanuc dialect it is group 09 and the
    // group-01 mode moves the axes (fanuc_groups_test.cpp).
    const MachineConfig ngc = linuxcnc_mill();
    Diagnostic d = error_of("G80 X1\n", ngc);
    EXPECT_EQ(where(d), "unused-word 1:5");
    EXPECT_EQ(d.message, "X word with no motion mode to use it (G80 is active)");
    EXPECT_EQ(error_where("G80\nG90 Z1\n", ngc), "unused-word 2:5");
}

TEST(UnusedWords, AxisWordsWithG4) {
    Diagnostic d = error_of("G4 P100 X1\n");
    EXPECT_EQ(where(d), "unused-word 1:9");
    EXPECT_EQ(d.message, "G4 takes no axis words (X given)");
    EXPECT_EQ(error_where("G1 X1 F1\nG4 X1 Y1\n"), "unused-word 2:7");
    EXPECT_EQ(error_where("G4 Z1\n"), "unused-word 1:4");
}

TEST(UnusedWords, CentreOffsetsWithoutArc) {
    Diagnostic d = error_of("G1 X1 I1 F1\n");
    EXPECT_EQ(where(d), "unused-word 1:7");
    EXPECT_EQ(d.message, "I word with no G2/G3 to use it");
    EXPECT_EQ(error_where("G0 X1 J1\n"), "unused-word 1:7");
    EXPECT_EQ(error_where("G1 X1 K1 F1\n"), "unused-word 1:7");
    EXPECT_EQ(error_where("G2 X2 I1 F1\nG80 I1\n", linuxcnc_mill()), "unused-word 2:5");
    EXPECT_EQ(error_where("G2 G4 P1 I1\n"), "unused-word 1:10");
    EXPECT_EQ(error_where("G33 Z-1 K1\nG33 Z-2 I1 K1\n"), "unused-word 2:9");
}

TEST(UnusedWords, RWithoutArc) {
    Diagnostic d = error_of("G1 X1 R1 F1\n");
    EXPECT_EQ(where(d), "unused-word 1:7");
    EXPECT_EQ(d.message, "R word with no G2/G3, drilling cycle or G10 L1-L13 to use it");
}

TEST(UnusedWords, EWithoutThread) {
    Diagnostic d = error_of("G1 X1 E1 F1\n");
    EXPECT_EQ(where(d), "unused-word 1:7");
    EXPECT_EQ(d.message, "E word with no G32/G33 to use it");
}

TEST(UnusedWords, PWithoutG4G10OrG64) {
    Diagnostic d = error_of("G1 X1 P1 F1\n");
    EXPECT_EQ(where(d), "unused-word 1:7");
    EXPECT_EQ(d.message, "P word with no G4, G10, G64 or drilling cycle to use it");
    EXPECT_EQ(error_where("G61 P1\n"), "unused-word 1:5");
    EXPECT_EQ(error_where("G64 P0.1\nP0.2\n"), "unused-word 2:1") << "G64 P is not modal as a word";
    EXPECT_EQ(error_where("G2 X10 R5 P2 F1\n"), "unused-word 1:11") << "no multi-turn P on arcs";
}

TEST(UnusedWords, QWithoutG64) {
    Diagnostic d = error_of("G1 X1 Q1 F1\n");
    EXPECT_EQ(where(d), "unused-word 1:7");
    EXPECT_EQ(d.message, "Q word with no G64, thread or drilling cycle to use it");
}

TEST(UnusedWords, LWithoutG10) {
    Diagnostic d = error_of("G0 X1 L2\n");
    EXPECT_EQ(where(d), "unused-word 1:7");
    EXPECT_EQ(d.message, "L word with no G10 or drilling cycle to use it");
}

// ---- arcs in the wrong plane ----------------------------------------------------------------

TEST(BlockErrors, CentreOffsetOutsideTheActivePlane) {
    Diagnostic d = error_of("G17 G2 X1 K1 F1\n");
    EXPECT_EQ(where(d), "bad-arc 1:11");
    EXPECT_EQ(d.message, "K is not a centre offset in the active plane");
    EXPECT_EQ(error_where("G18 G2 X1 J1 F1\n"), "bad-arc 1:11");
    EXPECT_EQ(error_where("G19\nG3 Y1 I1 F1\n"), "bad-arc 2:7");
}

TEST(BlockErrors, ArcWithBothRAndCentreOffset) {
    Diagnostic d = error_of("G2 X10 R5 I5 F1\n");
    EXPECT_EQ(where(d), "bad-arc 1:11");
    EXPECT_EQ(d.message, "arc with both R and I/J/K");
    EXPECT_EQ(error_where("G2 X10 J0 R5 F1\n"), "bad-arc 1:8");
}

// ---- G10 ----------------------------------------------------------------------------------

TEST(G10Errors, NeedsL2OrL20) {
    Diagnostic d = error_of("G0 X1\nG10 P1 X1\n");
    EXPECT_EQ(where(d), "bad-g10 2:1");
    EXPECT_EQ(d.message, "G10 needs L1, L2, L10-L13 or L20");
    EXPECT_EQ(error_where("X1 G10 L7 P1\n"), "bad-g10 1:4");
    EXPECT_EQ(error_where("G10 L2.5 P1 X1\n"), "bad-g10 1:1");
}

TEST(G10Errors, NeedsPZeroToSix) {
    Diagnostic d = error_of("G10 L2 X1\n");
    EXPECT_EQ(where(d), "bad-g10 1:1");
    EXPECT_EQ(d.message, "G10 needs P0 (active system) or P1 to P6 (G54 to G59)");
    EXPECT_EQ(error_where("G10 L2 P7 X1\n"), "bad-g10 1:8");
    EXPECT_EQ(error_where("G10 L20 P1.5 X1\n"), "bad-g10 1:9");
    EXPECT_EQ(error_where("G10 L2 P-1 X1\n"), "bad-g10 1:8");
}

}  // namespace
}  // namespace nckit::test
