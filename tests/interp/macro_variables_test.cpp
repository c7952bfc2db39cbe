// Custom Macro B variables: #0, locals per call level, common, retained across runs through a
// file, indirect numbers, illegal numbers, and Fanuc's rules for vacant values.
#include <gtest/gtest.h>

#include "macro_support.hpp"

namespace nckit::test {
namespace {

//! 1 when `condition` holds after `setup`, 0 when not.
double holds(std::string_view setup, std::string_view condition) {
    std::optional<double> v = value_after(std::string(setup) + "\n#1=0\nIF [" + std::string(condition) + "] THEN #1=1");
    return v.value_or(-1);
}

// ---- kinds of variables --------------------------------------------------------------------

TEST(MacroVariables, NullVariableIsVacantAndReadOnly) {
    EXPECT_EQ(value_of("#0"), std::nullopt);
    EXPECT_EQ(alarm_of("G1 X1 F100\nN5 #0=1\n"), "116 2:4");
    EXPECT_EQ(alarm_of("#1=0\n#[#1]=5\n"), "116 2:1");
    Diagnostic d = error_of("#0=1\n", wide_mill());
    EXPECT_EQ(d.code, "macro-alarm");
}

TEST(MacroVariables, LocalCommonAndRetainedNumbersExist) {
    EXPECT_EQ(value_after("#33=4\n#1=#33"), 4.0);
    EXPECT_EQ(value_after("#100=5\n#1=#100"), 5.0);
    EXPECT_EQ(value_after("#199=6\n#1=#199"), 6.0);
    EXPECT_EQ(value_after("#499=6.5\n#1=#499"), 6.5);
    EXPECT_EQ(value_after("#500=7\n#1=#500"), 7.0);
    EXPECT_EQ(value_after("#999=8\n#1=#999"), 8.0);
}

TEST(MacroVariables, IllegalNumbersAreAlarm115) {
    EXPECT_EQ(alarm_of("#34=1\n"), "115 1:1");
    EXPECT_EQ(alarm_of("#99=1\n"), "115 1:1");
    EXPECT_EQ(alarm_of("#1=#34\n"), "115 1:4");
    EXPECT_EQ(alarm_of("#1=2+#50\n"), "115 1:6");
    EXPECT_EQ(alarm_of("#1200=1\n"), "115 1:1");  // past the interface signals #1000-#1199
    EXPECT_EQ(alarm_of("#1=#1200\n"), "115 1:4");
    EXPECT_EQ(alarm_of("#1000=1\n"), "116 1:1");  // an input: read-only
    EXPECT_EQ(alarm_of("#1=#[0-1]\n"), "115 1:4");
    EXPECT_EQ(alarm_of("G1 X#40 F100\n"), "115 1:5");
}

TEST(MacroVariables, ReadOnlySystemVariablesAreAlarm116) {
    EXPECT_EQ(alarm_of("#4001=1\n"), "116 1:1");
    EXPECT_EQ(alarm_of("#5001=1\n"), "116 1:1");
    EXPECT_EQ(alarm_of("#5221=#0\n"), "116 1:1");  // a system variable cannot be made vacant
}

TEST(MacroVariables, IndirectNumbers) {
    EXPECT_EQ(value_after("#101=7\n#2=1\n#1=#[#2+100]"), 7.0);
    EXPECT_EQ(value_after("#2=1\n#[#2+100]=9\n#1=#101"), 9.0);
    EXPECT_EQ(value_after("#3=4\n#1=#[2.6]"), 4.0);    // the number is rounded: #3
    EXPECT_EQ(value_after("#1=#[#5]"), std::nullopt);  // vacant names #0
    EXPECT_EQ(value_after("#2=3\n#3=102\n#102=11\n#1=#[#[#2]]"), 11.0);
}

// ---- call levels ---------------------------------------------------------------------------

TEST(MacroVariables, MacroCallGetsAFreshSetOfLocals) {
    const char* program =
        "#1=5\n#2=6\n"
        "G65 P100\n"
        "G1 X#1 Y#2 F100\n"  // the caller's #1 and #2 are untouched
        "M30\n"
        "O100\n"
        "G1 X#1 Y#2 F100\n"  // vacant here: no move
        "#1=1\n#2=2\n"
        "G1 X#1 Y#2\n"
        "M99\n";
    EXPECT_EQ(texts(program, wide_mill()),
              (Texts{"G1 X1.0000 Y2.0000 Z0.0000 F100.0000", "G1 X5.0000 Y6.0000 Z0.0000 F100.0000", "M30"}));
}

TEST(MacroVariables, EachMacroLevelHasItsOwnLocals) {
    const char* program =
        "G65 P100 A1\n"
        "M30\n"
        "O100\n"
        "G65 P200 A2\n"
        "G1 X#1 F100\n"  // still 1 after the inner call
        "M99\n"
        "O200\n"
        "G1 X#1 F100\n"
        "#1=9\n"
        "M99\n";
    EXPECT_EQ(xs(program), (std::vector<double>{2, 1}));
}

TEST(MacroVariables, SubprogramSharesItsCallersLocals) {
    const char* program =
        "#1=5\n"
        "M98 P100\n"
        "G1 X#2 F100\n"
        "M30\n"
        "O100\n"
        "#2=#1+1\n"
        "M99\n";
    EXPECT_EQ(xs(program), (std::vector<double>{6}));
    // Inside a macro, M98 shares the macro's locals.
    EXPECT_EQ(xs("G65 P100 A3\nM30\nO100\nM98 P200\nG1 X#2 F100\nM99\nO200\n#2=#1*2\nM99\n"), (std::vector<double>{6}));
}

TEST(MacroVariables, CommonVariablesAreSharedByEveryLevel) {
    EXPECT_EQ(xs("G65 P100\nG1 X#100 F100\nM30\nO100\n#100=12\nM99\n"), (std::vector<double>{12}));
}

TEST(MacroVariables, CommonVariablesStartVacantInEveryRun) {
    ScratchDir dir;
    InterpreterOptions options;
    options.retained_file = dir.path() / "retained.txt";
    EXPECT_EQ(xs("#100=5\n#500=6\nG1 X#100 F100\n", options), (std::vector<double>{5}));
    // #100 is vacant again (no X word), #500 kept.
    EXPECT_EQ(xs("G1 X#100 Y#500 F100\n", options), (std::vector<double>{0}));
    EXPECT_EQ(xs("G1 X#500 F100\n", options), (std::vector<double>{6}));
}

// ---- retained variables --------------------------------------------------------------------

TEST(MacroVariables, RetainedVariablesSurviveARun) {
    ScratchDir dir;
    InterpreterOptions options;
    options.retained_file = dir.path() / "macro.var";
    EXPECT_TRUE(moves_of("#500=1.5\n#999=-2.25\n#501=#0\n", wide_mill(), options).empty());
    EXPECT_EQ(dir.read("macro.var"),
              "; nckit retained macro variables #500-#999 (vacant ones are left out)\n"
              "#500 = 1.5\n"
              "#999 = -2.25\n");
    EXPECT_EQ(xs("G1 X#500 Y#999 F100\nX[#500+#999]\n", options), (std::vector<double>{1.5, -0.75}));
    // The file is replaced whole, through a temporary that does not stay behind.
    std::size_t files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir.path())) {
        ++files;
        EXPECT_EQ(entry.path().filename(), "macro.var");
    }
    EXPECT_EQ(files, 1U);
}

