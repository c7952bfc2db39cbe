#include <array>
#include <string>
#include <string_view>

#include <gtest/gtest.h>

#include "nckit/core/machine.hpp"

namespace nckit {
namespace {

// A valid config whose line numbers the error tests below rely on (line 1 is "[machine]").
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
encoder_counts = 4096
)";

//! `valid_config` with the line `key = ...` replaced by `key = value`.
std::string with(std::string_view key, std::string_view value) {
    std::string text(valid_config);
    const std::string start = std::string(key) + " = ";
    const std::size_t at = text.find("\n" + start) + 1;
    const std::size_t end = text.find('\n', at);
    return text.replace(at, end - at, start + std::string(value));
}

//! `valid_config` without the line `key = ...`.
std::string without(std::string_view key) {
    std::string text(valid_config);
    const std::size_t at = text.find("\n" + std::string(key) + " = ") + 1;
    return text.erase(at, text.find('\n', at) + 1 - at);
}

Diagnostics errors_of(std::string_view text) {
    Result<MachineConfig> result = parse_machine_config(text, "m.toml");
    EXPECT_FALSE(result.ok()) << "config was accepted:\n" << text;
    return result.ok() ? Diagnostics{} : result.diagnostics();
}

//! The only error `text` gives, as `LINE:COL: message`, so a test states all three at once.
std::string only_error(std::string_view text) {
    const Diagnostics errors = errors_of(text);
    if (errors.size() != 1) {
        std::string all;
        for (const Diagnostic& d : errors) all += format_diagnostic(d) + "\n";
        ADD_FAILURE() << "expected one error, got " << errors.size() << ":\n" << all;
        return all;
    }
    const Diagnostic& d = errors.front();
    EXPECT_EQ(d.location.file_name(), "m.toml");
    EXPECT_EQ(d.severity, Severity::error);
    return std::to_string(d.location.line) + ":" + std::to_string(d.location.column) + ": " + d.message;
}

TEST(MachineConfig, ParsesTheDocumentedSchema) {
    constexpr std::string_view text = R"([machine]
name = "demo-mill"
servo_period_s = 0.001
diameter_mode = false          # lathe: X words are diameters
exact_stop_mcodes = [24, 25, 27, 28]   # M-codes that need the axes at rest
laser_on_mcodes = [27]
laser_off_mcodes = [28, 128]

[[axis]]
name = "X"                     # X Y Z A B C U V W
kind = "linear"                # or "rotary" (degrees)
max_velocity = 100.0           # mm/s (deg/s)
max_acceleration = 500.0       # mm/s^2
max_jerk = 50000.0             # mm/s^3
min = -500.0
max = 500.0
steps_per_unit = 800.0
backlash = 0.0

[spindle]
max_rpm = 6000
encoder_counts = 4096
)";
    Result<MachineConfig> result = parse_machine_config(text, "demo.toml");
    ASSERT_TRUE(result.ok()) << format_diagnostic(result.diagnostics().front());
    const MachineConfig& m = *result;
    EXPECT_EQ(m.name, "demo-mill");
    EXPECT_DOUBLE_EQ(m.servo_period_s, 0.001);
    EXPECT_FALSE(m.diameter_mode);
    EXPECT_EQ(m.exact_stop_mcodes, (std::vector<int>{24, 25, 27, 28}));
    EXPECT_EQ(m.laser_on_mcodes, (std::vector<int>{27}));
    EXPECT_EQ(m.laser_off_mcodes, (std::vector<int>{28, 128}));
    EXPECT_TRUE(m.is_laser_on_mcode(27));
    EXPECT_TRUE(m.is_laser_off_mcode(128));
    EXPECT_FALSE(m.is_laser_off_mcode(27));
    EXPECT_EQ(m.decimal_point_input, DecimalPointInput::calculator);
    EXPECT_EQ(m.profile, ProfileKind::scurve);
    ASSERT_EQ(m.axes.size(), 1U);
    const AxisConfig& x = m.axes[0];
    EXPECT_EQ(x.axis, Axis::X);
    EXPECT_EQ(x.kind, AxisKind::linear);
    EXPECT_DOUBLE_EQ(x.max_velocity, 100.0);
    EXPECT_DOUBLE_EQ(x.max_acceleration, 500.0);
    EXPECT_DOUBLE_EQ(x.max_jerk, 50000.0);
    EXPECT_DOUBLE_EQ(x.min, -500.0);
    EXPECT_DOUBLE_EQ(x.max, 500.0);
    EXPECT_DOUBLE_EQ(x.steps_per_unit, 800.0);
    EXPECT_DOUBLE_EQ(x.backlash, 0.0);
    EXPECT_DOUBLE_EQ(x.home, 0.0);
    EXPECT_DOUBLE_EQ(m.spindle.max_rpm, 6000.0);
    EXPECT_EQ(m.spindle.encoder_counts, 4096);
}

