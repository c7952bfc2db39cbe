// The interpreter as a stream: program end (M2, M30, '%', end of file), block delete, and what
// happens after an error.
#include <gtest/gtest.h>

#include "interp_support.hpp"

namespace nckit::test {
namespace {

Interpreter interpreter_for(std::string program, InterpreterOptions options = {}) {
    return Interpreter(default_mill(), ProgramSource::from_string(std::move(program), "test.ngc"), options);
}

TEST(ProgramEnd, M30EndsAndNothingAfterItRuns) {
    RunResult r = run_program("G0 X1\nM30\nG0 X2\nG1 X$\n");
    EXPECT_FALSE(r.error);
    ASSERT_EQ(r.moves.size(), 2U);
    const Io& end = std::get<Io>(r.moves[1].what);
    EXPECT_EQ(end.number, 30);
    EXPECT_TRUE(end.waits);
}

TEST(ProgramEnd, M2EndsLikeM30) {
    RunResult r = run_program("G0 X1\nM2\nG0 X2\n");
    EXPECT_FALSE(r.error);
    EXPECT_EQ(r.moves.size(), 2U);
}

TEST(ProgramEnd, MovesOfTheLastBlockGoOutFirst) {
    EXPECT_EQ(texts("G0 X1 M30\nG0 X2\n"), (Texts{"G0 X1.0000 Y0.0000 Z0.0000", "M30"}));
}

TEST(ProgramEnd, M0AndM1DoNotEnd) {
    EXPECT_EQ(texts("M0\nM1\nG0 X1\n"), (Texts{"M0", "M1", "G0 X1.0000 Y0.0000 Z0.0000"}));
}

TEST(ProgramEnd, EndOfFileEnds) {
    RunResult r = run_program("G0 X1");
    EXPECT_FALSE(r.error);
    EXPECT_EQ(r.moves.size(), 1U);
}

TEST(ProgramEnd, EmptyProgramEndsAtOnce) {
    Interpreter interpreter = interpreter_for("");
    EXPECT_TRUE(std::holds_alternative<ProgramEnd>(interpreter.next()));
}

TEST(ProgramEnd, EndRepeats) {
    Interpreter interpreter = interpreter_for("G0 X1\nM30\n");
    EXPECT_TRUE(std::holds_alternative<Move>(interpreter.next()));
    EXPECT_TRUE(std::holds_alternative<Move>(interpreter.next()));
    for (int i = 0; i < 3; ++i) EXPECT_TRUE(std::holds_alternative<ProgramEnd>(interpreter.next()));
}

TEST(ProgramEnd, SecondPercentEndsTheTape) {
    EXPECT_EQ(texts("%\nO100 (part)\nG0 X1\n%\nG0 X2\n"), (Texts{"G0 X1.0000 Y0.0000 Z0.0000"}));
}

TEST(ProgramEnd, PercentAfterCommentsStillOpensTheTape) {
    EXPECT_EQ(texts("(header)\n\n%\nG0 X1\n%\nG0 X2\n"), (Texts{"G0 X1.0000 Y0.0000 Z0.0000"}));
}

TEST(ProgramEnd, PercentAfterABlockEndsTheProgram) {
    EXPECT_EQ(texts("G0 X1\n%\nG0 X2\n"), (Texts{"G0 X1.0000 Y0.0000 Z0.0000"}));
}

TEST(ProgramEnd, ATitleBeforeTheTapeStartIsTheLeader) {
    // Fanuc's label skip: a first line that is no block, with the tape start '%' after it, is
    // the tape's leader (the title of tests/real_lathe/37..42); the program runs from the '%',
    // with a warning at line 1.
    std::vector<Diagnostic> warnings;
    InterpreterOptions options;
    options.on_warning = [&](const Diagnostic& d) { warnings.push_back(d); };
    EXPECT_EQ(texts("PAWN 30\n%\nO0002\nG0 X1\nM30\n%\n", default_mill(), options),
              (Texts{"G0 X1.0000 Y0.0000 Z0.0000", "M30"}));
    ASSERT_EQ(warnings.size(), 1U);
    EXPECT_EQ(where(warnings[0]), "tape-leader 1:1");
    EXPECT_EQ(warnings[0].severity, Severity::warning);
    // Bytes that are no G-code at all (a title in another script) are a leader as well, and
    // '%' with its label on the line (`%O8010;`) still starts the tape.
    EXPECT_EQ(texts("\xe5\x85\xb5 30\n%O8010;\nG0 X1;\n"), (Texts{"G0 X1.0000 Y0.0000 Z0.0000"}));
    // Without the '%' after it, such a line is an error as before, at line 1.
    EXPECT_EQ(error_where("PAWN 30\nG0 X1\n"), "syntax 1:1");
    // A first line that reads as a block is a block: the '%' after it ends the program.
    EXPECT_EQ(texts("G0 X1\n%\nG0 X2\n"), (Texts{"G0 X1.0000 Y0.0000 Z0.0000"}));
}

InterpreterOptions block_delete_on() {
    InterpreterOptions options;
    options.block_delete = true;
    return options;
}

TEST(BlockDelete, SlashBlocksRunWhenTheSwitchIsOff) {
    EXPECT_EQ(texts("/G0 X5\nG0 X1\n"), (Texts{"G0 X5.0000 Y0.0000 Z0.0000", "G0 X1.0000 Y0.0000 Z0.0000"}));
}

TEST(BlockDelete, SwitchOnSkipsSlashBlocks) {
    EXPECT_EQ(texts("/G0 X5\nG0 X1\n / G0 X6\n", default_mill(), block_delete_on()),
              (Texts{"G0 X1.0000 Y0.0000 Z0.0000"}));
}

TEST(BlockDelete, SkippedBlockChangesNoMode) {
    EXPECT_EQ(texts("/G91\n/G20\nG0 X1\nX2\n", default_mill(), block_delete_on()),
              (Texts{"G0 X1.0000 Y0.0000 Z0.0000", "G0 X2.0000 Y0.0000 Z0.0000"}));
}

TEST(BlockDelete, SkippedBlockIsNotInterpreted) {
    // Only the parser sees a skipped block: unknown codes in it do not stop the program.
    EXPECT_EQ(texts("/G12 X1\nG0 X1\n", default_mill(), block_delete_on()), (Texts{"G0 X1.0000 Y0.0000 Z0.0000"}));
    EXPECT_EQ(error_where("/G12 X1\nG0 X1\n"), "unsupported-gcode 1:2");
}

TEST(BlockDelete, SkippedBlockIsNotEvenParsed) {
    // A deleted block is not part of the program: a syntax error in it cannot stop the machine.
    EXPECT_EQ(texts("/G1 X$\nG0 X1\n", default_mill(), block_delete_on()), (Texts{"G0 X1.0000 Y0.0000 Z0.0000"}));
    EXPECT_EQ(error_where("/G1 X$\nG0 X1\n"), "syntax 1:5");
}

TEST(BlockDelete, SkippedM30DoesNotEnd) {
    EXPECT_EQ(texts("/M30\nG0 X1\n", default_mill(), block_delete_on()), (Texts{"G0 X1.0000 Y0.0000 Z0.0000"}));
}

// ---- after an error ---------------------------------------------------------------------------

TEST(AfterError, EarlierMovesComeFirstThenTheErrorRepeats) {
    Interpreter interpreter = interpreter_for("G0 X1\nG0 X2\nG5\nG0 X3\n");
    EXPECT_TRUE(std::holds_alternative<Move>(interpreter.next()));
    EXPECT_TRUE(std::holds_alternative<Move>(interpreter.next()));
    for (int i = 0; i < 3; ++i) {
        InterpResult r = interpreter.next();
        ASSERT_TRUE(std::holds_alternative<Diagnostic>(r));
        EXPECT_EQ(where(std::get<Diagnostic>(r)), "unsupported-gcode 3:1");
    }
}

TEST(AfterError, ErrorInABlockLeavesNoPartialMoves) {
    // S, T, M3 and M8 would come before the move that leaves the travel.
    RunResult r = run_program("G0 X1\nS1000 T3 M3 M8 G1 X600 F100\n");
    ASSERT_TRUE(r.error);
    EXPECT_EQ(where(*r.error), "travel-limit 2:19");
    ASSERT_EQ(r.moves.size(), 1U);
    EXPECT_EQ(r.moves[0].where.line, 1U);
}

TEST(AfterError, G28ErrorLeavesNoIntermediateMove) {
    MachineConfig m = default_mill();
    m.axes[2].home = 600;  // beyond the travel: the second leg fails
    RunResult r = run_program("G28 Z10\n", m);
    ASSERT_TRUE(r.error);
    EXPECT_EQ(where(*r.error), "travel-limit 1:5");
    EXPECT_TRUE(r.moves.empty());
}

TEST(AfterError, DwellBeforeABadMoveIsNotSent) {
    RunResult r = run_program("M8 G4 P100\nG1 X1\n");
    ASSERT_TRUE(r.error);
    EXPECT_EQ(r.moves.size(), 2U) << "the first block is whole";
    RunResult same_block = run_program("G4 P100 S9000\n");
    ASSERT_TRUE(same_block.error);
    EXPECT_TRUE(same_block.moves.empty());
}

TEST(AfterError, SourceErrorRepeats) {
    Interpreter interpreter = interpreter_for("(" + std::string(ProgramSource::max_line_bytes + 1, 'x') + ")\n");
    for (int i = 0; i < 2; ++i) {
        InterpResult r = interpreter.next();
        ASSERT_TRUE(std::holds_alternative<Diagnostic>(r));
        EXPECT_EQ(std::get<Diagnostic>(r).code, "line-too-long");
    }
}

TEST(Interpreter, KeepsItsMachine) {
    Interpreter interpreter(lathe(), ProgramSource::from_string("", "x"));
    EXPECT_EQ(interpreter.machine().name, "test-lathe");
    Interpreter moved = std::move(interpreter);
    EXPECT_EQ(moved.machine().name, "test-lathe");
    EXPECT_TRUE(std::holds_alternative<ProgramEnd>(moved.next()));
}

}  // namespace
}  // namespace nckit::test
