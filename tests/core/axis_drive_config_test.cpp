// The drive keys of an [[axis]]: the phase-table port encoding and the [axis.servo] table.
#include <string>
#include <string_view>

#include <gtest/gtest.h>

#include "nckit/core/machine.hpp"

namespace nckit {
namespace {

// Line 14 is "backlash = 0.0"; the tests add their keys after it, from line 15.
constexpr std::string_view valid_config = R"([machine]
name = "m"
servo_period_s = 0.001

[[axis]]
name = "X"
kind = "linear"
max_velocity = 100.0
max_acceleration = 500.0
max_jerk = 50000.0
min = -500.0
max = 500.0
steps_per_unit = 800.0
backlash = 0.0

[spindle]
max_rpm = 6000
)";

//! `valid_config` with `lines` from line 15.
std::string with_axis_lines(std::string_view lines) {
    std::string text(valid_config);
    const std::size_t at = text.find("backlash = 0.0\n") + 15;
    return text.insert(at, std::string(lines) + "\n");
}

//! The only error `text` gives, as `LINE:COL: message`.
std::string only_error(std::string_view text) {
    Result<MachineConfig> result = parse_machine_config(text, "m.toml");
    if (result.ok()) {
        ADD_FAILURE() << "config was accepted:\n" << text;
        return {};
    }
    const Diagnostics& errors = result.diagnostics();
    if (errors.size() != 1) {
        std::string all;
        for (const Diagnostic& d : errors) all += format_diagnostic(d) + "\n";
        ADD_FAILURE() << "expected one error, got " << errors.size() << ":\n" << all;
        return all;
    }
    const Diagnostic& d = errors.front();
    EXPECT_EQ(d.location.file_name(), "m.toml");
    return std::to_string(d.location.line) + ":" + std::to_string(d.location.column) + ": " + d.message;
}

AxisConfig axis_of(std::string_view text) {
    Result<MachineConfig> result = parse_machine_config(text, "m.toml");
    if (!result.ok()) {
        ADD_FAILURE() << format_diagnostic(result.diagnostics().front());
        return {};
    }
    return result->axes.at(0);
}

TEST(AxisDriveConfig, PortEncodingDefaultsToPlainWindings) {
    const AxisConfig axis = axis_of(with_axis_lines("phase_table = \"3phase-6beat\""));
    EXPECT_FALSE(axis.port_active_low);
    EXPECT_EQ(axis.port_set_bits, 0);
    EXPECT_FALSE(axis.servo.has_value());
}

TEST(AxisDriveConfig, ReadsTheSeedPortEncoding) {
    const AxisConfig axis =
        axis_of(with_axis_lines("phase_table = \"3phase-6beat\"\nport_active_low = true\nport_set_bits = 0x08"));
    EXPECT_TRUE(axis.port_active_low);
    EXPECT_EQ(axis.port_set_bits, 0x08);
    // Two-phase tables drive four bits; bit 7 stays free for an enable line.
    EXPECT_EQ(axis_of(with_axis_lines("phase_table = \"2phase-half\"\nport_set_bits = 128")).port_set_bits, 0x80);
}

TEST(AxisDriveConfigError, PortKeysNeedAPhaseTable) {
    EXPECT_EQ(only_error(with_axis_lines("port_active_low = true")),
              "15:19: 'port_active_low' encodes a phase table's port: set 'phase_table' too");
    EXPECT_EQ(only_error(with_axis_lines("phase_table = \"none\"\nport_set_bits = 8")),
              "16:17: 'port_set_bits' encodes a phase table's port: set 'phase_table' too");
}

TEST(AxisDriveConfigError, PortSetBitsMustFitAndKeepClearOfTheWindings) {
    EXPECT_EQ(only_error(with_axis_lines("phase_table = \"3phase-6beat\"\nport_set_bits = 256")),
              "16:17: 'port_set_bits' must fit the 8-bit port (0 to 255), not 256");
    EXPECT_EQ(only_error(with_axis_lines("phase_table = \"3phase-6beat\"\nport_set_bits = 12")),
              "16:17: 'port_set_bits' (0x0C) overlaps the winding bits 0x07 of phase table '3phase-6beat'");
    EXPECT_EQ(only_error(with_axis_lines("phase_table = \"2phase-full\"\nport_set_bits = 8")),
              "16:17: 'port_set_bits' (0x08) overlaps the winding bits 0x0F of phase table '2phase-full'");
    EXPECT_EQ(only_error(with_axis_lines("phase_table = \"3phase-6beat\"\nport_set_bits = -1")),
              "16:17: 'port_set_bits' must be zero or more, not -1");
    EXPECT_EQ(only_error(with_axis_lines("phase_table = \"3phase-6beat\"\nport_active_low = 1")),
              "16:19: 'port_active_low' must be true or false, not an integer");
}

TEST(AxisDriveConfig, ReadsAServoTable) {
    const AxisConfig axis =
        axis_of(with_axis_lines("[axis.servo]\nnatural_frequency_hz = 30.0\ndamping = 0.7\ngain = 0.98"));
    ASSERT_TRUE(axis.servo.has_value());
    EXPECT_DOUBLE_EQ(axis.servo->natural_frequency_hz, 30.0);
    EXPECT_DOUBLE_EQ(axis.servo->damping, 0.7);
    EXPECT_DOUBLE_EQ(axis.servo->gain, 0.98);
    // gain is optional; an inline table works as well.
    const AxisConfig inline_servo = axis_of(with_axis_lines("servo = { natural_frequency_hz = 12, damping = 1 }"));
    ASSERT_TRUE(inline_servo.servo.has_value());
    EXPECT_DOUBLE_EQ(inline_servo.servo->gain, 1.0);
    EXPECT_DOUBLE_EQ(inline_servo.servo->damping, 1.0);
}

TEST(AxisDriveConfigError, ServoKeysAreCheckedWithTheirLocation) {
    EXPECT_EQ(only_error(with_axis_lines("[axis.servo]\nnatural_frequency_hz = 0\ndamping = 0.7")),
              "16:24: 'natural_frequency_hz' must be positive, not 0");
    EXPECT_EQ(only_error(with_axis_lines("[axis.servo]\nnatural_frequency_hz = 30\ndamping = -0.1")),
              "17:11: 'damping' must be zero or more, not -0.1");
    EXPECT_EQ(only_error(with_axis_lines("[axis.servo]\nnatural_frequency_hz = 30\ndamping = 0.7\ngain = 0")),
              "18:8: 'gain' must be positive, not 0");
    EXPECT_EQ(only_error(with_axis_lines("[axis.servo]\nnatural_frequency_hz = 30\ndamping = \"high\"")),
              "17:11: 'damping' must be a number, not a string");
    EXPECT_EQ(only_error(with_axis_lines("[axis.servo]\nnatural_frequency_hz = 30")),
              "15:1: missing key 'damping' in [axis.servo]");
    EXPECT_EQ(only_error(with_axis_lines("[axis.servo]\nnatural_frequency_hz = 30\ndamping = 0.7\nkp = 5")),
              "18:1: unknown key 'kp' in [axis.servo]");
    EXPECT_EQ(only_error(with_axis_lines("servo = 30")),
              "15:9: 'servo' must be a table ([axis.servo] after its [[axis]]), not an integer");
}

}  // namespace
}  // namespace nckit