TEST(MachineConfig, ReadsTheOptionalKeys) {
    std::string config(valid_config);
    config.replace(config.find("servo_period_s"), 0,
                   "decimal_point_input = \"least_increment\"\nprofile = \"trapezoid\"\n");
    config.replace(config.find("backlash = 0.0"), 14, "backlash = 0.02\nbacklash_rate_steps_s = 5000\nhome = 250");
    Result<MachineConfig> result = parse_machine_config(config, "m.toml");
    ASSERT_TRUE(result.ok()) << format_diagnostic(result.diagnostics().front());
    EXPECT_EQ(result->decimal_point_input, DecimalPointInput::least_increment);
    EXPECT_EQ(result->profile, ProfileKind::trapezoid);
    EXPECT_DOUBLE_EQ(result->axes[0].backlash, 0.02);
    EXPECT_DOUBLE_EQ(result->axes[0].backlash_rate_steps_s, 5000.0);
    EXPECT_DOUBLE_EQ(result->axes[0].home, 250.0);
}

TEST(MachineConfig, KeepsTheAxisOrderOfTheFile) {
    std::string config(valid_config);
    const std::size_t axis_start = config.find("[[axis]]");
    const std::string axis = config.substr(axis_start, config.find("[spindle]") - axis_start);
    std::string rotary = axis;
    rotary.replace(rotary.find("\"X\""), 3, "\"C\"");
    rotary.replace(rotary.find("\"linear\""), 8, "\"rotary\"");
    config.insert(axis_start, rotary);
    Result<MachineConfig> result = parse_machine_config(config, "m.toml");
    ASSERT_TRUE(result.ok()) << format_diagnostic(result.diagnostics().front());
    ASSERT_EQ(result->axes.size(), 2U);
    EXPECT_EQ(result->axes[0].axis, Axis::C);
    EXPECT_EQ(result->axes[0].kind, AxisKind::rotary);
    EXPECT_EQ(result->axes[1].axis, Axis::X);
}

TEST(MachineConfig, AcceptsIntegersWhereFloatsBelong) {
    Result<MachineConfig> result = parse_machine_config(with("max_velocity", "120"), "m.toml");
    ASSERT_TRUE(result.ok());
    EXPECT_DOUBLE_EQ(result->axes[0].max_velocity, 120.0);
}

TEST(MachineConfig, DefaultsAnOmittedSpindle) {
    std::string config(valid_config);
    config.erase(config.find("[spindle]"));
    Result<MachineConfig> result = parse_machine_config(config, "m.toml");
    ASSERT_TRUE(result.ok());
    EXPECT_DOUBLE_EQ(result->spindle.max_rpm, 6000.0);
    EXPECT_EQ(result->spindle.encoder_counts, 4096);
}

TEST(MachineConfig, DefaultsOmittedOptionalKeys) {
    Result<MachineConfig> result = parse_machine_config(without("servo_period_s"), "m.toml");
    ASSERT_TRUE(result.ok());
    EXPECT_DOUBLE_EQ(result->servo_period_s, 0.001);
    EXPECT_FALSE(result->diameter_mode);
    EXPECT_TRUE(result->exact_stop_mcodes.empty());
    EXPECT_TRUE(result->laser_on_mcodes.empty());
    EXPECT_TRUE(result->laser_off_mcodes.empty());
    Result<MachineConfig> no_backlash = parse_machine_config(without("backlash"), "m.toml");
    ASSERT_TRUE(no_backlash.ok());
    EXPECT_DOUBLE_EQ(no_backlash->axes[0].backlash, 0.0);
    EXPECT_DOUBLE_EQ(no_backlash->axes[0].backlash_rate_steps_s, 20000.0);
}

