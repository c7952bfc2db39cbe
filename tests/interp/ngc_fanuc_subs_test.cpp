// The LinuxCNC dialect's Fanuc-style subs (M98/M99), computed O-word numbers, and the state a
// run starts from (startup_gcodes, the parameter file's G92 offset and work system), and its
// G84 under G18/G19, each against what LinuxCNC 2.9's rs274 does with the same program.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <fmt/format.h>

#include "interp_support.hpp"

namespace nckit::test {
namespace {

//! "from -> to" of every straight move, X Y Z to 4 decimals.
std::vector<std::string> lines_of(std::string_view program, const MachineConfig& machine = linuxcnc_mill(),
                                  InterpreterOptions options = {}) {
    std::vector<std::string> out;
    for (const Move& m : moves_of(program, machine, options)) {
        if (const auto* line = std::get_if<Line>(&m.what)) {
            out.push_back(fmt::format("{:.4f} {:.4f} {:.4f} -> {:.4f} {:.4f} {:.4f}", line->from[Axis::X],
                                      line->from[Axis::Y], line->from[Axis::Z], line->to[Axis::X], line->to[Axis::Y],
                                      line->to[Axis::Z]));
        }
    }
    return out;
}

TEST(NgcFanucSubs, M98CallsTheNumberedBlockLTimesSharingParameters) {
    auto got = lines_of("#1 = 0\nM98 P1 L3\nG0 Y#1\nM30\nO1\n#1 = [#1 + 1]\nG0 X#1\nM99\n%\n");
    EXPECT_EQ(got,
              (std::vector<std::string>{
                  "0.0000 0.0000 0.0000 -> 1.0000 0.0000 0.0000", "1.0000 0.0000 0.0000 -> 2.0000 0.0000 0.0000",
                  "2.0000 0.0000 0.0000 -> 3.0000 0.0000 0.0000", "3.0000 0.0000 0.0000 -> 3.0000 3.0000 0.0000"}));
}

TEST(NgcFanucSubs, PFindsTheFirstBlockOfThatNumberAndL0CallsNothing) {
    auto got = lines_of("M98 P0002\nM98 P2 L0\nM30\nO0002\nG0 X2\nM99\nO2\nG0 X9\nM99\n");
    EXPECT_EQ(got, (std::vector<std::string>{"0.0000 0.0000 0.0000 -> 2.0000 0.0000 0.0000"}));
}

TEST(NgcFanucSubs, NestedCallsAndM99InTheMainProgramEndsIt) {
    auto got = lines_of("M98 P2 L2\nG0 Z1\nM99\nO2\nM98 P1\nM99\nO1\nG91 G0 X1\nG90\nM99\n");
    EXPECT_EQ(got, (std::vector<std::string>{"0.0000 0.0000 0.0000 -> 1.0000 0.0000 0.0000",
                                             "1.0000 0.0000 0.0000 -> 2.0000 0.0000 0.0000",
                                             "2.0000 0.0000 0.0000 -> 2.0000 0.0000 1.0000"}));
}

TEST(NgcFanucSubs, ComputedONumbers) {
    auto got = lines_of(
        "#2 = 10\n#<_n> = 100\nO[#2 * 10] call\nM98 P[2 * 100]\no#<_n> call\nM30\n"
        "O100 sub\nG91 G0 X1\nG90\nO100 endsub\nO200\nG0 Y5\nM99\n");
    ASSERT_EQ(got.size(), 3u);
    EXPECT_EQ(got[1], "1.0000 0.0000 0.0000 -> 1.0000 5.0000 0.0000");
    EXPECT_EQ(got[2], "1.0000 5.0000 0.0000 -> 2.0000 5.0000 0.0000");
}

TEST(NgcFanucSubs, ComputedONumberInADefinitionIsReadOnlyWhenTheSubRuns) {
    auto got = lines_of("o<m> sub\n#<s> = 2\no#<s> call\no<m> endsub\no2 sub\nG0 X2\no2 endsub\no<m> call\nM2\n");
    EXPECT_EQ(got, (std::vector<std::string>{"0.0000 0.0000 0.0000 -> 2.0000 0.0000 0.0000"}));
}

TEST(NgcFanucSubs, EndsubValueIsNotReadWhenTheDefinitionIsPassedOver) {
    auto got = lines_of("o<f> sub\n#<r> = [#1 * 2]\no<f> endsub [#<r>]\no<f> call [3]\nG0 X#<_value>\nM2\n");
    EXPECT_EQ(got, (std::vector<std::string>{"0.0000 0.0000 0.0000 -> 6.0000 0.0000 0.0000"}));
}

TEST(NgcFanucSubs, ErrorsAsLinuxCncGivesThem) {
    const MachineConfig m = linuxcnc_mill();
    EXPECT_EQ(at(error_of("G0 X1\nM98\nM30\n", m)), "2:1 M98 with no P word (the number of the O-word to call)");
    EXPECT_EQ(at(error_of("O1 call\nM2\nO1 sub\nG0 X1\nM99\n%\n", m)),
              "5:1 M99 inside o<1> sub: a sub called by `call` ends with endsub or return");
    EXPECT_EQ(at(error_of("O1 call\nM2\nO1\nG0 X1\nM99\n", m)),
              "3:1 o1 is a Fanuc-style sub: call it with M98 P1, not with `call`");
    EXPECT_EQ(at(error_of("M98 P1\nM30\nO1 sub\nG0 X1\nO1 endsub\n", m)),
              "3:1 o1 sub is called with `o1 call`, not with M98");
    EXPECT_EQ(at(error_of("%\nO2 call\n%\nO2 sub\nO2 endsub\n", m)),
              "2:1 subroutine o<2> not found before the closing %");
    EXPECT_EQ(at(error_of("%\nM98 P7\n%\nO7\nM99\n", m)), "2:1 subroutine O7 not found before the closing %");
    EXPECT_EQ(at(error_of("M98 P1 L-1\nM30\n", m)), "1:8 M98 L-1: the repeat count is a whole number 0-9999");
    // An M98 sub is a call level of its own: the caller's named locals are not there.
    EXPECT_EQ(at(error_of("#<k> = 3\nM98 P5\nM30\nO5\nG0 X#<k>\nM99\n", m)), "5:5 named parameter #<k> not defined");
    // A computed O number is read on a skipped line too: #<n> is not yet defined there.
    EXPECT_EQ(at(error_of("o<s> call\n#<n> = 1\no#<n> call\nM2\no<s> sub\no<s> endsub\n", m)),
              "3:2 named parameter #<n> not defined");
}

TEST(NgcStart, StartupGcodesApplyInTheLinuxCncDialect) {
    MachineConfig m = linuxcnc_mill();
    m.startup_gcodes = "G20 G91";
    auto got = lines_of("G0 X1\nG0 X1\nM2\n", m);
    EXPECT_EQ(got, (std::vector<std::string>{"0.0000 0.0000 0.0000 -> 25.4000 0.0000 0.0000",
                                             "25.4000 0.0000 0.0000 -> 50.8000 0.0000 0.0000"}));
}

TEST(NgcStart, ParameterFileRestoresG92WhenAppliedAndTheWorkSystem) {
    auto dir = std::filesystem::temp_directory_path() / "nckit_ngc_vars_test";
    std::filesystem::create_directories(dir);
    InterpreterOptions options;
    options.retained_file = dir / "mill.var";
    options.save_retained = false;
    auto write = [&](double applied) {
        std::ofstream(options.retained_file) << fmt::format("5210\t{}\n5211\t1\n5212\t2\n5220\t2\n5241\t10\n", applied);
    };
    write(1);
    EXPECT_EQ(lines_of("G0 X0 Y0\nM2\n", linuxcnc_mill(), options),
              (std::vector<std::string>{"0.0000 0.0000 0.0000 -> 11.0000 2.0000 0.0000"}));
    write(0);  // G92 not applied: its numbers stay values only
    EXPECT_EQ(lines_of("G0 X0 Y0\nM2\n", linuxcnc_mill(), options),
              (std::vector<std::string>{"0.0000 0.0000 0.0000 -> 10.0000 0.0000 0.0000"}));
    std::filesystem::remove_all(dir);
}

TEST(NgcCycles, TappingUnderG18AndG19FeedsWhereLinuxCncFeeds) {
    // rs274: G18 `G84 X1 Z2 Y0.5 R3` from Y2 feeds to (0.5, 2, 1) and back to (3, 2, 1), the
    // point meant with X Y Z turned round; the next move starts there.
    auto g18 = lines_of("G18 G99 M3 S100 F10\nG0 X0 Y2 Z0\nG84 X1 Z2 Y0.5 R3\nG80 G0 X0\nM2\n");
    EXPECT_EQ(g18,
              (std::vector<std::string>{
                  "0.0000 0.0000 0.0000 -> 0.0000 2.0000 0.0000", "0.0000 2.0000 0.0000 -> 0.0000 3.0000 0.0000",
                  "0.0000 3.0000 0.0000 -> 1.0000 3.0000 2.0000", "1.0000 3.0000 2.0000 -> 0.5000 2.0000 1.0000",
                  "0.5000 2.0000 1.0000 -> 3.0000 2.0000 1.0000", "3.0000 2.0000 1.0000 -> 0.0000 3.0000 2.0000"}));
    auto g19 = lines_of("G19 G99 M3 S100 F10\nG0 X2 Y0 Z0\nG84 Y1 Z2 X0.5 R3\nM2\n");
    ASSERT_EQ(g19.size(), 5u);
    EXPECT_EQ(g19[3], "3.0000 1.0000 2.0000 -> 2.0000 0.5000 1.0000");
    EXPECT_EQ(g19[4], "2.0000 0.5000 1.0000 -> 2.0000 3.0000 1.0000");
}

TEST(NgcProbe, G38FeedsToThePointSetsParametersAndGoesOnShortOfIt) {
    // rs274: G38.2 X3 Y4 from 0,0 probes to (3, 4), #5061/#5062 = 3, 4, #5070 = 0, and the next
    // move's unnamed axes come from 0.254 mm short of the point: G0 Z1 ends at (2.8476, 3.7968, 1).
    auto got = lines_of("G0 X0 Y0 Z0\nG38.2 X3 Y4 F100\nG0 Z1\nG0 X[#5061 + #5070] Y#5062\nM2\n");
    EXPECT_EQ(got,
              (std::vector<std::string>{
                  "0.0000 0.0000 0.0000 -> 0.0000 0.0000 0.0000", "0.0000 0.0000 0.0000 -> 3.0000 4.0000 0.0000",
                  "3.0000 4.0000 0.0000 -> 2.8476 3.7968 1.0000", "2.8476 3.7968 1.0000 -> 3.0000 4.0000 1.0000"}));
    // rs274 runs a probe of any length (0.1 mm here) and G38.3 to where the tool stands; G38.2
    // (and G38.4) there is its error.
    EXPECT_EQ(lines_of("G0 Z0\nG38.2 Z-0.1 F100\nG38.3 Z-0.1\nM2\n").size(), 3u);
    EXPECT_EQ(at(error_of("G0 Z0\nG38.2 Z0 F100\nM2\n", linuxcnc_mill())),
              "2:1 start point too close to probe point (G38.2/G38.4 to where the tool is)");
}

}  // namespace
}  // namespace nckit::test
