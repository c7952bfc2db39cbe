// The LinuxCNC dialect through the Interpreter: O-word subs and control flow, named parameters,
// expressions, comments, and the errors LinuxCNC gives, each at its line and column.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <fmt/format.h>

#include "interp_support.hpp"

namespace nckit::test {
namespace {

Diagnostic ngc_error(std::string_view program) {
    return error_of(program, linuxcnc_mill());
}

//! End points only (the X Y Z of each move's text), for short comparisons.
std::vector<std::string> ends(std::string_view program) {
    std::vector<std::string> out;
    for (const Move& m : moves_of(program, linuxcnc_mill())) {
        if (const auto* line = std::get_if<Line>(&m.what)) {
            out.push_back(fmt::format("{:.4f} {:.4f} {:.4f}", line->to[Axis::X], line->to[Axis::Y], line->to[Axis::Z]));
        } else if (const auto* arc = std::get_if<Arc>(&m.what)) {
            out.push_back(fmt::format("{:.4f} {:.4f} {:.4f}", arc->to[Axis::X], arc->to[Axis::Y], arc->to[Axis::Z]));
        }
    }
    return out;
}

TEST(NgcDialect, NamedSubWithArgumentsAndReturnValue) {
    auto got = ends(R"(o<double> sub
  G0 X#1 Y#2
o<double> endsub [#1 * 2]
o<double> call [3] [4]
G0 X#<_value>
M2
)");
    EXPECT_EQ(got, (std::vector<std::string>{"3.0000 4.0000 0.0000", "6.0000 4.0000 0.0000"}));
}

TEST(NgcDialect, CallLocalsAreRestoredAndNamedLocalsBelongToTheCall) {
    auto got = ends(R"(#1 = 7
#<a> = 1
o100 sub
  #<a> = 5
  G0 X[#1 + #<a>]
o100 endsub
o100 call [2]
G0 Y[#1 + #<a>]
M2
)");
    EXPECT_EQ(got, (std::vector<std::string>{"7.0000 0.0000 0.0000", "7.0000 8.0000 0.0000"}));
}

TEST(NgcDialect, SubDefinedAfterItsCallIsFoundReadingForward) {
    auto got = ends("o<later> call [1]\nG0 Y2\nM2\no<later> sub\nG0 X#1\no<later> endsub\n");
    EXPECT_EQ(got, (std::vector<std::string>{"1.0000 0.0000 0.0000", "1.0000 2.0000 0.0000"}));
}

TEST(NgcDialect, SubFromTheLibraryFolder) {
    auto dir = std::filesystem::temp_directory_path() / "nckit_ngc_library_test";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "square.ngc") << "o<square> sub\nG1 X#1 F100\nG1 Y#1\no<square> endsub\nM2\n";
    InterpreterOptions options;
    options.library_dir = dir;
    RunResult r = run_program("o<square> call [5]\nM2\n", linuxcnc_mill(), options);
    ASSERT_FALSE(r.error) << format_diagnostic(*r.error);
    ASSERT_EQ(r.moves.size(), 3u);  // two feeds and M2's event
    EXPECT_DOUBLE_EQ(std::get<Line>(r.moves[1].what).to[Axis::Y], 5.0);
    std::filesystem::remove_all(dir);
}

TEST(NgcDialect, IfElseifElse) {
    auto got = ends(R"(#<n> = 0
o1 repeat [3]
  #<n> = [#<n> + 1]
  o2 if [#<n> EQ 1]
    G0 X1
  o2 elseif [#<n> EQ 2]
    G0 X2
  o2 else
    G0 X3
  o2 endif
o1 endrepeat
M2
)");
    EXPECT_EQ(got, (std::vector<std::string>{"1.0000 0.0000 0.0000", "2.0000 0.0000 0.0000", "3.0000 0.0000 0.0000"}));
}

TEST(NgcDialect, WhileBreakContinueAndDoWhile) {
    auto got = ends(R"(#1 = 0
o10 while [1]
  #1 = [#1 + 1]
  o11 if [#1 EQ 2]
    o10 continue
  o11 endif
  o12 if [#1 GT 3]
    o10 break
  o12 endif
  G0 X#1
o10 endwhile
#2 = 0
o20 do
  #2 = [#2 + 1]
  G0 Y#2
o20 while [#2 LT 2]
M2
)");
    EXPECT_EQ(got, (std::vector<std::string>{"1.0000 0.0000 0.0000", "3.0000 0.0000 0.0000", "3.0000 1.0000 0.0000",
                                             "3.0000 2.0000 0.0000"}));
}

TEST(NgcDialect, ExpressionsAsLinuxCncComputesThem) {
    auto got = ends(R"(G0 X[2 ** 3] Y[-7 MOD 3] Z[FIX[-2.5]]
G0 X[1 AND 2] Y[ATAN[1]/[-1]] Z[EXISTS[#<nope>]]
G0 X[1 + 2 * 3 ** 2] Y[[1 EQ 1.0000001] + [3 GT 2 OR 0]] Z[ROUND[2.5]]
M2
)");
    EXPECT_EQ(got,
              (std::vector<std::string>{"8.0000 2.0000 -3.0000", "1.0000 135.0000 0.0000", "19.0000 2.0000 3.0000"}));
}

TEST(NgcDialect, SettingsOfOneLineReadTheOldValues) {
    auto got = ends("#1 = 1\n#1 = 5 #2 = [#1 + 1]\nG0 X#1 Y#2\nM2\n");
    EXPECT_EQ(got, (std::vector<std::string>{"5.0000 2.0000 0.0000"}));
}

TEST(NgcDialect, PredefinedParameters) {
    auto got = ends(R"(G21 G1 X3 Y4 F250
G0 X#<_x> Y[#<_y> + #<_metric>] Z[#<_feed> / 100]
G0 X[#<_motion_mode>] Y#5420
M2
)");
    EXPECT_EQ(got, (std::vector<std::string>{"3.0000 4.0000 0.0000", "3.0000 5.0000 2.5000", "0.0000 3.0000 2.5000"}));
}

TEST(NgcDialect, DwellPIsSeconds) {
    RunResult r = run_program("G4 P1.5\nM2\n", linuxcnc_mill());
    ASSERT_FALSE(r.error);
    ASSERT_EQ(r.moves.size(), 2u);  // the dwell and M2's event
    EXPECT_DOUBLE_EQ(std::get<Dwell>(r.moves[0].what).seconds, 1.5);
}

TEST(NgcDialect, PercentWrappedProgramEndsAtTheSecondPercent) {
    EXPECT_EQ(ends("%\nG0 X1\n%\nG0 X2\n"), (std::vector<std::string>{"1.0000 0.0000 0.0000"}));
}

TEST(NgcDialect, Errors) {
    EXPECT_EQ(at(ngc_error("G0 X1\no1 endif\nM2\n")), "2:1 undefined O-word label: o1");
    EXPECT_EQ(at(ngc_error("o1 while [0]\no1 endif\nM2\n")).substr(0, 21), "2:1 no matching if fo");
    EXPECT_EQ(at(ngc_error("G0 X1\no<x> endsub\nM2\n")), "2:1 not in a subroutine definition: o<x> endsub");
    EXPECT_EQ(at(ngc_error("G0 X#<nope>\nM2\n")), "1:5 named parameter #<nope> not defined");
    EXPECT_EQ(at(ngc_error("#<_x> = 1\nM2\n")), "1:1 cannot assign to read-only parameter #<_x>");
    EXPECT_EQ(at(ngc_error("G0 X#0\nM2\n")).substr(0, 40), "1:5 parameter number #0 out of range (1-");
    EXPECT_EQ(at(ngc_error("G0 X1\n")).substr(0, 33), "1:1 file ended with no percent si");
    EXPECT_EQ(at(ngc_error("(abort, stop #<_x> here)\nM2\n")).substr(0, 20), "1:1 abort:  stop 0.0");
    Diagnostic missing = ngc_error("G0 X1\no<nowhere> call\nM2\n");
    EXPECT_EQ(missing.location.line, 2u);
    EXPECT_NE(missing.message.find("o<nowhere> not found"), std::string::npos);
}

TEST(NgcDialect, RunawayLoopIsBounded) {
    InterpreterOptions options;
    options.max_blocks = 1000;
    RunResult r = run_program("o1 while [1]\nG0 X1\no1 endwhile\nM2\n", linuxcnc_mill(), options);
    ASSERT_TRUE(r.error);
    EXPECT_NE(r.error->message.find("runaway"), std::string::npos);
}

TEST(NgcDialect, FanucMacroFailsWhereLinuxCncFails) {
    // LinuxCNC: "Unknown word starting with f" at the IF; nckit names the same place.
    Diagnostic d = ngc_error("G0 X1\nIF [#1 EQ 0] GOTO 10\nM2\n");
    EXPECT_EQ(d.location.line, 2u);
    EXPECT_NE(d.message.find("starting with f"), std::string::npos) << d.message;
}

}  // namespace
}  // namespace nckit::test