// ---- one test per error kind: exact line, column and message ----

TEST(MachineConfigError, TomlSyntaxAtTomlsPosition) {
    EXPECT_EQ(only_error(with("max", "1.2.3")),
              "12:10: toml syntax error in floating-point: expected decimal digit or exponent, "
              "saw '.'");
}

TEST(MachineConfigError, MissingKeyPointsAtItsTable) {
    EXPECT_EQ(only_error(without("max_jerk")), "5:1: missing key 'max_jerk' in [[axis]]");
    EXPECT_EQ(only_error(without("name")), "1:1: missing key 'name' in [machine]");
}

TEST(MachineConfigError, MissingMachineTable) {
    std::string config(valid_config);
    config.erase(0, config.find("[[axis]]"));
    EXPECT_EQ(only_error(config), "1:1: missing table [machine]");
}

TEST(MachineConfigError, WrongTypePointsAtTheValue) {
    EXPECT_EQ(only_error(with("max_velocity", "\"fast\"")), "8:16: 'max_velocity' must be a number, not a string");
    EXPECT_EQ(only_error(with("name", "42")), "2:8: 'name' must be a string, not an integer");
    EXPECT_EQ(only_error(with("encoder_counts", "4096.0")),
              "18:18: 'encoder_counts' must be an integer, not a floating-point number");
    EXPECT_EQ(only_error(with("servo_period_s", "0.001\ndiameter_mode = 1")),
              "4:17: 'diameter_mode' must be true or false, not an integer");
}

struct NonPositiveCase {
    std::string_view key;
    std::string_view value;
    std::string expected;
};

class NonPositive : public ::testing::TestWithParam<NonPositiveCase> {};

TEST_P(NonPositive, IsAnErrorAtTheValue) {
    EXPECT_EQ(only_error(with(GetParam().key, GetParam().value)), GetParam().expected);
}

INSTANTIATE_TEST_SUITE_P(
    MachineConfigError, NonPositive,
    ::testing::Values(NonPositiveCase{"servo_period_s", "0", "3:18: 'servo_period_s' must be positive, not 0"},
                      NonPositiveCase{"max_velocity", "-100", "8:16: 'max_velocity' must be positive, not -100"},
                      NonPositiveCase{"max_acceleration", "0.0", "9:20: 'max_acceleration' must be positive, not 0"},
                      NonPositiveCase{"max_jerk", "-1.5", "10:12: 'max_jerk' must be positive, not -1.5"},
                      NonPositiveCase{"steps_per_unit", "0", "13:18: 'steps_per_unit' must be positive, not 0"},
                      NonPositiveCase{"max_rpm", "0", "17:11: 'max_rpm' must be positive, not 0"},
                      NonPositiveCase{"encoder_counts", "-4096",
                                      "18:18: 'encoder_counts' must be positive, not -4096"}));

TEST(MachineConfigError, NegativeBacklash) {
    EXPECT_EQ(only_error(with("backlash", "-0.01")), "14:12: 'backlash' must be zero or more, not -0.01");
    EXPECT_EQ(only_error(with("backlash", "0.0\nbacklash_rate_steps_s = 0")),
              "15:25: 'backlash_rate_steps_s' must be positive, not 0");
}

TEST(MachineConfigError, NonFiniteNumber) {
    EXPECT_EQ(only_error(with("max", "inf")), "12:7: 'max' must be a finite number, not inf");
}

TEST(MachineConfigError, MinNotBelowMax) {
    EXPECT_EQ(only_error(with("max", "-500.0")), "12:7: 'max' (-500) must be greater than 'min' (-500)");
}

TEST(MachineConfigError, HomeOutsideTheTravel) {
    EXPECT_EQ(only_error(with("backlash", "0.0\nhome = 501")),
              "15:8: 'home' (501) must lie within min..max (-500..500)");
    EXPECT_EQ(only_error(with("min", "10.0")),
              "5:1: 'home' defaults to 0, which lies outside min..max (10..500): set it");
}

