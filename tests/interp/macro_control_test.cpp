// Custom Macro B control flow: GOTO (forward, then from the start; computed), IF GOTO, IF THEN,
// WHILE/DO/END loops with their numbering rules and alarms, and the runaway block budget.
#include <gtest/gtest.h>

#include "macro_support.hpp"

namespace nckit::test {
namespace {

InterpreterOptions budget(std::int64_t max_blocks) {
    InterpreterOptions options;
    options.max_blocks = max_blocks;
    return options;
}

// ---- GOTO and IF ---------------------------------------------------------------------------

TEST(MacroControl, GotoForward) {
    EXPECT_EQ(xs("GOTO 10\nG1 X1 F100\nN10 G1 X2 F100\n"), (std::vector<double>{2}));
}

TEST(MacroControl, GotoBackwardMakesALoop) {
    EXPECT_EQ(xs("#1=0\nN5 #1=#1+1\nG1 X#1 F100\nIF [#1 LT 3] GOTO 5\nG1 Y1\n"), (std::vector<double>{1, 2, 3, 3}));
}

TEST(MacroControl, GotoSearchesForwardFirstThenFromTheStart) {
    const char* program =
        "#1=0\n"
        "N7 G1 X1 F100\n"
        "#1=#1+1\n"
        "IF [#1 EQ 2] GOTO 9\n"
        "GOTO 7\n"  // forward: the N7 below
        "N7 G1 X7\n"
        "GOTO 7\n"  // nothing forward: the N7 at the top
        "N9 G1 X9\n";
    EXPECT_EQ(xs(program), (std::vector<double>{1, 7, 1, 9}));
}

TEST(MacroControl, ComputedGoto) {
    EXPECT_EQ(xs("#10=20\nGOTO#10\nN10 G1 X1 F100\nN20 G1 X2 F100\n"), (std::vector<double>{2}));
    EXPECT_EQ(xs("#10=1\nGOTO[#10*10+0.4]\nN10 G1 X1 F100\nN20 G1 X2 F100\n"), (std::vector<double>{1, 2}));
}

TEST(MacroControl, GotoFindsBlockDeleteAndBlanksInTheSequenceNumber) {
    EXPECT_EQ(xs("GOTO 12\nG1 X1 F100\n/N 1 2 G1 X2 F100\n"), (std::vector<double>{2}));
}

TEST(MacroControl, IfGotoJumpsOnlyWhenTheConditionHolds) {
    EXPECT_EQ(xs("#1=1\nIF [#1 EQ 1] GOTO 5\nG1 X1 F100\nN5 G1 X2 F100\n"), (std::vector<double>{2}));
    EXPECT_EQ(xs("#1=2\nIF [#1 EQ 1] GOTO 5\nG1 X1 F100\nN5 G1 X2 F100\n"), (std::vector<double>{1, 2}));
}

TEST(MacroControl, IfThenAssignsOnlyWhenTheConditionHolds) {
    EXPECT_EQ(texts("#1=5\nIF [#1 GT 3] THEN #2=1\nIF [#1 LT 3] THEN #3=1\nG1 X#2 Y#3 Z1 F100\n", wide_mill()),
              (Texts{"G1 X1.0000 Y0.0000 Z1.0000 F100.0000"}));
}

TEST(MacroControl, MissingGotoTargetIsAlarm128) {
    EXPECT_EQ(alarm_of("G1 X1 F100\nGOTO 99\n"), "128 2:6");
    EXPECT_EQ(alarm_of("IF [1 EQ 1] GOTO 5\n"), "128 1:18");
    EXPECT_EQ(alarm_of("GOTO 0\n"), "128 1:6");
    EXPECT_EQ(alarm_of("GOTO 100000\n"), "128 1:6");
    EXPECT_EQ(alarm_of("GOTO #5\n"), "128 1:6");  // vacant
    Diagnostic d = error_of("GOTO 99\n", wide_mill());
    EXPECT_EQ(d.message, "sequence number N99 not found");
}

TEST(MacroControl, GotoStaysInsideItsProgram) {
    // N5 of another program, or of the caller, is not a target.
    EXPECT_EQ(alarm_of("M98 P100\nM30\nO100\nGOTO 5\nM99\nO200\nN5 M99\n"), "128 4:6");
    EXPECT_EQ(alarm_of("N5 M98 P100\nM30\nO100\nGOTO 5\nM99\n"), "128 4:6");
}

// ---- WHILE / DO / END ----------------------------------------------------------------------

TEST(MacroControl, WhileLoop) {
    EXPECT_EQ(xs("#1=0\nWHILE [#1 LT 3] DO1\n#1=#1+1\nG1 X#1 F100\nEND1\nG1 X9\n"), (std::vector<double>{1, 2, 3, 9}));
}

TEST(MacroControl, WhileThatNeverHoldsSkipsItsBody) {
    EXPECT_EQ(xs("WHILE [1 GT 2] DO2\nG1 X1 F100\nWHILE [1] DO3\nEND3\nEND2\nG1 X2 F100\n"), (std::vector<double>{2}));
}

TEST(MacroControl, LoopsNestThreeDeep) {
    const char* program =
        "#1=0\n"
        "WHILE [#1 LT 2] DO1\n"
        "#2=0\n"
        "WHILE [#2 LT 2] DO2\n"
        "#3=0\n"
        "WHILE [#3 LT 2] DO3\n"
        "G1 X[#1*100+#2*10+#3] F100\n"
        "#3=#3+1\n"
        "END3\n"
        "#2=#2+1\n"
        "END2\n"
        "#1=#1+1\n"
        "END1\n";
    EXPECT_EQ(xs(program), (std::vector<double>{0, 1, 10, 11, 100, 101, 110, 111}));
}

TEST(MacroControl, SameLoopNumberForLoopsThatDoNotOverlap) {
    const char* program =
        "#1=0\nWHILE [#1 LT 2] DO1\n#1=#1+1\nG1 X#1 F100\nEND1\n"
        "WHILE [#1 LT 4] DO1\n#1=#1+1\nG1 X[#1*10]\nEND1\n";
    EXPECT_EQ(xs(program), (std::vector<double>{1, 2, 30, 40}));
}

TEST(MacroControl, InnerLoopNumberReusedInsideAnother) {
    // Two DO2 loops one after the other inside DO1.
    const char* program =
        "#1=0\nWHILE [#1 LT 2] DO1\n#1=#1+1\n"
        "#2=0\nWHILE [#2 LT 1] DO2\n#2=#2+1\nG1 X#1 F100\nEND2\n"
        "#2=0\nWHILE [#2 LT 1] DO2\n#2=#2+1\nG1 X[-#1]\nEND2\n"
        "END1\n";
    EXPECT_EQ(xs(program), (std::vector<double>{1, -1, 2, -2}));
}

TEST(MacroControl, DoWithoutWhileLoopsUntilAGotoLeaves) {
    const char* program = "#1=0\nDO1\n#1=#1+1\nIF [#1 EQ 3] GOTO 10\nG1 X#1 F100\nEND1\nN10 G1 X9\n";
    EXPECT_EQ(xs(program), (std::vector<double>{1, 2, 9}));
}

TEST(MacroControl, JumpingOutOfALoopEndsIt) {
    // After leaving DO1 by GOTO, DO1 may start again, and a new DO2 / DO3 may nest in it.
    const char* program =
        "#1=0\n"
        "WHILE [1] DO1\n"
        "WHILE [1] DO2\n"
        "#1=#1+1\n"
        "IF [#1 GE 2] GOTO 10\n"
        "END2\n"
        "END1\n"
        "N10 G1 X#1 F100\n"
        "WHILE [#1 LT 4] DO1\nWHILE [#1 LT 4] DO2\nWHILE [#1 LT 4] DO3\n#1=#1+1\nEND3\nEND2\nEND1\n"
        "G1 X#1\n";
    EXPECT_EQ(xs(program), (std::vector<double>{2, 4}));
}

TEST(MacroControl, JumpingBackBeforeALoopLeavesIt) {
    const char* program =
        "#1=0\n"
        "N5 WHILE [1] DO1\n"
        "#1=#1+1\n"
        "G1 X#1 F100\n"
        "IF [#1 LT 3] GOTO 5\n"  // back to the DO block: no "DO1 inside DO1" alarm
        "GOTO 10\n"
        "END1\n"
        "N10 G1 X9\n";
    EXPECT_EQ(xs(program), (std::vector<double>{1, 2, 3, 9}));
}

TEST(MacroControl, OverlappingLoopsAreAlarm126) {
    EXPECT_EQ(alarm_of("#1=0\nWHILE [#1 LT 2] DO1\nWHILE [#1 LT 2] DO2\n#1=#1+1\nEND1\nEND2\n"), "126 5:1");
}

TEST(MacroControl, SameLoopNumberNestedIsAlarm126) {
    EXPECT_EQ(alarm_of("WHILE [1] DO1\nN20 WHILE [1] DO1\nEND1\nEND1\n"), "126 2:5");
}

TEST(MacroControl, IllegalLoopNumberIsAlarm126) {
    EXPECT_EQ(alarm_of("G1 X1 F100\nWHILE [1] DO4\nEND4\n"), "126 2:13");
    EXPECT_EQ(alarm_of("END0\n"), "126 1:4");
}

TEST(MacroControl, EndWithoutDoIsAlarm124) {
    EXPECT_EQ(alarm_of("G1 X1 F100\nEND1\n"), "124 2:1");
    EXPECT_EQ(alarm_of("WHILE [1] DO1\nGOTO 5\nEND1\nN5 END1\n"), "124 4:4");
    // Jumping into a loop from outside reaches its END without its DO.
    EXPECT_EQ(alarm_of("GOTO 5\nWHILE [1] DO1\nN5 G1 X1 F100\nEND1\n"), "124 4:1");
}

TEST(MacroControl, WhileWithoutEndIsAlarm124) {
    EXPECT_EQ(alarm_of("WHILE [0] DO1\nG1 X1 F100\n"), "124 1:1");
    EXPECT_EQ(alarm_of("WHILE [0] DO1\nEND2\n"), "124 1:1");
    // When the condition holds, the body runs and the program ends inside the loop: at the end
    // of the file, at the next O program, or at the closing '%'.
    RunResult r = run_program("#1=0\nN7 WHILE [#1 LT 2] DO1\n#1=#1+1\nG1 X1 F100\n", wide_mill());
    ASSERT_TRUE(r.error.has_value());
    EXPECT_EQ(format_diagnostic(*r.error), "test.ngc:2:4: error: alarm 124: WHILE ... DO1 has no END1");
    EXPECT_EQ(r.moves.size(), 1U);
    EXPECT_EQ(alarm_of("DO2\nG1 X1 F100\nO100\nEND2\nM99\n"), "124 1:1");
    EXPECT_EQ(alarm_of("%\nDO3\nG1 X1 F100\n%\n"), "124 2:1");
    // A program that ends by M30 inside a loop ends normally.
    EXPECT_EQ(xs("WHILE [1] DO1\nG1 X1 F100\nM30\nEND1\n"), (std::vector<double>{1}));
}

TEST(MacroControl, EndInTheNextProgramDoesNotCloseALoop) {
    EXPECT_EQ(alarm_of("M98 P100\nM30\nO100\nWHILE [0] DO1\nM99\nO200\nEND1\nM99\n"), "124 4:1");
}

TEST(MacroControl, LoopsBelongToTheirProgramLevel) {
    // A loop in a subprogram does not see the caller's DO1, and the caller's loop goes on after.
    const char* program =
        "#1=0\n"
        "WHILE [#1 LT 2] DO1\n"
        "#1=#1+1\n"
        "M98 P100\n"
        "END1\n"
        "M30\n"
        "O100\n"
        "#2=0\n"
        "WHILE [#2 LT 2] DO1\n"
        "#2=#2+1\n"
        "G1 X[#1*10+#2] F100\n"
        "END1\n"
        "M99\n";
    EXPECT_EQ(xs(program), (std::vector<double>{11, 12, 21, 22}));
}

// ---- block budget --------------------------------------------------------------------------

TEST(MacroControl, RunawayLoopStopsWithAlarm100) {
    RunResult r = run_program("DO1\nG1 X1 F100\nEND1\n", wide_mill(), budget(50));
    ASSERT_TRUE(r.error.has_value());
    EXPECT_EQ(r.error->alarm, 100);
    EXPECT_EQ(where(*r.error), "macro-alarm 1:1");
    EXPECT_EQ(r.moves.size(), 17U);  // blocks 1, 4, .. 49 of the 50 counted are the G1
}

TEST(MacroControl, BackwardJumpStartsCounting) {
    EXPECT_EQ(alarm_of("#1=0\nN1 #1=#1+1\nIF [#1 LT 1000] GOTO 1\n", budget(50)), "100 2:1");
    EXPECT_EQ(xs("#1=0\nN1 #1=#1+1\nIF [#1 LT 10] GOTO 1\nG1 X#1 F100\n", budget(100)), (std::vector<double>{10}));
}

TEST(MacroControl, ProgramWithoutJumpsIsNotLimitedByTheBudget) {
    std::string program = "G1 F100\n";
    for (int i = 1; i <= 100; ++i) program += "#1=" + std::to_string(i) + "\nG1 X#1\n";
    program += "GOTO 5\nG1 X0\nN5 G1 X-1\n";  // a forward jump does not count either
    std::vector<double> x = xs(program, budget(10));
    ASSERT_EQ(x.size(), 101U);
    EXPECT_EQ(x[99], 100.0);
    EXPECT_EQ(x[100], -1.0);
}

TEST(MacroControl, MainProgramM99RestartsUntilTheBudget) {
    RunResult r = run_program("G1 X1 F100\nM99\n", wide_mill(), budget(10));
    ASSERT_TRUE(r.error.has_value());
    EXPECT_EQ(r.error->alarm, 100);
    EXPECT_EQ(r.error->location.line, 1U);
    EXPECT_EQ(r.moves.size(), 6U);  // the first pass, then 5 counted G1 blocks
}

TEST(MacroControl, CalledProgramsCount) {
    EXPECT_EQ(alarm_of("M98 P100 L20\nM30\nO100\nG1 X1 F100\nM99\n", budget(25)), "100 5:1");
    EXPECT_EQ(xs("M98 P100 L10\nM30\nO100\nG1 X1 F100\nM99\n", budget(20)).size(), 10U);
}

TEST(MacroControl, StatementsInEveryPlaceABlockMayBe) {
    // After N, behind block delete, in a loop, in a subprogram.
    InterpreterOptions skip;
    skip.block_delete = true;
    EXPECT_EQ(xs("N1 #1=1\n/#1=2\nG1 X#1 F100\n", skip), (std::vector<double>{1}));
    EXPECT_EQ(xs("N1 #1=1\n/#1=2\nG1 X#1 F100\n"), (std::vector<double>{2}));
    EXPECT_EQ(xs("N1 #1=1 (ONE)\nN2 IF [#1 EQ 1] THEN #1=3 ; three\nG1 X#1 F100\n"), (std::vector<double>{3}));
}

}  // namespace
}  // namespace nckit::test
