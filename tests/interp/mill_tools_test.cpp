// Tool table in the interpreter: T, M6 and the tool-change position, G43/G44/G43.1/G49, G10
// L1/L10-L13, #2001-#2800, #4107/#4111/#4120, #5081-.
#include <string>

#include <gtest/gtest.h>

#include "interp_support.hpp"

namespace nckit::test {
namespace {

MachineConfig mill_with_tools() {
    MachineConfig m = default_mill();
    ToolEntry t1;
    t1.number = 1;
    t1.length_mm = 100.0;
    t1.length_wear_mm = -0.5;
    t1.radius_mm = 5.0;
    m.tools.insert(t1);
    ToolEntry t2;
    t2.number = 2;
    t2.length_mm = 50.0;
    m.tools.insert(t2);
    return m;
}

TEST(ToolLength, G43AddsTheLengthToZ) {
    EXPECT_EQ(texts("G43 H1 G0 Z10\nG49 G0 Z10\n", mill_with_tools()),
              (Texts{"G0 X0.0000 Y0.0000 Z109.5000", "G0 X0.0000 Y0.0000 Z10.0000"}));
}

TEST(ToolLength, G44SubtractsIt) {
    EXPECT_EQ(texts("G44 H2 G0 Z0\n", mill_with_tools()), (Texts{"G0 X0.0000 Y0.0000 Z-50.0000"}));
}

TEST(ToolLength, G43WithoutHTakesTheToolInTheSpindle) {
    EXPECT_EQ(texts("T2 M6\nG43 G0 Z1\n", mill_with_tools()), (Texts{"T2", "M6", "G0 X0.0000 Y0.0000 Z51.0000"}));
}

TEST(ToolLength, AnHWordUnderG43SwitchesTheOffset) {
    EXPECT_EQ(texts("G43 H1\nH2 G0 Z0\n", mill_with_tools()), (Texts{"G0 X0.0000 Y0.0000 Z50.0000"}));
}

TEST(ToolLength, G431TakesTheLengthFromZ) {
    EXPECT_EQ(texts("G43.1 Z12.5\nG0 Z0\n", mill_with_tools()), (Texts{"G0 X0.0000 Y0.0000 Z12.5000"}));
}

TEST(ToolLength, InchProgramsConvertTheWordsNotTheTable) {
    EXPECT_EQ(texts("G20 G43 H2 G0 Z1\n", mill_with_tools()), (Texts{"G0 X0.0000 Y0.0000 Z75.4000"}));
}

TEST(ToolLength, WorkPositionIgnoresTheOffset) {
    EXPECT_EQ(texts("G43 H2 G0 Z5\n#100 = #5003\n#101 = #5083\nG49 G0 X#100 Y#101\n", mill_with_tools()),
              (Texts{"G0 X0.0000 Y0.0000 Z55.0000", "G0 X5.0000 Y50.0000 Z55.0000"}));
}

TEST(ToolLength, HWithoutEntryIsAnError) {
    EXPECT_EQ(error_where("G0 X1\nG43 H7 Z5\n", mill_with_tools()), "no-tool-offset 2:5");
    EXPECT_EQ(error_where("G43 H1 Z5\n"), "no-tool-offset 1:5");  // no table at all
    EXPECT_EQ(error_where("G43 H1.5 Z5\n", mill_with_tools()), "bad-value 1:5");
}

TEST(ToolChange, M6GoesToTheToolChangePositionZFirst) {
    MachineConfig m = mill_with_tools();
    m.axes[2].tool_change = 200.0;
    m.axes[0].tool_change = -100.0;
    EXPECT_EQ(texts("G0 X5 Y5 Z5\nT1 M6\n", m),
              (Texts{"G0 X5.0000 Y5.0000 Z5.0000", "T1", "G0 X5.0000 Y5.0000 Z200.0000",
                     "G0 X-100.0000 Y5.0000 Z200.0000", "M6"}));
}

TEST(ToolChange, G30GoesToTheToolChangePosition) {
    MachineConfig m = default_mill();
    m.axes[2].tool_change = 150.0;
    EXPECT_EQ(texts("G91 G30 Z0\nG0 G28 G91 Z0\n", m),
              (Texts{"G0 X0.0000 Y0.0000 Z0.0000", "G0 X0.0000 Y0.0000 Z150.0000", "G0 X0.0000 Y0.0000 Z150.0000",
                     "G0 X0.0000 Y0.0000 Z0.0000"}));
}

TEST(ToolTableWrites, G10L10ToL13SetLengthsAndRadii) {
    std::string program =
        "G10 L10 P3 R20\nG10 L11 P3 R-0.5\nG10 L12 P3 R4\nG10 L13 P3 R0.1\n"
        "G43 H3 G0 Z0\n#100 = #2003\n#101 = #2203\n#102 = #2403\n#103 = #2603\nG49 G0 X#100 Y#101\nX#102 Y#103\n";
    EXPECT_EQ(texts(program),
              (Texts{"G0 X0.0000 Y0.0000 Z19.5000", "G0 X-0.5000 Y20.0000 Z19.5000", "G0 X0.1000 Y4.0000 Z19.5000"}));
}

TEST(ToolTableWrites, G91AddsAndLinuxcncFormSetsZ) {
    EXPECT_EQ(texts("G10 L1 P4 Z10 R3\nG91 G10 L1 P4 R2\nG90 G43 H4 G0 Z0\n"), (Texts{"G0 X0.0000 Y0.0000 Z12.0000"}));
}

TEST(ToolTableWrites, VariablesWriteTheTable) {
    EXPECT_EQ(texts("#2205 = 30\n#2005 = 1\nG43 H5 G0 Z0\n"), (Texts{"G0 X0.0000 Y0.0000 Z31.0000"}));
}

TEST(ToolTableWrites, MalformedG10IsLocated) {
    EXPECT_EQ(error_where("G10 L10 R3\n"), "bad-g10 1:5");
    EXPECT_EQ(error_where("G10 L11 P1\n"), "missing-word 1:5");
    EXPECT_EQ(error_where("G10 L12 P1 R1 Y3\n"), "unused-word 1:15");
    EXPECT_EQ(error_where("G10 L7 P1 R1\n"), "bad-g10 1:1");
}

TEST(ToolVariables, ModalNumbers) {
    EXPECT_EQ(texts("T2 M6\nG43 H1 D2\n#100 = #4111\n#101 = #4107\n#102 = #4120\nG49 G0 X#100 Y#101 Z#102\n",
                    mill_with_tools()),
              (Texts{"T2", "M6", "G0 X1.0000 Y2.0000 Z2.0000"}));
}

TEST(ToolVariables, BeyondTheOffsetPagesIsNoVariable) {
    EXPECT_EQ(error_of("#2801 = 1\n").alarm, 115);
}

}  // namespace
}  // namespace nckit::test
