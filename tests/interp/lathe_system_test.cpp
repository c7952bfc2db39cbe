// Fanuc lathe G-code systems A, B and C, the power-up modes and U/W words (docs/gcode-lathe.md).
#include <gtest/gtest.h>

#include "interp_support.hpp"

namespace nckit::test {
namespace {

MachineConfig lathe(std::string_view machine_keys) {
    std::string text =
        "[machine]\nname = \"t\"\ndiameter_mode = true\n" + std::string(machine_keys) +
        "\n[[axis]]\nname = \"X\"\nkind = \"linear\"\nmax_velocity = 100\nmax_acceleration = 500\nmax_jerk = 50000\n"
        "min = -10\nmax = 200\nsteps_per_unit = 800\n"
        "[[axis]]\nname = \"Z\"\nkind = \"linear\"\nmax_velocity = 100\nmax_acceleration = 500\nmax_jerk = 50000\n"
        "min = -300\nmax = 10\nsteps_per_unit = 800\n[spindle]\nmax_rpm = 4000\n";
    auto config = parse_machine_config(text, "lathe.toml");
    if (!config) {
        ADD_FAILURE() << format_diagnostic(config.diagnostics().front());
        return default_mill();
    }
    return *config;
}

MachineConfig system_a() {
    return lathe("gcode_system = \"A\"\nstartup_gcodes = \"G18 G21 G40 G97 G99\"");
}

const Line& line_at(const std::vector<Move>& moves, std::size_t i) {
    return std::get<Line>(moves.at(i).what);
}

TEST(LatheSystem, FeedPerRevolutionAtPowerUp) {
    // No G98/G99: a Fanuc lathe is in G99, so F0.2 is 0.2 mm/rev; at 500 rpm that is 100 mm/min.
    auto moves = moves_of("G97 S500 M3\nG0 X50. Z2.\nG1 Z-50. F0.2\nM30\n", system_a());
    const Line& cut = line_at(moves, 3);
    EXPECT_EQ(cut.feed.mode, FeedMode::per_revolution);
    EXPECT_DOUBLE_EQ(cut.feed.mm_per_rev, 0.2);
    EXPECT_DOUBLE_EQ(cut.feed.mm_per_min, 100.0);
}

TEST(LatheSystem, WithoutStartupKeyALatheSystemStillStartsPerRevolution) {
    auto moves = moves_of("G97 S1000 M3\nG1 X10. F0.1\nM30\n", lathe("gcode_system = \"A\""));
    EXPECT_EQ(line_at(moves, 2).feed.mode, FeedMode::per_revolution);
    EXPECT_DOUBLE_EQ(line_at(moves, 2).feed.mm_per_min, 100.0);
}

TEST(LatheSystem, G98IsFeedPerMinuteInSystemA) {
    auto moves = moves_of("G98 G97 S500 M3\nG1 X10. F120.\nG99\nG1 X20. F0.3\nM30\n", system_a());
    EXPECT_EQ(line_at(moves, 2).feed.mode, FeedMode::per_minute);
    EXPECT_DOUBLE_EQ(line_at(moves, 2).feed.mm_per_min, 120.0);
    EXPECT_DOUBLE_EQ(line_at(moves, 3).feed.mm_per_min, 150.0);
}

TEST(LatheSystem, SystemBUsesG94G95AndStartsAsConfigured) {
    MachineConfig b = lathe("gcode_system = \"B\"\nstartup_gcodes = \"G18 G90 G94\"");
    auto moves = moves_of("G97 S500 M3\nG1 X10. F100.\nG95 G91 X10. F0.1\nM30\n", b);
    EXPECT_EQ(line_at(moves, 2).feed.mode, FeedMode::per_minute);
    EXPECT_DOUBLE_EQ(line_at(moves, 3).to[Axis::X], 10.0);  // G91: +10 on the diameter = +5 radius
    EXPECT_DOUBLE_EQ(line_at(moves, 3).feed.mm_per_min, 50.0);
}

TEST(LatheSystem, UAndWAreIncrementalInSystemA) {
    auto moves = moves_of("G0 X50. Z0\nG1 U-10. W-5. F0.2\nU4.\nM30\n", system_a());
    EXPECT_DOUBLE_EQ(line_at(moves, 1).to[Axis::X], 20.0);  // 50 - 10 on the diameter: radius 20
    EXPECT_DOUBLE_EQ(line_at(moves, 1).to[Axis::Z], -5.0);
    EXPECT_DOUBLE_EQ(line_at(moves, 2).to[Axis::X], 22.0);
}

TEST(LatheSystem, G28UWGoesHomeThroughTheCurrentPoint) {
    auto moves = moves_of("G0 X50. Z0\nG28 U0 W0\n", system_a());
    const Line& home = line_at(moves, moves.size() - 1);
    EXPECT_TRUE(home.rapid);
    EXPECT_DOUBLE_EQ(home.to[Axis::X], 0.0);
    EXPECT_DOUBLE_EQ(home.to[Axis::Z], 0.0);
}

TEST(LatheSystem, CodesThatDoNotExistInTheSystemAreRefused) {
    EXPECT_EQ(error_where("G0 X10.\nG91 U1.\n", system_a()), "unsupported-gcode 2:1");
    EXPECT_EQ(error_where("G95 F0.2\n", system_a()), "unsupported-gcode 1:1");
    EXPECT_EQ(error_where("G1 X10. Z1. G77 F0.2\n", system_a()), "unsupported-gcode 1:13");
    Diagnostic d = error_of("G0 X10.\nG91 U1.\n", system_a());
    EXPECT_NE(d.message.find("U W incremental"), std::string::npos) << d.message;
}

TEST(LatheSystem, XAndUInOneBlockIsAnError) {
    EXPECT_EQ(error_where("G0 X10. U2.\n", system_a()), "duplicate-word 1:9");
}

TEST(LatheSystem, UIsAnUnknownAxisOutsideSystemA) {
    MachineConfig b = lathe("gcode_system = \"B\"");
    EXPECT_EQ(error_where("G0 U10.\n", b), "unknown-axis 1:4");
}

TEST(LatheSystem, SystemCReadsG70G71AsUnits) {
    MachineConfig c = lathe("gcode_system = \"C\"");
    auto moves = moves_of("G70\nG98 G1 X1. F10.\nM30\n", c);
    EXPECT_DOUBLE_EQ(line_at(moves, 0).to[Axis::X], 12.7);  // G70: inch, X1 diameter = 12.7 radius
}

TEST(LatheSystem, StartupCodesErrorsPointIntoTheMachineFile) {
    auto bad = parse_machine_config(
        "[machine]\nname = \"t\"\ngcode_system = \"A\"\nstartup_gcodes = \"G18 G91\"\n"
        "[[axis]]\nname = \"X\"\nkind = \"linear\"\nmax_velocity = 1\nmax_acceleration = 1\nmax_jerk = 1\n"
        "min = 0\nmax = 1\nsteps_per_unit = 1\n[[axis]]\nname = \"Z\"\nkind = \"linear\"\nmax_velocity = 1\n"
        "max_acceleration = 1\nmax_jerk = 1\nmin = 0\nmax = 1\nsteps_per_unit = 1\n",
        "m.toml");
    ASSERT_TRUE(bad);
    RunResult run = run_program("G0 X0\n", *bad);
    ASSERT_TRUE(run.error);
    EXPECT_EQ(run.error->location.file_name(), "m.toml");
    EXPECT_EQ(run.error->location.line, 4u);
    EXPECT_EQ(run.error->location.column, 23u);  // the G91 inside the quoted value
    EXPECT_TRUE(run.moves.empty());
    MachineConfig words = lathe("startup_gcodes = \"G18 X1\"");
    RunResult with_axis = run_program("G0 X0\n", words);
    ASSERT_TRUE(with_axis.error);
    EXPECT_EQ(with_axis.error->code, "config-value");
}

TEST(LatheSystem, MillsHaveNoGCodeSystem) {
    auto mill = parse_machine_config(
        "[machine]\nname = \"m\"\ngcode_system = \"A\"\n"
        "[[axis]]\nname = \"X\"\nkind = \"linear\"\nmax_velocity = 1\nmax_acceleration = 1\nmax_jerk = 1\n"
        "min = 0\nmax = 1\nsteps_per_unit = 1\n[[axis]]\nname = \"Y\"\nmax_velocity = 1\n"
        "max_acceleration = 1\nmax_jerk = 1\nmin = 0\nmax = 1\nsteps_per_unit = 1\n",
        "mill.toml");
    ASSERT_FALSE(mill);
    EXPECT_EQ(mill.diagnostics().front().location.line, 3u);
    auto bad_value = parse_machine_config("[machine]\nname = \"m\"\ngcode_system = \"D\"\n", "x.toml");
    ASSERT_FALSE(bad_value);
}

TEST(LatheSystem, TurningCycleG90WithTaper) {
    // Start X60 Z2; G90 X50 Z-30 R-2: rapid to X46 (radius 23 = 25 - 2), taper cut to X50 Z-30,
    // feed out to X60, rapid back to Z2. Then X45: the next pass with the same Z and R.
    auto moves = moves_of("G0 X60. Z2.\nG90 X50. Z-30. R-2. F0.25\nX45.\nG0 X80.\n", system_a());
    ASSERT_EQ(moves.size(), 10u);
    EXPECT_TRUE(line_at(moves, 1).rapid);
    EXPECT_DOUBLE_EQ(line_at(moves, 1).to[Axis::X], 23.0);
    EXPECT_DOUBLE_EQ(line_at(moves, 1).to[Axis::Z], 2.0);
    EXPECT_FALSE(line_at(moves, 2).rapid);
    EXPECT_DOUBLE_EQ(line_at(moves, 2).to[Axis::X], 25.0);
    EXPECT_DOUBLE_EQ(line_at(moves, 2).to[Axis::Z], -30.0);
    EXPECT_DOUBLE_EQ(line_at(moves, 2).feed.mm_per_rev, 0.25);
    EXPECT_FALSE(line_at(moves, 3).rapid);
    EXPECT_DOUBLE_EQ(line_at(moves, 3).to[Axis::X], 30.0);
    EXPECT_TRUE(line_at(moves, 4).rapid);
    EXPECT_DOUBLE_EQ(line_at(moves, 4).to[Axis::Z], 2.0);
    EXPECT_DOUBLE_EQ(line_at(moves, 5).to[Axis::X], 20.5);
    EXPECT_DOUBLE_EQ(line_at(moves, 6).to[Axis::Z], -30.0);
}

TEST(LatheSystem, FacingCycleG94) {
    auto moves = moves_of("G0 X60. Z2.\nG94 X20. Z-2. F0.2\n", system_a());
    ASSERT_EQ(moves.size(), 5u);
    EXPECT_DOUBLE_EQ(line_at(moves, 1).to[Axis::Z], -2.0);
    EXPECT_DOUBLE_EQ(line_at(moves, 1).to[Axis::X], 30.0);
    EXPECT_DOUBLE_EQ(line_at(moves, 2).to[Axis::X], 10.0);
    EXPECT_DOUBLE_EQ(line_at(moves, 3).to[Axis::Z], 2.0);
    EXPECT_TRUE(line_at(moves, 4).rapid);
}

TEST(LatheSystem, ThreadingCycleG92IsSpindleLocked) {
    auto moves = moves_of("G97 S600 M3\nG0 X24. Z5.\nG92 X19.4 Z-25. F1.5\nX18.9\nM30\n", system_a());
    const auto& cut = std::get<SyncMove>(moves.at(4).what);
    EXPECT_DOUBLE_EQ(cut.feed.mm_per_rev, 1.5);
    EXPECT_DOUBLE_EQ(cut.to[Axis::X], 9.7);
    EXPECT_DOUBLE_EQ(cut.to[Axis::Z], -25.0);
    EXPECT_TRUE(line_at(moves, 5).rapid);
    const auto& second = std::get<SyncMove>(moves.at(8).what);
    EXPECT_DOUBLE_EQ(second.to[Axis::X], 9.45);
}

TEST(LatheSystem, SingleCycleErrors) {
    EXPECT_EQ(error_where("G0 X60. Z2.\nG90 X50. F0.2\n", system_a()), "missing-word 2:1");
    EXPECT_EQ(error_where("G0 X60. Z2.\nG92 X50. Z-10.\n", system_a()), "missing-word 2:1");
    EXPECT_EQ(error_where("G0 X60. Z2.\nG90 X50. Z-10. P1 F0.2\n", system_a()), "unused-word 2:16");
    EXPECT_EQ(error_where("G0 X60. Z2.\nG90 X50. Z-10.\n", system_a()), "no-feed 2:1");
}

}  // namespace
}  // namespace nckit::test
