#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "nckit/core/machine.hpp"
#include "nckit/core/tool_table.hpp"

namespace nckit {
namespace {

std::string first_error(const Diagnostics& diagnostics) {
    if (diagnostics.empty()) return "no error";
    return format_diagnostic(diagnostics.front());
}

TEST(ToolTableToml, ReadsEveryColumnAndLooksUpByNumber) {
    Result<ToolTable> table = parse_tool_toml(R"(
[[tool]]
number = 1
pocket = 3
length_mm = 120.5
length_wear_mm = -0.02
diameter_mm = 10.0
diameter_wear_mm = -0.04
comment = "10 mm end mill"

[[tool]]
number = 12
radius_mm = 3.0

[[tool]]
number = 21
x_offset_mm = -1.5
length_mm = 30
nose_radius_mm = 0.4
orientation = 3
)",
                                              "tools.toml");
    ASSERT_TRUE(table.ok()) << first_error(table.diagnostics());
    ASSERT_EQ(table->size(), 3u);
    EXPECT_DOUBLE_EQ(*table->length_mm(1), 120.48);
    EXPECT_DOUBLE_EQ(*table->radius_mm(1), 4.98);  // (10 - 0.04) / 2
    EXPECT_EQ(table->find(1)->pocket, 3);
    EXPECT_EQ(table->find(1)->comment, "10 mm end mill");
    EXPECT_DOUBLE_EQ(*table->radius_mm(12), 3.0);
    EXPECT_DOUBLE_EQ(*table->length_mm(12), 0.0);
    EXPECT_DOUBLE_EQ(table->find(21)->nose_radius_mm(), 0.4);
    EXPECT_EQ(table->find(21)->orientation, 3);
    EXPECT_DOUBLE_EQ(table->find(21)->x_offset_mm, -1.5);
    EXPECT_EQ(table->length_mm(0), 0.0);  // H0: no offset
    EXPECT_FALSE(table->length_mm(7));    // no row 7
    EXPECT_FALSE(table->radius_mm(7));
}

TEST(ToolTableToml, ErrorsCarryLineAndColumn) {
    auto error = [](std::string_view text) {
        Result<ToolTable> t = parse_tool_toml(text, "t.toml");
        EXPECT_FALSE(t.ok()) << text;
        return t.ok() ? std::string() : first_error(t.diagnostics());
    };
    EXPECT_EQ(error("[[tool]]\nnumber = 1\nlenght_mm = 3\n"), "t.toml:3:1: error: unknown key 'lenght_mm' in [[tool]]");
    EXPECT_EQ(error("[[tool]]\nnumber = 1\n[[tool]]\nnumber = 1\n"), "t.toml:4:10: error: tool 1 is listed twice");
    EXPECT_EQ(error("[[tool]]\nnumber = 1\nradius_mm = 1\ndiameter_mm = 2\n"),
              "t.toml:4:15: error: give 'radius_mm' or 'diameter_mm', not both");
    EXPECT_EQ(error("[[tool]]\nnumber = 1\norientation = 12\n"),
              "t.toml:3:15: error: 'orientation' is a tip orientation 0 to 9, not 12");
    // A number a T word cannot select (a fuzzer found 299999999 accepted).
    EXPECT_EQ(error("[[tool]]\nnumber = 299999999\n"),
              "t.toml:2:10: error: 'number' is a tool number 1 to 99999999, not 299999999");
    EXPECT_NE(error("[[tool]]\nlength_mm = 3\n").find("t.toml:1:1: error:"), std::string::npos);
    EXPECT_NE(error("[[tool]]\nnumber = 1\ndiameter_mm = -2\n").find("t.toml:3:15: error:"), std::string::npos);
    // Values a tool cannot have (a fuzzer found 1e308 + 1e308 wear overflowing to infinity).
    EXPECT_EQ(error("[[tool]]\nnumber = 1\ndiameter_mm = 1e308\n"),
              "t.toml:3:15: error: 'diameter_mm' is beyond the 100000 mm a tool can measure");
    EXPECT_EQ(error("[[tool]]\nnumber = 1\nlength_wear_mm = -2e5\n"),
              "t.toml:3:18: error: 'length_wear_mm' is beyond the 100000 mm a tool can measure");
}

TEST(ToolTableLinuxcnc, ReadsToolTblAsItIs) {
    Result<ToolTable> table = parse_tool_tbl(
        "T1 P1 Z+12.500000 D+6.000000 ;6 mm drill\n"
        "\n"
        "t2 p2 x0 y0 z-3.25 d0.5 q0\n"
        "T3 P3 X+0.5 Z+0.25 D0.8 I95 J155 Q2 ;lathe tool\r\n",
        "tool.tbl");
    ASSERT_TRUE(table.ok()) << first_error(table.diagnostics());
    ASSERT_EQ(table->size(), 3u);
    EXPECT_DOUBLE_EQ(*table->length_mm(1), 12.5);
    EXPECT_DOUBLE_EQ(*table->radius_mm(1), 3.0);
    EXPECT_EQ(table->find(1)->comment, "6 mm drill");
    EXPECT_DOUBLE_EQ(*table->length_mm(2), -3.25);
    EXPECT_DOUBLE_EQ(table->find(3)->x_offset_mm, 0.5);
    EXPECT_DOUBLE_EQ(table->find(3)->nose_radius_mm(), 0.4);
    EXPECT_EQ(table->find(3)->orientation, 2);
    EXPECT_DOUBLE_EQ(table->find(3)->back_angle_deg, 155);
}

TEST(ToolTableLinuxcnc, InchValuesScaleToMm) {
    Result<ToolTable> table = parse_tool_tbl("T1 Z1.0 D0.5\n", "tool.tbl", true);
    ASSERT_TRUE(table.ok());
    EXPECT_DOUBLE_EQ(*table->length_mm(1), 25.4);
    EXPECT_DOUBLE_EQ(*table->radius_mm(1), 6.35);
}

TEST(ToolTableLinuxcnc, BadLinesAreLocated) {
    auto error = [](std::string_view text) {
        Result<ToolTable> t = parse_tool_tbl(text, "tool.tbl");
        EXPECT_FALSE(t.ok()) << text;
        return t.ok() ? std::string() : first_error(t.diagnostics());
    };
    EXPECT_EQ(error("T1 Z1\nT2 Zx\n"), "tool.tbl:2:4: error: Z needs a number");
    EXPECT_EQ(error("T1 Z1\n  T1 Z2\n"), "tool.tbl:2:3: error: tool 1 is listed twice");
    EXPECT_EQ(error("T1.5 Z1\n"), "tool.tbl:1:1: error: T must be a whole number from 0 to 99999999");
    EXPECT_EQ(error("T1 Z1 Z2\n"), "tool.tbl:1:7: error: Z appears twice in one tool");
    EXPECT_EQ(error("T1 Y2\n"), "tool.tbl:1:4: error: a Y offset is not supported (only Z, X, D, Q, I, J)");
    EXPECT_EQ(error("P1 Z2\n"), "tool.tbl:1:1: error: tool line without T (tool number)");
    EXPECT_EQ(error("T1 D-1\n"), "tool.tbl:1:4: error: D (diameter) must not be negative");
    EXPECT_EQ(error("T1 K1\n"), "tool.tbl:1:4: error: K is not a tool table column");
    EXPECT_EQ(error("T1 Z2e5\n"), "tool.tbl:1:4: error: Z 200000 is beyond the 100000 mm a tool can measure");
    // An inch table's ×25.4 must not overflow a value that strtod still reads.
    Result<ToolTable> inch = parse_tool_tbl("T1 D1e308\n", "tool.tbl", true);
    ASSERT_FALSE(inch.ok());
    EXPECT_EQ(first_error(inch.diagnostics()),
              "tool.tbl:1:4: error: D 1e+308 is beyond the 100000 mm a tool can measure");
}

TEST(ToolTableFile, MachineFileNamesItsToolFile) {
    auto dir = std::filesystem::temp_directory_path() / "nckit_tool_table_test";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "tool.tbl") << "T5 Z10 D4\n";
    const std::string machine = R"([machine]
name = "m"
tools = "tool.tbl"

[[axis]]
name = "Z"
kind = "linear"
max_velocity = 100.0
max_acceleration = 500.0
max_jerk = 50000.0
min = -500.0
max = 500.0
steps_per_unit = 800.0
tool_change = 100.0
)";
    std::ofstream(dir / "m.toml") << machine;
    Result<MachineConfig> config = load_machine_config(dir / "m.toml");
    ASSERT_TRUE(config.ok()) << first_error(config.diagnostics());
    EXPECT_DOUBLE_EQ(*config->tools.length_mm(5), 10.0);
    EXPECT_DOUBLE_EQ(*config->axes[0].tool_change, 100.0);

    std::string missing = machine;
    missing.replace(missing.find("tool.tbl"), 8, "none.tbl");
    std::ofstream(dir / "bad.toml") << missing;
    Result<MachineConfig> bad = load_machine_config(dir / "bad.toml");
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(first_error(bad.diagnostics()).find("bad.toml:3:9: error: tool file"), std::string::npos)
        << first_error(bad.diagnostics());

    std::ofstream(dir / "tool.tbl") << "T5 Z10 D4 Q11\n";
    Result<MachineConfig> bad_table = load_machine_config(dir / "m.toml");
    ASSERT_FALSE(bad_table.ok());
    EXPECT_NE(first_error(bad_table.diagnostics()).find("tool.tbl:1:11: error: Q is a tip orientation"),
              std::string::npos)
        << first_error(bad_table.diagnostics());
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace nckit
