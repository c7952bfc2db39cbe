#include <filesystem>
#include <vector>

#include <gtest/gtest.h>

#include "nckit/core/machine.hpp"

namespace nckit {
namespace {

const std::filesystem::path machines_dir = std::filesystem::path(NCKIT_SOURCE_DIR) / "examples" / "machines";

MachineConfig load(const char* file_name) {
    Result<MachineConfig> result = load_machine_config(machines_dir / file_name);
    if (!result.ok()) {
        for (const Diagnostic& d : result.diagnostics()) ADD_FAILURE() << format_diagnostic(d);
        return {};
    }
    return *result;
}

// Every shipped machine must load: a broken example is the first thing a new user runs into.
TEST(MachineExamples, EveryFileLoads) {
    int loaded = 0;
    for (const auto& entry : std::filesystem::directory_iterator(machines_dir)) {
        if (entry.path().extension() != ".toml") continue;
        Result<MachineConfig> result = load_machine_config(entry.path());
        EXPECT_TRUE(result.ok()) << (result.ok() ? "" : format_diagnostic(result.diagnostics()[0]));
        ++loaded;
    }
    EXPECT_GE(loaded, 3);
}

TEST(MachineExamples, Mill) {
    const MachineConfig m = load("mill.toml");
    EXPECT_EQ(m.name, "demo-mill");
    ASSERT_EQ(m.axes.size(), 3U);
    EXPECT_EQ(m.axes[0].axis, Axis::X);
    EXPECT_EQ(m.axes[1].axis, Axis::Y);
    EXPECT_EQ(m.axes[2].axis, Axis::Z);
    EXPECT_FALSE(m.diameter_mode);
    EXPECT_EQ(m.exact_stop_mcodes, (std::vector<int>{24, 25, 27, 28}));
    EXPECT_DOUBLE_EQ(m.spindle.max_rpm, 6000.0);
}

TEST(MachineExamples, Lathe) {
    const MachineConfig m = load("lathe.toml");
    EXPECT_TRUE(m.diameter_mode);
    ASSERT_EQ(m.axes.size(), 2U);
    const AxisConfig* x = m.find(Axis::X);
    const AxisConfig* z = m.find(Axis::Z);
    ASSERT_NE(x, nullptr);
    ASSERT_NE(z, nullptr);
    EXPECT_EQ(m.find(Axis::Y), nullptr);
    EXPECT_DOUBLE_EQ(x->min, -10.0);  // facing passes the centre line a little
    EXPECT_DOUBLE_EQ(x->max, 200.0);
    EXPECT_DOUBLE_EQ(z->min, -300.0);
    EXPECT_DOUBLE_EQ(z->max, 10.0);
    EXPECT_DOUBLE_EQ(m.spindle.max_rpm, 4000.0);
    EXPECT_TRUE(m.exact_stop_mcodes.empty());
}

TEST(MachineExamples, Notcher) {
    const MachineConfig m = load("notcher.toml");
    ASSERT_EQ(m.axes.size(), 2U);
    EXPECT_FALSE(m.axis_set().contains(Axis::Y));
    EXPECT_TRUE(m.axis_set().contains(Axis::X));
    EXPECT_TRUE(m.axis_set().contains(Axis::Z));
    for (int code : {24, 25, 27, 28}) EXPECT_TRUE(m.is_exact_stop_mcode(code)) << code;
    EXPECT_FALSE(m.is_exact_stop_mcode(3));
    EXPECT_EQ(m.exact_stop_mcodes, (std::vector<int>{24, 25, 27, 28}));
    EXPECT_EQ(m.laser_on_mcodes, (std::vector<int>{27}));
    EXPECT_EQ(m.laser_off_mcodes, (std::vector<int>{28, 128}));
    EXPECT_FALSE(m.is_exact_stop_mcode(128));  // switches off at speed, by position
    for (const AxisConfig& a : m.axes) {
        EXPECT_DOUBLE_EQ(a.max_velocity, 100.0);
        EXPECT_DOUBLE_EQ(a.max_acceleration, 500.0);
        EXPECT_DOUBLE_EQ(a.max_jerk, 5000.0);
    }
}

TEST(DefaultMill, HasThreeLinearAxes) {
    const MachineConfig m = default_mill();
    EXPECT_EQ(m.name, "default-mill");
    ASSERT_EQ(m.axes.size(), 3U);
    const Axis expected[] = {Axis::X, Axis::Y, Axis::Z};
    for (std::size_t i = 0; i < 3; ++i) {
        const AxisConfig& a = m.axes[i];
        EXPECT_EQ(a.axis, expected[i]);
        EXPECT_EQ(a.kind, AxisKind::linear);
        EXPECT_DOUBLE_EQ(a.max_velocity, 100.0);
        EXPECT_DOUBLE_EQ(a.max_acceleration, 500.0);
        EXPECT_DOUBLE_EQ(a.max_jerk, 50000.0);
        EXPECT_DOUBLE_EQ(a.min, -500.0);
        EXPECT_DOUBLE_EQ(a.max, 500.0);
        EXPECT_DOUBLE_EQ(a.steps_per_unit, 800.0);
        EXPECT_DOUBLE_EQ(a.backlash, 0.0);
        EXPECT_DOUBLE_EQ(a.home, 0.0);
    }
}

TEST(DefaultMill, MachineAndSpindle) {
    const MachineConfig m = default_mill();
    EXPECT_DOUBLE_EQ(m.servo_period_s, 0.001);
    EXPECT_FALSE(m.diameter_mode);
    EXPECT_TRUE(m.exact_stop_mcodes.empty());
    EXPECT_FALSE(m.is_exact_stop_mcode(0));
    EXPECT_DOUBLE_EQ(m.spindle.max_rpm, 6000.0);
    EXPECT_EQ(m.spindle.encoder_counts, 4096);
    EXPECT_EQ(m.decimal_point_input, DecimalPointInput::calculator);
    EXPECT_EQ(m.profile, ProfileKind::scurve);
}

TEST(DefaultMill, FindAndAxisSet) {
    const MachineConfig m = default_mill();
    ASSERT_NE(m.find(Axis::Z), nullptr);
    EXPECT_EQ(m.find(Axis::Z)->axis, Axis::Z);
    EXPECT_EQ(m.find(Axis::A), nullptr);
    AxisSet xyz;
    xyz.insert(Axis::X);
    xyz.insert(Axis::Y);
    xyz.insert(Axis::Z);
    EXPECT_EQ(m.axis_set(), xyz);
}

// The built-in mill and the shipped mill example describe the same axes; if one changes,
// programs checked without --machine and with the example would disagree.
TEST(DefaultMill, MatchesTheMillExampleAxes) {
    const MachineConfig builtin = default_mill();
    const MachineConfig example = load("mill.toml");
    ASSERT_EQ(builtin.axes.size(), example.axes.size());
    for (std::size_t i = 0; i < builtin.axes.size(); ++i) {
        EXPECT_EQ(builtin.axes[i].axis, example.axes[i].axis);
        EXPECT_DOUBLE_EQ(builtin.axes[i].max_velocity, example.axes[i].max_velocity);
        EXPECT_DOUBLE_EQ(builtin.axes[i].max_jerk, example.axes[i].max_jerk);
        EXPECT_DOUBLE_EQ(builtin.axes[i].max, example.axes[i].max);
    }
}

}  // namespace
}  // namespace nckit