TEST(MacroVariables, RetainedValuesKeepEveryDigit) {
    ScratchDir dir;
    InterpreterOptions options;
    options.retained_file = dir.path() / "macro.var";
    EXPECT_TRUE(moves_of("#600=1/3\n", wide_mill(), options).empty());
    EXPECT_EQ(xs("#1=0\nIF [#600*3 EQ 1] THEN #1=1\nIF [#600 EQ 0.3333333] THEN #1=2\nG1 X#1 F100\n", options),
              (std::vector<double>{1}));
}

TEST(MacroVariables, RetainedFileIsReplacedOnlyWhenChanged) {
    ScratchDir dir;
    InterpreterOptions options;
    options.retained_file = dir.write("macro.var", "; my offsets\n#700 = 3\n\n");
    EXPECT_EQ(xs("G1 X#700 F100\n", options), (std::vector<double>{3}));
    EXPECT_EQ(dir.read("macro.var"), "; my offsets\n#700 = 3\n\n");
    // Making it vacant drops it from the file.
    EXPECT_TRUE(moves_of("#700=#0\n", wide_mill(), options).empty());
    EXPECT_EQ(dir.read("macro.var"), "; nckit retained macro variables #500-#999 (vacant ones are left out)\n");
}

TEST(MacroVariables, RetainedValuesAreSavedWhenAnAlarmStopsTheRun) {
    ScratchDir dir;
    InterpreterOptions options;
    options.retained_file = dir.path() / "macro.var";
    EXPECT_EQ(alarm_of("#500=4\n#1=1/0\n", options), "112 2:5");
    EXPECT_EQ(xs("G1 X#500 F100\n", options), (std::vector<double>{4}));
}

TEST(MacroVariables, CorruptRetainedFileIsAnErrorWithItsLine) {
    ScratchDir dir;
    InterpreterOptions options;
    options.retained_file = dir.write("macro.var", "#500 = 1\n#501 = abc\n");
    RunResult r = run_program("G1 X1 F100\n", wide_mill(), options);
    ASSERT_TRUE(r.error.has_value());
    EXPECT_TRUE(r.moves.empty());
    EXPECT_EQ(r.error->code, "retained-file");
    EXPECT_EQ(format_diagnostic(*r.error), (dir.path() / "macro.var").string() + ":2:1: error: 'abc' is not a number");
    // The broken file is left as it was.
    EXPECT_EQ(dir.read("macro.var"), "#500 = 1\n#501 = abc\n");

    options.retained_file = dir.write("other.var", "; fine\n#1 = 2\n");
    r = run_program("G1 X1 F100\n", wide_mill(), options);
    ASSERT_TRUE(r.error.has_value());
    EXPECT_EQ(r.error->location.line, 2U);
    options.retained_file = dir.write("third.var", "500 = 2\n");
    r = run_program("G1 X1 F100\n", wide_mill(), options);
    ASSERT_TRUE(r.error.has_value());
    EXPECT_EQ(r.error->location.line, 1U);
    // from_chars reads "nan" and "inf": no value a variable may hold.
    options.retained_file = dir.write("fourth.var", "#500 = 1\n#501 = nan\n");
    r = run_program("G1 X1 F100\n", wide_mill(), options);
    ASSERT_TRUE(r.error.has_value());
    EXPECT_EQ(r.error->location.line, 2U);
    options.retained_file = dir.write("fifth.var", "#502 = -inf\n");
    r = run_program("G1 X1 F100\n", wide_mill(), options);
    ASSERT_TRUE(r.error.has_value());
    EXPECT_EQ(r.error->location.line, 1U);
}

