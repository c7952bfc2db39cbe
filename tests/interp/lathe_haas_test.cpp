// A Haas lathe (`lathe_control = "haas"`): system A's codes, inch and feed per revolution at
// power-up as the corpus Haas is set up, and G70 reading G71's words copied onto it without
// using them. Worked numbers in inches: 1 in = 25.4 mm, X words are diameters.
#include <gtest/gtest.h>

#include "interp_support.hpp"
#include "lathe_test_machine.hpp"

namespace nckit::test {
namespace {

MachineConfig haas_lathe() {
    return lathe_machine("gcode_system = \"A\"\nlathe_control = \"haas\"\nstartup_gcodes = \"G18 G20 G40 G97 G99\"",
                         300);
}

// A one-block G71 (D depth) and a G70 carrying G71's U W D, as the Haas class programs of
// tests/real_lathe write it. The shape: X1. (radius 0.5 in) from Z0.1 to Z-1., then out to X2.
std::string program_with_g70(const std::string& g70_block) {
    return "G97 S500 M03\n"
           "G00 X2. Z0.1\n"
           "G71 P10 Q20 U0.02 W0 D0.1 F0.01\n"
           "N10 G00 X1.\n"
           "G01 Z-1.\n"
           "N20 X2.\n" +
           g70_block +
           "\n"
           "M30\n";
}

TEST(HaasLathe, G70IgnoresG71WordsAndFinishesTheShapeAsProgrammed) {
    std::vector<Diagnostic> warnings;
    InterpreterOptions options;
    options.on_warning = [&](const Diagnostic& d) { warnings.push_back(d); };
    const auto with_words = moves_of(program_with_g70("G70 P10 Q20 U0.02 W0 D0.05 F0.005"), haas_lathe(), options);
    const auto plain = moves_of(program_with_g70("G70 P10 Q20 F0.005"), haas_lathe());
    ASSERT_EQ(with_words.size(), plain.size());
    const MachineConfig machine = haas_lathe();
    for (std::size_t i = 0; i < plain.size(); ++i) {
        std::string a;
        std::string b;
        append_move_json(a, with_words[i], machine);
        append_move_json(b, plain[i], machine);
        EXPECT_EQ(a, b) << "move " << i;
    }
    // The G70 pass by hand: A is (r1 in, Z0.1 in) = (25.4, 2.54) mm. G00 X1. goes to r0.5 in
    // = 12.7 mm; G01 Z-1. to Z-25.4; X2. out to r25.4; then a rapid back to A.
    const auto path = lathe_path_of(with_words);
    ASSERT_GE(path.size(), 4u);
    const std::vector<LathePoint> want = {
        {12.7, 2.54, true}, {12.7, -25.4, false}, {25.4, -25.4, false}, {25.4, 2.54, true}};
    for (std::size_t i = 0; i < want.size(); ++i) {
        const LathePoint& got = path[path.size() - want.size() + i];
        EXPECT_NEAR(got.x_radius, want[i].x_radius, 1e-9) << i;
        EXPECT_NEAR(got.z, want[i].z, 1e-9) << i;
        EXPECT_EQ(got.rapid, want[i].rapid) << i;
    }
    // One warning for the block, at its first ignored word (U, column 13), naming each letter once.
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0].code, "ignored-word");
    EXPECT_EQ(warnings[0].severity, Severity::warning);
    EXPECT_EQ(warnings[0].location.line, 7u);
    EXPECT_EQ(warnings[0].location.column, 13u);
    EXPECT_NE(warnings[0].message.find("U W D"), std::string::npos) << warnings[0].message;
}

TEST(HaasLathe, FanucLatheStillRefusesG71WordsOnG70) {
    const MachineConfig fanuc = lathe_machine("gcode_system = \"A\"\nstartup_gcodes = \"G18 G20 G40 G97 G99\"", 300);
    EXPECT_EQ(error_where(program_with_g70("G70 P10 Q20 U0.02 W0 D0.05 F0.005"), fanuc), "unused-word 7:13");
}

TEST(HaasLathe, OtherWordsAndMissingNumbersStayErrorsOnG70) {
    // Only G71's own letters are read and not used: any other letter, a missing Q, or a word with
    // no number is an error on a Haas lathe too.
    EXPECT_EQ(error_where(program_with_g70("G70 P10 Q20 R1"), haas_lathe()), "unused-word 7:13");
    EXPECT_EQ(error_where(program_with_g70("G70 P10 U0.02"), haas_lathe()), "missing-word 7:1");
    EXPECT_EQ(error_of(program_with_g70("G70 P10 Q"), haas_lathe()).code, "syntax");
}

TEST(HaasLathe, PowersUpInInchFeedPerRevolution) {
    // G99 and G20 at power-up: F0.01 in/rev at 500 rpm feeds 5 in/min = 127 mm/min.
    const auto moves = moves_of("G97 S500 M03\nG00 X2. Z0.1\nG01 U-0.2 F0.01\nM30\n", haas_lathe());
    const auto lines = only<Line>(moves);
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_EQ(lines[1].feed.mode, FeedMode::per_revolution);
    EXPECT_NEAR(lines[1].feed.mm_per_rev, 0.254, 1e-12);
    EXPECT_NEAR(lines[1].feed.mm_per_min, 127.0, 1e-9);
    EXPECT_NEAR(lines[1].to[Axis::X], 22.86, 1e-9);  // U-0.2 in on the diameter: radius 1 - 0.1 in
}

TEST(HaasLathe, MachineKeyErrors) {
    const std::string axes =
        "[[axis]]\nname = \"X\"\nkind = \"linear\"\nmax_velocity = 100\nmax_acceleration = 500\nmax_jerk = 50000\n"
        "min = -10\nmax = 10\nsteps_per_unit = 800\n"
        "[[axis]]\nname = \"Z\"\nkind = \"linear\"\nmax_velocity = 100\nmax_acceleration = 500\nmax_jerk = 50000\n"
        "min = -10\nmax = 10\nsteps_per_unit = 800\n";
    // A Haas lathe reads system A's codes: with system B the key is an error at its value.
    auto b = parse_machine_config("[machine]\nname = \"t\"\ngcode_system = \"B\"\nlathe_control = \"haas\"\n" + axes,
                                  "haas.toml");
    ASSERT_FALSE(b);
    EXPECT_EQ(b.diagnostics().front().code, "config-value");
    EXPECT_EQ(b.diagnostics().front().location.line, 4u);
    EXPECT_EQ(b.diagnostics().front().location.column, 17u);
    // A control nckit does not know.
    auto other = parse_machine_config(
        "[machine]\nname = \"t\"\ngcode_system = \"A\"\nlathe_control = \"okuma\"\n" + axes, "haas.toml");
    ASSERT_FALSE(other);
    EXPECT_EQ(other.diagnostics().front().location.line, 4u);
}

}  // namespace
}  // namespace nckit::test
