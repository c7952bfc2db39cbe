// Fanuc's modal-group rules as shop programs rely on them: of two G codes of one group in a
// block the last one is valid (with a warning naming the ignored one), and the drilling cycles
// are group 09, so G80 brings back the group-01 motion that was modal before the cycle. The
// LinuxCNC dialect keeps RS-274/NGC's rules (block_errors_test.cpp).
#include <string>

#include <gtest/gtest.h>

#include "interp_support.hpp"

namespace nckit::test {
namespace {

//! The warnings a program gives, as `code LINE:COL message`.
std::vector<std::string> warnings_of(std::string_view program, const MachineConfig& machine = default_mill()) {
    std::vector<std::string> out;
    InterpreterOptions options;
    options.on_warning = [&](const Diagnostic& d) {
        EXPECT_EQ(d.severity, Severity::warning);
        out.push_back(where(d) + " " + d.message);
    };
    moves_of(program, machine, options);
    return out;
}

// ---- two codes of one group: the last one is valid -----------------------------------------

TEST(FanucGroups, LastDistanceCodeIsValid) {
    // `G91 G28 X0 Y0 Z100. G90` as shop programs write it: G90 is valid, so the words are absolute.
    EXPECT_EQ(texts("G0 X10 Y10 Z10\nG91 X5 G90\n"), texts("G0 X10 Y10 Z10\nG90 X5\n"));
    EXPECT_EQ(texts("G0 X10 Y10 Z10\nG90 X5 G91\n"), texts("G0 X10 Y10 Z10\nG91 X5\n"));
}

TEST(FanucGroups, LastMotionCodeIsValid) {
    EXPECT_EQ(texts("G0 G1 X1 F100\n"), texts("G1 X1 F100\n"));
    EXPECT_EQ(texts("G1 G0 X5 F100\n"), texts("G0 X5 F100\n"));
    EXPECT_EQ(texts("G17 G18 G2 X10 Z0 I5 K0 F100\n"), texts("G18 G2 X10 Z0 I5 K0 F100\n"));
    EXPECT_EQ(texts("G20 G21 G0 X1\n"), texts("G21 G0 X1\n"));
}

TEST(FanucGroups, EachIgnoredCodeIsAWarningAtItsColumn) {
    Texts expected{
        "gcode-overridden 2:1 G91 is ignored: G90 of the same modal group, written later in the block, "
        "is valid"};
    EXPECT_EQ(warnings_of("G0 X1\nG91 G28 Z0 G90\n"), expected);
    EXPECT_EQ(warnings_of("G0 G1 G0 X1 F100\n").size(), 2u);
    EXPECT_TRUE(warnings_of("G0 G17 G40 G49 G80 G90 X1\n").empty());
}

TEST(FanucGroups, ABlockRunInALoopWarnsOnce) {
    EXPECT_EQ(warnings_of("#1=0\nWHILE [#1 LT 5] DO1\nG91 G1 X1 G90 F100\n#1=#1+1\nEND1\n").size(), 1u);
}

TEST(FanucGroups, TwoOneShotCodesStayAnError) {
    EXPECT_EQ(error_where("G28 G92 X0\n"), "modal-conflict 1:5");
    EXPECT_EQ(error_where("G4 P1 G53 X0\n"), "modal-conflict 1:7");
}

TEST(FanucGroups, MCodesKeepTheirRules) {
    EXPECT_EQ(error_where("M3 M4\n"), "modal-conflict 1:4");
    EXPECT_EQ(error_where("M8 M9\n"), "modal-conflict 1:4");
}

// ---- drilling cycles are group 09 ---------------------------------------------------------

TEST(FanucGroups, G80BringsBackTheRapidModeOfBeforeTheCycle) {
    // `Z90.5` after G80 moves Z at rapid: G0 was the group-01 code when the cycle began.
    Texts moves = texts("G0 X0 Y0 Z50\nG99 G81 X5 Y5 Z-5 R2 F100\nG80\nZ90.5\n");
    ASSERT_FALSE(moves.empty());
    EXPECT_EQ(moves.back(), "G0 X5.0000 Y5.0000 Z90.5000");
    EXPECT_EQ(moves[moves.size() - 2], "G0 X5.0000 Y5.0000 Z2.0000");  // the hole's return to R
}

TEST(FanucGroups, G80BringsBackTheFeedModeOfBeforeTheCycle) {
    Texts moves = texts("G0 X0 Y0 Z50\nG1 Z40 F200\nG98 G81 X5 Y5 Z-5 R2 F100\nG80 X10\n");
    ASSERT_FALSE(moves.empty());
    EXPECT_EQ(moves.back(), "G1 X10.0000 Y5.0000 Z40.0000 F100.0000");
}

TEST(FanucGroups, G80WithoutACycleLeavesTheMotionModeAlone) {
    // A safe-start line without a motion code: the group-01 code stays modal.
    EXPECT_EQ(texts("G1 X1 F100\nG17 G40 G80 G90\nX2\n"), texts("G1 X1 F100\nX2\n"));
}

TEST(FanucGroups, MotionCodeBesideG80CancelsTheCycleAndMoves) {
    // Fusion 360 posts: `G0 Z15 G80` (or G80 first) ends the cycle with a rapid.
    const std::string drill = "G0 X0 Y0 Z50\nG98 G81 X5 Y5 Z-5 R2 F100\n";
    Texts moves = texts(drill + "G0 Z15 G80\nX20\n");
    ASSERT_GE(moves.size(), 2u);
    EXPECT_EQ(moves[moves.size() - 2], "G0 X5.0000 Y5.0000 Z15.0000");
    EXPECT_EQ(moves.back(), "G0 X20.0000 Y5.0000 Z15.0000");
    EXPECT_EQ(texts(drill + "G80 G0 Z15\nX20\n"), moves);
    EXPECT_TRUE(warnings_of(drill + "G0 Z15 G80\n").empty());
}

TEST(FanucGroups, MotionCodeBesideACycleCodeWinsWhereverWritten) {
    // A group-01 code cancels the cycle, so the cycle code of the same block is ignored.
    EXPECT_EQ(texts("G0 Z50\nG0 G81 X5 Z40\n"), texts("G0 Z50\nG0 X5 Z40\n"));
    EXPECT_EQ(texts("G0 Z50\nG81 G0 X5 Z40\n"), texts("G0 Z50\nG0 X5 Z40\n"));
    Texts expected{"gcode-overridden 2:4 G81 is ignored: G0 in the same block cancels the drilling cycle"};
    EXPECT_EQ(warnings_of("G0 Z50\nG0 G81 X5 Z40\n"), expected);
}

TEST(FanucGroups, LastOfG80AndACycleCodeIsValid) {
    const std::string start = "G0 X0 Y0 Z50\n";
    EXPECT_EQ(texts(start + "G81 G80 X5\n"), texts(start + "X5\n"));
    EXPECT_EQ(texts(start + "G80 G81 X5 Z-5 R2 F100\n"), texts(start + "G81 X5 Z-5 R2 F100\n"));
    EXPECT_EQ(texts(start + "G81 G82 X5 Z-5 R2 P500 F100\n"), texts(start + "G82 X5 Z-5 R2 P500 F100\n"));
}

TEST(FanucGroups, G1AfterTheCycleStillCancelsIt) {
    Texts moves = texts("G0 X0 Y0 Z50\nG81 X5 Y5 Z-5 R2 F100\nG1 X10\n");
    ASSERT_FALSE(moves.empty());
    EXPECT_EQ(moves.back(), "G1 X10.0000 Y5.0000 Z50.0000 F100.0000");
}

TEST(FanucGroups, LinuxCncDialectKeepsG80AsItsMotionMode) {
    const MachineConfig ngc = linuxcnc_mill();
    EXPECT_EQ(error_where("G0 X0 Y0 Z50\nG81 X5 Y5 Z-5 R2 F100\nG80\nZ90.5\n", ngc), "unused-word 4:1");
    EXPECT_EQ(error_where("G0 Z50\nG0 G81 X5 Z40\n", ngc), "modal-conflict 2:4");
}

TEST(FanucGroups, GroupOneVariableShowsTheModeOfBeforeTheCycle) {
    // #4001 is group 01, #4009 group 09: during a cycle G0 and G81.
    EXPECT_EQ(texts("G0 X0 Y0 Z50\nG81 X5 Y5 Z-5 R2 F100\n#100=#4001\n#101=#4009\nG80\nG1 X[#100+1] Y[#101]\n"),
              texts("G0 X0 Y0 Z50\nG81 X5 Y5 Z-5 R2 F100\nG80\nG1 X1 Y81\n"));
}

}  // namespace
}  // namespace nckit::test