TEST(MachineConfigError, UnknownAxisName) {
    std::string config(valid_config);
    config.replace(config.find("\"X\""), 3, "\"Q\"");
    EXPECT_EQ(only_error(config), "6:8: axis 'Q' is not one of X Y Z A B C U V W");
}

TEST(MachineConfigError, DuplicateAxis) {
    std::string config(valid_config);
    const std::size_t axis_start = config.find("[[axis]]");
    config.insert(axis_start, config.substr(axis_start, config.find("[spindle]") - axis_start));
    EXPECT_EQ(only_error(config), "17:8: axis 'X' is listed twice (first at line 6)");
}

TEST(MachineConfigError, UnknownKind) {
    EXPECT_EQ(only_error(with("kind", "\"prismatic\"")), "7:8: kind 'prismatic' is not one of linear rotary");
}

TEST(MachineConfigError, UnknownChoices) {
    EXPECT_EQ(only_error(with("servo_period_s", "0.001\nprofile = \"bang-bang\"")),
              "4:11: profile 'bang-bang' is not one of scurve trapezoid");
    EXPECT_EQ(only_error(with("servo_period_s", "0.001\ndecimal_point_input = \"fanuc\"")),
              "4:23: decimal_point_input 'fanuc' is not one of calculator least_increment");
}

TEST(MachineConfig, PhaseTableDefaultsToNone) {
    Result<MachineConfig> result = parse_machine_config(valid_config, "m.toml");
    ASSERT_TRUE(result.ok());
    EXPECT_EQ(result->axes[0].phase_table, PhaseTableKind::none);
    for (const AxisConfig& axis : default_mill().axes) {
        EXPECT_EQ(axis.phase_table, PhaseTableKind::none);
    }
}

TEST(MachineConfig, ReadsEveryPhaseTableName) {
    const std::array expected{PhaseTableKind::none, PhaseTableKind::three_phase_six_beat,
                              PhaseTableKind::three_phase_three_beat, PhaseTableKind::two_phase_full_step,
                              PhaseTableKind::two_phase_half_step};
    static_assert(expected.size() == phase_table_names.size());
    for (std::size_t i = 0; i < expected.size(); ++i) {
        const std::string value = "0.0\nphase_table = \"" + std::string(phase_table_names[i]) + "\"";
        Result<MachineConfig> result = parse_machine_config(with("backlash", value), "m.toml");
        ASSERT_TRUE(result.ok()) << phase_table_names[i];
        EXPECT_EQ(result->axes[0].phase_table, expected[i]) << phase_table_names[i];
    }
}

TEST(MachineConfigError, PhaseTableMustBeAKnownName) {
    EXPECT_EQ(only_error(with("backlash", "0.0\nphase_table = \"3phase-12beat\"")),
              "15:15: phase_table '3phase-12beat' is not one of none 3phase-6beat 3phase-3beat "
              "2phase-full 2phase-half");
    EXPECT_EQ(only_error(with("backlash", "0.0\nphase_table = 6")),
              "15:15: 'phase_table' must be a string, not an integer");
}

TEST(MachineConfigError, AtLeastOneAxis) {
    std::string config(valid_config);
    const std::size_t axis_start = config.find("[[axis]]");
    config.erase(axis_start, config.find("[spindle]") - axis_start);
    EXPECT_EQ(only_error(config), "1:1: at least one [[axis]] is required");
    EXPECT_EQ(only_error("axis = []\n[machine]\nname = \"m\"\n"), "1:8: at least one [[axis]] is required");
}

TEST(MachineConfigError, AxisMustBeAnArrayOfTables) {
    std::string config(valid_config);
    config.replace(config.find("[[axis]]"), 8, "[axis]");
    EXPECT_EQ(only_error(config), "5:1: 'axis' must be an array of tables ([[axis]]), not a table");
}

TEST(MachineConfigError, SectionsMustBeTables) {
    std::string config(valid_config);
    config.replace(config.find("[spindle]"), 9, "[[spindle]]");
    EXPECT_EQ(only_error(config), "16:1: 'spindle' must be a table ([spindle]), not an array");
}

