// The machine file's [probe] and [inputs] tables: what they read, and every malformed use
// named at its place in the file (machine_probe_inputs.cpp).
#include <string>
#include <string_view>

#include <gtest/gtest.h>

#include "nckit/core/machine.hpp"

namespace nckit {
namespace {

// Lines 1-8; a test appends its tables from line 9 on.
constexpr std::string_view base = R"([machine]
name = "m"
servo_period_s = 0.001

[[axis]]
name = "Z"
kind = "linear"
max_velocity = 100.0
)";

std::string config(std::string_view tables) {
    return std::string(base) +
           "max_acceleration = 500.0\nmax_jerk = 50000.0\nmin = -500.0\nmax = 500.0\nsteps_per_unit = 800.0\n"
           "backlash = 0.0\n" +
           std::string(tables);
}
constexpr int first_line = 15;  // the first line of `tables`

//! Every error `tables` gives, one `LINE:COL: code: message` a line.
std::string errors_of(std::string_view tables) {
    Result<MachineConfig> result = parse_machine_config(config(tables), "m.toml");
    if (result.ok()) return "accepted";
    std::string out;
    for (const Diagnostic& d : result.diagnostics()) {
        out += std::to_string(d.location.line - first_line + 1) + ":" + std::to_string(d.location.column) + ": " +
               d.code + ": " + d.message + "\n";
    }
    return out;
}

TEST(MachineProbeInputs, ReadsSurfacesAndInputs) {
    Result<MachineConfig> result =
        parse_machine_config(config("[probe]\nsurfaces = [{ axis = \"Z\", at = -20.5 }, { axis = \"z\", at = 3 }]\n\n"
                                    "[inputs]\n1000 = 1\n1199 = -2.5\n"),
                             "m.toml");
    ASSERT_TRUE(result.ok()) << format_diagnostic(result.diagnostics().front());
    const MachineConfig& m = result.value();
    ASSERT_EQ(m.probe_surfaces.size(), 2U);
    EXPECT_EQ(m.probe_surfaces[0].axis, Axis::Z);
    EXPECT_EQ(m.probe_surfaces[0].at_mm, -20.5);
    EXPECT_EQ(m.probe_surfaces[1].at_mm, 3.0);
    ASSERT_EQ(m.macro_inputs.size(), 2U);
    EXPECT_EQ(m.macro_inputs[0].number, 1000);
    EXPECT_EQ(m.macro_inputs[1].number, 1199);
    EXPECT_EQ(m.macro_inputs[1].value, -2.5);
}

TEST(MachineProbeInputs, WithoutTheTablesNothingIsConfigured) {
    Result<MachineConfig> result = parse_machine_config(config(""), "m.toml");
    ASSERT_TRUE(result.ok());
    EXPECT_TRUE(result.value().probe_surfaces.empty());
    EXPECT_TRUE(result.value().macro_inputs.empty());
}

TEST(MachineProbeInputsError, SurfaceNeedsAnAxisLetterAndAPlace) {
    EXPECT_EQ(errors_of("[probe]\nsurfaces = [{ axis = \"Q\", at = 1 }]\n"),
              "2:22: config-value: 'Q' is not an axis letter\n");
    EXPECT_EQ(errors_of("[probe]\nsurfaces = [{ axis = \"XY\", at = 1 }]\n"),
              "2:22: config-value: 'XY' is not an axis letter\n");
    EXPECT_NE(errors_of("[probe]\nsurfaces = [{ axis = \"Z\" }]\n").find("2:"), std::string::npos);
    EXPECT_NE(errors_of("[probe]\nsurfaces = [{ at = 1 }]\n").find("'axis'"), std::string::npos);
    EXPECT_NE(errors_of("[probe]\nsurfaces = [{ axis = \"Z\", at = \"low\" }]\n").find("config-type"),
              std::string::npos);
    EXPECT_NE(errors_of("[probe]\nsurfaces = [{ axis = \"Z\", at = 1, depth = 2 }]\n").find("config-unknown-key"),
              std::string::npos);
}

TEST(MachineProbeInputsError, SurfacesAreAnArrayOfTablesOfBoundedLength) {
    EXPECT_EQ(errors_of("[probe]\nsurfaces = [1]\n"),
              "2:13: config-type: a probe surface is a table: { axis = \"Z\", at = -20.0 }\n");
    EXPECT_NE(errors_of("[probe]\n").find("surfaces"), std::string::npos);
    EXPECT_NE(errors_of("[probe]\nsurfaces = []\nspeed = 3\n").find("3:1: config-unknown-key"), std::string::npos);
    std::string many = "[probe]\nsurfaces = [";
    for (int i = 0; i < 65; ++i) many += std::string(i ? ", " : "") + "{ axis = \"Z\", at = 1 }";
    EXPECT_NE(errors_of(many + "]\n").find("at most 64 probe surfaces"), std::string::npos);
}

TEST(MachineProbeInputsError, InputsAreNumbered1000To1199WithNumbers) {
    EXPECT_EQ(errors_of("[inputs]\n999 = 1\n"),
              "2:7: config-unknown-key: [inputs] keys are macro variable numbers 1000 to 1199, not '999'\n");
    EXPECT_NE(errors_of("[inputs]\n1200 = 1\n").find("not '1200'"), std::string::npos);
    EXPECT_NE(errors_of("[inputs]\nstart = 1\n").find("not 'start'"), std::string::npos);
    EXPECT_NE(errors_of("[inputs]\n1001x = 1\n").find("not '1001x'"), std::string::npos);
    EXPECT_NE(errors_of("[inputs]\n1001 = \"on\"\n").find("2:8: config-type"), std::string::npos);
    // Every bad key is reported, not only the first.
    const std::string two = errors_of("[inputs]\n1 = 1\n2 = 2\n");
    EXPECT_NE(two.find("2:5:"), std::string::npos) << two;
    EXPECT_NE(two.find("3:5:"), std::string::npos) << two;
}

}  // namespace
}  // namespace nckit
