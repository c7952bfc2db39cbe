// Custom Macro B calls: G65 with both argument specifications, G66/G67 modal calls, M98 (with L
// and packed repeat counts), M99 (return, return to a sequence number), nesting limits, and
// programs found in the main file or in a library folder.
#include <gtest/gtest.h>

#include "macro_support.hpp"

namespace nckit::test {
namespace {

//! O9000 moves to X = #n for n = 1..33 in turn, or to X = -1 where #n is vacant.
constexpr const char* dump_locals =
    "M30\n"
    "O9000\n"
    "#140=1\n"
    "WHILE [#140 LE 33] DO1\n"
    "#141=-1\n"
    "IF [#[#140] NE #0] THEN #141=#[#140]\n"
    "G1 X#141 F100\n"
    "#140=#140+1\n"
    "END1\n"
    "M99\n";

std::vector<double> locals_after(std::string_view call, const MachineConfig& machine = wide_mill()) {
    return xs(std::string(call) + "\n" + dump_locals, {}, machine);
}

std::vector<double> expected_locals(std::initializer_list<std::pair<int, double>> set) {
    std::vector<double> out(33, -1.0);
    for (auto [n, v] : set) out[static_cast<std::size_t>(n - 1)] = v;
    return out;
}

//! `depth` nested calls of O100 by `call` (G65 or M98); O100 moves to X = its level.
std::string nested_calls(const std::string& call, int depth) {
    return "#100=0\n" + call + " P100\nM30\nO100\n#100=#100+1\nG1 X#100 F100\nIF [#100 GE " + std::to_string(depth) +
           "] GOTO 10\n" + call + " P100\nN10 M99\n";
}

// ---- G65 arguments -------------------------------------------------------------------------

TEST(MacroCalls, ArgumentSpecificationOne) {
    EXPECT_EQ(locals_after("G65 P9000 A1 B2 C3 I4 J5 K6 D7 E8 F9 H11 M13 Q17 R18 S19 T20 U21 V22 W23 X24 Y25 Z26"),
              expected_locals({{1, 1},   {2, 2},   {3, 3},   {4, 4},   {5, 5},   {6, 6},   {7, 7},
                               {8, 8},   {9, 9},   {11, 11}, {13, 13}, {17, 17}, {18, 18}, {19, 19},
                               {20, 20}, {21, 21}, {22, 22}, {23, 23}, {24, 24}, {25, 25}, {26, 26}}));
}

TEST(MacroCalls, ArgumentSpecificationTwo) {
    std::string call = "G65 P9000 A1 B2 C3";
    for (int set = 0; set < 10; ++set) {
        int n = 4 + 3 * set;
        call += " I" + std::to_string(n) + " J" + std::to_string(n + 1) + " K" + std::to_string(n + 2);
    }
    std::vector<double> all(33);
    for (int n = 1; n <= 33; ++n) all[static_cast<std::size_t>(n - 1)] = n;
    EXPECT_EQ(locals_after(call), all);
}

TEST(MacroCalls, IjkSetsWithOmittedLetters) {
    // I K then I: J1 omitted, the second I starts set 2.
    EXPECT_EQ(locals_after("G65 P9000 I1 K3 I4"), expected_locals({{4, 1}, {6, 3}, {7, 4}}));
    // K then J: J cannot follow K in one set.
    EXPECT_EQ(locals_after("G65 P9000 K1 J2"), expected_locals({{6, 1}, {8, 2}}));
}

TEST(MacroCalls, LaterArgumentWinsWhereBothFormsMeetOneVariable) {
    EXPECT_EQ(locals_after("G65 P9000 I1 I2 D3"), expected_locals({{4, 1}, {7, 3}}));
    EXPECT_EQ(locals_after("G65 P9000 D3 I1 I2"), expected_locals({{4, 1}, {7, 2}}));
}

TEST(MacroCalls, ArgumentsAreEvaluatedAndVacantOnesLeftOut) {
    EXPECT_EQ(locals_after("#5=3\nN20 G65 P9000 A#5 B[#5*2] C#6"), expected_locals({{1, 3}, {2, 6}}));
}

TEST(MacroCalls, ArgumentsWithoutAPointAreLeastIncrementsOnSuchMachines) {
    MachineConfig machine = wide_mill();
    machine.decimal_point_input = DecimalPointInput::least_increment;
    // X and A are axis words (0.001), F and S are not scaled, a point means what it says.
    EXPECT_EQ(locals_after("G65 P9000 X10 A10 F10 S10 Y10. I5", machine),
              expected_locals({{1, 0.01}, {4, 0.005}, {9, 10}, {19, 10}, {24, 0.01}, {25, 10}}));
    // ADP gives back the number as written.
    EXPECT_EQ(xs("G65 P100 A10\nM30\nO100\nG1 X[ADP[#1]] F100.\nM99\n", {}, machine), (std::vector<double>{10}));
}

TEST(MacroCalls, G65RepeatsWithL) {
    EXPECT_EQ(xs("G65 P100 L3 A2\nG90 G1 X0\nM30\nO100\nG91 G1 X#1 F100\nM99\n"), (std::vector<double>{2, 4, 6, 0}));
}

TEST(MacroCalls, G65FormatErrors) {
    EXPECT_EQ(alarm_of("G65 P100 G1 X1\nM30\nO100\nM99\n"), "125 1:1");
    EXPECT_EQ(alarm_of("G1 G65 P100\nM30\nO100\nM99\n"), "125 1:4");
    EXPECT_EQ(alarm_of("G65 G67 P100\nM30\nO100\nM99\n"), "125 1:5");
    EXPECT_EQ(alarm_of("G65 P100 L0\nM30\nO100\nM99\n"), "125 1:1");
    EXPECT_EQ(alarm_of("N1 G65 A1\n"), "76 1:4");
    std::string eleven_sets = "G65 P100";
    for (int i = 0; i < 11; ++i) eleven_sets += " I1";
    EXPECT_EQ(alarm_of(eleven_sets + "\nM30\nO100\nM99\n"), "125 1:40");
}

// ---- G66 / G67 -----------------------------------------------------------------------------

TEST(MacroCalls, ModalCallAfterEveryMoveBlockUntilG67) {
    const char* program =
        "G66 P100 A5\n"
        "G1 X10 F100\n"
        "S1000 M3\n"  // no move: no call
        "G4 P100\n"   // no move: no call
        "X20\n"
        "G67\n"
        "X30\n"
        "M30\n"
        "O100\n"
        "G1 Z-#1\n"  // the macro's own moves call nothing
        "#1=#1+1\n"  // its locals are its own: the next call gets A5 again
        "Z0\n"
        "M99\n";
    EXPECT_EQ(texts(program, wide_mill()),
              (Texts{"G1 X10.0000 Y0.0000 Z0.0000 F100.0000", "G1 X10.0000 Y0.0000 Z-5.0000 F100.0000",
                     "G1 X10.0000 Y0.0000 Z0.0000 F100.0000", "S1000", "M3", "G4 P0.1000",
                     "G1 X20.0000 Y0.0000 Z0.0000 F100.0000", "G1 X20.0000 Y0.0000 Z-5.0000 F100.0000",
                     "G1 X20.0000 Y0.0000 Z0.0000 F100.0000", "G1 X30.0000 Y0.0000 Z0.0000 F100.0000", "M30"}));
}

TEST(MacroCalls, ModalCallBlockItselfDoesNotMove) {
    EXPECT_EQ(xs("G66 P100 X5\nG67\nM30\nO100\nG1 X#24 F100\nM99\n"), (std::vector<double>{}));
}

TEST(MacroCalls, ModalCallFollowsMovesInSubprograms) {
    EXPECT_EQ(xs("G66 P100\nM98 P200\nG67\nG1 X9 F100\nM30\nO100\nG1 X[#5001+1] F100\nM99\nO200\nG1 X5 F100\nM99\n"),
              (std::vector<double>{5, 6, 9}));
}

TEST(MacroCalls, ModalCallRepeatsWithL) {
    EXPECT_EQ(xs("G66 P100 L2\nG1 X5 F100\nG67\nM30\nO100\nG91 G1 X1\nG90\nM99\n"), (std::vector<double>{5, 6, 7}));
}

// ---- M98 / M99 -----------------------------------------------------------------------------

TEST(MacroCalls, SubprogramCallAndReturn) {
    EXPECT_EQ(xs("M98 P100\nG1 X9 F100\nM30\nO100\nG1 X1 F100\nM99\n"), (std::vector<double>{1, 9}));
    // The block's own motion runs first, then the call.
    EXPECT_EQ(xs("G1 X5 F100 M98 P100\nM30\nO100\nG91 G1 X1\nG90\nM99\n"), (std::vector<double>{5, 6}));
}

TEST(MacroCalls, SubprogramRepeatsWithL) {
    EXPECT_EQ(xs("M98 P100 L3\nM30\nO100\nG91 G1 X1 F100\nG90\nM99\n"), (std::vector<double>{1, 2, 3}));
}

TEST(MacroCalls, PackedRepeatCount) {
    // P30123: three times O0123; the O number may be written with leading zeros.
    EXPECT_EQ(xs("M98 P30123\nM30\nO0123\nG91 G1 X1 F100\nG90\nM99\n"), (std::vector<double>{1, 2, 3}));
    EXPECT_EQ(xs("M98 P10123\nM30\nO123\nG91 G1 X1 F100\nG90\nM99\n"), (std::vector<double>{1}));
}

TEST(MacroCalls, ComputedProgramNumbersAreRounded) {
    // 1.001 * 1000 is 1000.9999999999999 in binary: it names O1001, not O1000.
    const char* programs = "M30\nO1000\nG1 X1000 F100\nM99\nO1001\nG1 X1001 F100\nM99\n";
    EXPECT_EQ(xs(std::string("#1=1.001\nM98 P[#1*1000]\n") + programs), (std::vector<double>{1001}));
    EXPECT_EQ(xs(std::string("#1=1.001\nG65 P[#1*1000]\n") + programs), (std::vector<double>{1001}));
    EXPECT_EQ(xs(std::string("#1=1.001\nG65 P1000 L[#1*3]\n") + programs), (std::vector<double>{1000, 1000, 1000}));
    EXPECT_EQ(alarm_of(std::string("M98 P1000 L-1\n") + programs), "125 1:1");
    EXPECT_EQ(alarm_of(std::string("M98 P-1000\n") + programs), "78 1:1");
}

TEST(MacroCalls, ReturnToASequenceNumberInTheCaller) {
    EXPECT_EQ(xs("M98 P100\nG1 X1 F100\nN20 G1 X2 F100\nM30\nO100\nM99 P20\n"), (std::vector<double>{2}));
    const char* backward =
        "#100=0\n"
        "N5 G1 X#100 F100\n"
        "#100=#100+1\n"
        "IF [#100 GT 2] GOTO 9\n"
        "M98 P100\n"
        "G1 X-1\n"
        "N9 M30\n"
        "O100\n"
        "M99 P5\n";
    EXPECT_EQ(xs(backward), (std::vector<double>{0, 1, 2}));
    EXPECT_EQ(alarm_of("M98 P100\nM30\nO100\nM99 P77\n"), "128 4:1");
}

TEST(MacroCalls, ReturnToASequenceNumberEndsTheRepeats) {
    // L3, but M99 P5 returns to the caller's N5 after the first run.
    EXPECT_EQ(xs("M98 P100 L3\nG1 X9 F100\nN5 G1 X5 F100\nM30\nO100\nG91 G1 X1 F100\nG90\nM99 P5\n"),
              (std::vector<double>{1, 5}));
    EXPECT_EQ(xs("G65 P100 L3\nG1 X9 F100\nN5 G1 X5 F100\nM30\nO100\nG91 G1 X1 F100\nG90\nM99 P5\n"),
              (std::vector<double>{1, 5}));
}

TEST(MacroCalls, SubprogramFormatErrors) {
    EXPECT_EQ(alarm_of("M98 L2\n"), "76 1:1");
    EXPECT_EQ(alarm_of("M98 P100 M99\nM30\nO100\nM99\n"), "114 1:10");
    EXPECT_EQ(alarm_of("M98 P100\nM30\nO100\nG1 X1 F100\n"), "114 5:1");  // ends without M99
    EXPECT_EQ(alarm_of("M98 P100\nM30\nO100\nG1 X1 F100\nO200\nM99\n"), "114 5:1");
}

// ---- nesting and finding programs ----------------------------------------------------------

TEST(MacroCalls, FourMacroLevels) {
    EXPECT_EQ(xs(nested_calls("G65", 4)), (std::vector<double>{1, 2, 3, 4}));
    EXPECT_EQ(alarm_of(nested_calls("G65", 5)), "122 8:1");
}

TEST(MacroCalls, TenSubprogramLevels) {
    EXPECT_EQ(xs(nested_calls("M98", 10)), (std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10}));
    EXPECT_EQ(alarm_of(nested_calls("M98", 11)), "122 8:1");
}

TEST(MacroCalls, TenLevelsInAllWithMacrosIncluded) {
    // Four G65 levels, then M98 levels on top of them.
    auto program = [](int depth) {
        return "#100=0\nG65 P100\nM30\nO100\n#100=#100+1\nG1 X#100 F100\nIF [#100 GE " + std::to_string(depth) +
               "] GOTO 10\nIF [#100 LT 4] GOTO 20\nM98 P100\nGOTO 10\nN20 G65 P100\nN10 M99\n";
    };
    EXPECT_EQ(xs(program(10)).size(), 10U);
    EXPECT_EQ(alarm_of(program(11)), "122 9:1");
}

TEST(MacroCalls, ProgramNotFoundIsAlarm78) {
    EXPECT_EQ(alarm_of("G1 X1 F100\nM98 P4321\n"), "78 2:1");
    EXPECT_EQ(alarm_of("G65 P4321 A1\n"), "78 1:1");
    Diagnostic d = error_of("M98 P12\n", wide_mill());
    // It says where it looked and how to give a library folder.
    EXPECT_EQ(d.message.rfind("program O0012 not found: looked in ", 0), 0U) << d.message;
    EXPECT_NE(d.message.find("--library"), std::string::npos) << d.message;
}

TEST(MacroCalls, SeveralProgramsInOneFile) {
    const char* program =
        "O1\n"
        "M98 P200\n"
        "G65 P300 A3\n"
        "M98 P200\n"
        "M30\n"
        "O200 (SECOND)\n"
        "G1 X2 F100\n"
        "M99\n"
        "O300 (THIRD)\n"
        "G1 X#1 F100\n"
        "M98 P200\n"
        "M99\n";
    EXPECT_EQ(xs(program), (std::vector<double>{2, 3, 2, 2}));
}

TEST(MacroCalls, ProgramsFromALibraryFolder) {
    ScratchDir library;
    library.write("O1234.nc", "%\nO1234 (WITH TAPE MARKS)\nG1 X#1 F100\nM99\n%\n");
    library.write("2000.ngc", "G1 X2 F100\nM99\n");
    library.write("O3000", "O3000\nM98 P2000\nG1 X3 F100\nM99\n");
    library.write("o5.nc", "G1 X5 F100\nM99\n");
    library.write("notes.txt", "not a program\n");
    InterpreterOptions options;
    options.library_dir = library.path();
    EXPECT_EQ(xs("G65 P1234 A1\nM98 P2000\nM98 P3000\nM98 P5\nG65 P1234 A7\nM30\n", options),
              (std::vector<double>{1, 2, 2, 3, 5, 7}));
    // Programs of the main file and of the library, called in turn at the same depth.
    EXPECT_EQ(xs("M98 P100\nM98 P2000\nM98 P100\nG65 P1234 A4\nM98 P100\nM30\nO100\nG1 X100 F100\nM99\n", options),
              (std::vector<double>{100, 2, 100, 4, 100}));
    // A library program repeats from its start, past its tape mark again.
    EXPECT_EQ(xs("G65 P1234 L2 A6\nM30\n", options), (std::vector<double>{6, 6}));
    // A program of the main file comes first.
    EXPECT_EQ(xs("M98 P2000\nM30\nO2000\nG1 X20 F100\nM99\n", options), (std::vector<double>{20}));
}

TEST(MacroCalls, LibraryProgramWithoutM99) {
    ScratchDir library;
    library.write("O2000.nc", "G1 X2 F100\n");
    InterpreterOptions options;
    options.library_dir = library.path();
    RunResult r = run_program("M98 P2000\n", wide_mill(), options);
    ASSERT_TRUE(r.error.has_value());
    EXPECT_EQ(r.error->alarm, 114);
    EXPECT_EQ(r.error->location.file_name(), (library.path() / "O2000.nc").string());
    EXPECT_EQ(r.error->location.line, 2U);
    EXPECT_EQ(r.moves.size(), 1U);
}

}  // namespace
}  // namespace nckit::test