TEST(MachineConfigError, UnknownKeysEverywhere) {
    EXPECT_EQ(only_error(with("servo_period_s", "0.001\nservo_perod = 2")),
              "4:1: unknown key 'servo_perod' in [machine]");
    EXPECT_EQ(only_error(with("backlash", "0.0\nmax_acceleraton = 10")),
              "15:1: unknown key 'max_acceleraton' in [[axis]]");
    EXPECT_EQ(only_error(with("encoder_counts", "4096\nfoo = 1")), "19:1: unknown key 'foo' in [spindle]");
    EXPECT_EQ(only_error(std::string(valid_config) + "[coolant]\n"), "19:2: unknown table [coolant]");
    EXPECT_EQ(only_error("answer = 42\n" + std::string(valid_config)), "1:1: unknown key 'answer' at top level");
}

TEST(MachineConfigError, ExactStopMcodesAreNonNegativeIntegers) {
    EXPECT_EQ(only_error(with("servo_period_s", "0.001\nexact_stop_mcodes = [24, -3]")),
              "4:26: each entry of 'exact_stop_mcodes' must be zero or more, not -3");
    EXPECT_EQ(only_error(with("servo_period_s", "0.001\nexact_stop_mcodes = [\"M24\"]")),
              "4:22: each entry of 'exact_stop_mcodes' must be an integer, not a string");
    EXPECT_EQ(only_error(with("servo_period_s", "0.001\nexact_stop_mcodes = 24")),
              "4:21: 'exact_stop_mcodes' must be an array, not an integer");
}

TEST(MachineConfigError, LaserMcodesAreNonNegativeIntegers) {
    EXPECT_EQ(only_error(with("servo_period_s", "0.001\nlaser_on_mcodes = [27, -3]")),
              "4:24: each entry of 'laser_on_mcodes' must be zero or more, not -3");
    EXPECT_EQ(only_error(with("servo_period_s", "0.001\nlaser_off_mcodes = [\"M28\"]")),
              "4:21: each entry of 'laser_off_mcodes' must be an integer, not a string");
    EXPECT_EQ(only_error(with("servo_period_s", "0.001\nlaser_off_mcodes = 28")),
              "4:20: 'laser_off_mcodes' must be an array, not an integer");
}

TEST(MachineConfigError, LaserMcodeCannotSwitchBothWays) {
    EXPECT_EQ(only_error(with("servo_period_s", "0.001\nlaser_on_mcodes = [27]\nlaser_off_mcodes = [28, 27]")),
              "5:20: M27 is in both 'laser_on_mcodes' and 'laser_off_mcodes'");
}

TEST(MachineConfigError, CollectsEveryErrorInFileOrder) {
    std::string config = with("max_jerk", "0");
    config.replace(config.find("max_rpm = 6000"), 14, "max_rpm = \"fast\"");
    config.replace(config.find("name = \"m\""), 10, "nmae = \"m\"");
    const Diagnostics errors = errors_of(config);
    ASSERT_EQ(errors.size(), 4U);
    EXPECT_EQ(format_diagnostic(errors[0]), "m.toml:1:1: error: missing key 'name' in [machine]");
    EXPECT_EQ(format_diagnostic(errors[1]), "m.toml:2:1: error: unknown key 'nmae' in [machine]");
    EXPECT_EQ(format_diagnostic(errors[2]), "m.toml:10:12: error: 'max_jerk' must be positive, not 0");
    EXPECT_EQ(format_diagnostic(errors[3]), "m.toml:17:11: error: 'max_rpm' must be a number, not a string");
    EXPECT_EQ(errors[1].code, "config-unknown-key");
}

TEST(MachineConfigError, UnreadableFile) {
    Result<MachineConfig> result = load_machine_config("/nonexistent/machine.toml");
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(format_diagnostic(result.diagnostics().front()),
              "/nonexistent/machine.toml:0:0: error: cannot read machine config: no such file or "
              "directory");
    EXPECT_EQ(result.diagnostics().front().code, "config-io");
}

}  // namespace
}  // namespace nckit