TEST(MacroVariables, RetainedFileThatCannotBeWrittenIsAnError) {
    ScratchDir dir;
    InterpreterOptions options;
    options.retained_file = dir.path() / "no-such-folder" / "macro.var";
    RunResult r = run_program("#500=1\nG1 X1 F100\n", wide_mill(), options);
    EXPECT_EQ(r.moves.size(), 1U);
    ASSERT_TRUE(r.error.has_value());
    EXPECT_EQ(r.error->code, "retained-file");
    EXPECT_EQ(r.error->location.file_name(), options.retained_file.string());
    // Nothing to keep, nothing to write: a run that changes no retained variable ends normally.
    EXPECT_EQ(xs("G1 X1 F100\n", options), (std::vector<double>{1}));
}

TEST(MacroVariables, WithoutARetainedFileNothingIsKept) {
    EXPECT_EQ(xs("#500=5\nG1 X#500 F100\n"), (std::vector<double>{5}));
    EXPECT_EQ(xs("G1 X#500 Y1 F100\n"), (std::vector<double>{0}));
}

// ---- vacant ------------------------------------------------------------------------------

TEST(MacroVariables, VacantCopiesAsVacant) {
    EXPECT_EQ(value_after("#1=#0"), std::nullopt);
    EXPECT_EQ(value_after("#2=#5\n#1=#2"), std::nullopt);
    EXPECT_EQ(value_after("#1=5\n#1=#0"), std::nullopt);
}

TEST(MacroVariables, VacantIsZeroInArithmetic) {
    EXPECT_EQ(value_of("#5*5"), 0.0);
    EXPECT_EQ(value_of("#5+#5"), 0.0);
    EXPECT_EQ(value_of("#5+2"), 2.0);
    EXPECT_EQ(value_of("SQRT[#5]"), 0.0);
    EXPECT_EQ(value_of("#5 OR 4"), 4.0);
    EXPECT_EQ(value_of("-#5"), 0.0);  // negation is arithmetic: 0, not vacant
}

TEST(MacroVariables, EqualityTellsVacantFromZero) {
    EXPECT_EQ(holds("", "#5 EQ #0"), 1.0);
    EXPECT_EQ(holds("", "#5 EQ 0"), 0.0);
    EXPECT_EQ(holds("", "#5 NE 0"), 1.0);
    EXPECT_EQ(holds("", "#5 NE #0"), 0.0);
    EXPECT_EQ(holds("#5=0", "#5 EQ #0"), 0.0);
    EXPECT_EQ(holds("#5=0", "#5 EQ 0"), 1.0);
    EXPECT_EQ(holds("#5=0", "#5 NE #0"), 1.0);
    EXPECT_EQ(holds("", "#0 EQ #5"), 1.0);
}

TEST(MacroVariables, OrderingComparisonsReadVacantAsZero) {
    EXPECT_EQ(holds("", "#5 GE 0"), 1.0);
    EXPECT_EQ(holds("", "#5 GT 0"), 0.0);
    EXPECT_EQ(holds("", "#5 LE 0"), 1.0);
    EXPECT_EQ(holds("", "#5 LT 0"), 0.0);
    EXPECT_EQ(holds("", "#5 LT 1"), 1.0);
    EXPECT_EQ(holds("", "#5 GT -1"), 1.0);
}

TEST(MacroVariables, VacantWordIsLeftOut) {
    EXPECT_EQ(texts("G1 X3 F100\nX#5 Y5\n", wide_mill()),
              (Texts{"G1 X3.0000 Y0.0000 Z0.0000 F100.0000", "G1 X3.0000 Y5.0000 Z0.0000 F100.0000"}));
    EXPECT_EQ(texts("#1=0\nG1 X3 F100\nX#1 Y5\n", wide_mill()),
              (Texts{"G1 X3.0000 Y0.0000 Z0.0000 F100.0000", "G1 X0.0000 Y5.0000 Z0.0000 F100.0000"}));
    // A block whose every word is vacant does nothing.
    EXPECT_TRUE(moves_of("G1 F100\nX#5 Y#6\n", wide_mill()).empty());
    EXPECT_EQ(xs("G1 F100 X[#5]\nX[#5+1]\n"), (std::vector<double>{1}));
}

}  // namespace
}  // namespace nckit::test
