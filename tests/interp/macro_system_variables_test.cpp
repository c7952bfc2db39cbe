// Custom Macro B system variables: #3000 user alarms, #3001/#3002 timers on simulated time,
// #3901/#3902 part counts, #4001- modal G codes, #4107- modal values, #5001- positions and
// #5221- work offsets (read and write).
#include <gtest/gtest.h>

#include "macro_support.hpp"

namespace nckit::test {
namespace {

// ---- #3000 ---------------------------------------------------------------------------------

TEST(MacroSystemVariables, UserAlarmCarriesTheBlocksComment) {
    RunResult r = run_program("G1 X1 F100\nN20 #3000=12 (TOOL BROKEN)\nG1 X2\n", wide_mill());
    ASSERT_TRUE(r.error.has_value());
    EXPECT_EQ(r.error->alarm, 3012);
    EXPECT_EQ(r.error->code, "user-alarm");
    EXPECT_EQ(r.error->message, "TOOL BROKEN");
    EXPECT_EQ(format_diagnostic(*r.error), "test.ngc:2:5: error: alarm 3012: TOOL BROKEN");
    EXPECT_EQ(r.moves.size(), 1U);
}

TEST(MacroSystemVariables, UserAlarmWithoutCommentOrFromIfThen) {
    Diagnostic d = error_of("#3000=1\n", wide_mill());
    EXPECT_EQ(d.alarm, 3001);
    EXPECT_EQ(d.message, "user alarm");
    EXPECT_EQ(alarm_of("IF [#1 EQ #0] THEN #3000=7 (A MISSING)\n"), "3007 1:20");
    EXPECT_EQ(alarm_of("#5=2\n#3000=#5*50 (X)\n"), "3100 2:1");
    EXPECT_EQ(value_of("#3000"), std::nullopt);
    // The number must make a user alarm: 0 .. 9999.
    EXPECT_EQ(alarm_of("#3000=-1 (NEGATIVE)\n"), "119 1:1");
    EXPECT_EQ(alarm_of("#3000=10000\n"), "119 1:1");
    EXPECT_EQ(alarm_of("#3000=9999\n"), "12999 1:1");
    EXPECT_EQ(alarm_of("#3000=0.4\n"), "3000 1:1");
}

// ---- timers and part counts ----------------------------------------------------------------

TEST(MacroSystemVariables, MillisecondTimerRunsOnSimulatedTime) {
    EXPECT_EQ(value_after("G4 P2500\n#1=#3001"), 2500.0);
    EXPECT_EQ(value_after("G1 X100 F6000\n#1=#3001"), 1000.0);  // 100 mm at 100 mm/s
    EXPECT_EQ(value_after("G0 X50\n#1=#3001"), 500.0);          // rapid at the axis' 100 mm/s
    EXPECT_EQ(value_after("G4 P1000\n#3001=100\nG4 P500\n#1=#3001"), 600.0);
    EXPECT_EQ(value_after("#1=#3001"), 0.0);
}

TEST(MacroSystemVariables, HourTimer) {
    EXPECT_EQ(value_after("G4 P1800000\n#1=#3002"), 0.5);
    EXPECT_EQ(value_after("#3002=2\nG4 P3600000\n#1=#3002"), 3.0);
}

TEST(MacroSystemVariables, SingleBlockAndFeedHoldSwitchesAreAccepted) {
    EXPECT_EQ(xs("#3003=1\n#3004=7\nG1 X1 F100\n"), (std::vector<double>{1}));
}

TEST(MacroSystemVariables, PartCounters) {
    EXPECT_EQ(value_after("#1=#3901+#3902"), 0.0);
    EXPECT_EQ(value_after("#3901=5\n#3902=10\n#1=#3901+#3902*100"), 1005.0);
}

// ---- modal information ---------------------------------------------------------------------

TEST(MacroSystemVariables, ModalGCodesAtStart) {
    // Groups 1..15 of a mill at power-on; groups nckit has no codes for are vacant.
    std::vector<double> expected = {0,  17, 90, -1, 94, 21, 40, 49, 80, 98, 50,
                                    67, 97, 54, 64, -1, -1, -1, -1, -1, -1, -1};
    for (int group = 1; group <= 22; ++group) {
        std::optional<double> v = value_of("#" + std::to_string(4000 + group));
        EXPECT_EQ(v.value_or(-1), expected[static_cast<std::size_t>(group - 1)]) << "group " << group;
    }
}

TEST(MacroSystemVariables, ModalGCodesFollowTheProgram) {
    EXPECT_EQ(value_after("G1 X1 F100\n#1=#4001"), 1.0);
    EXPECT_EQ(value_after("G3 X0 Y0 I1 F100\n#1=#4001"), 3.0);
    // G80 is group 09 on a Fanuc control: group 01 keeps its code.
    EXPECT_EQ(value_after("G1 X1 F100\nG80\n#1=#4001"), 1.0);
    EXPECT_EQ(value_after("G80\n#1=#4009"), 80.0);
    EXPECT_EQ(value_after("G18\n#1=#4002"), 18.0);
    EXPECT_EQ(value_after("G19\n#1=#4002"), 19.0);
    EXPECT_EQ(value_after("G91\n#1=#4003"), 91.0);
    EXPECT_EQ(value_after("G95\n#1=#4005"), 95.0);
    EXPECT_EQ(value_after("G20\n#1=#4006"), 20.0);
    EXPECT_EQ(value_after("G66 P100\n#1=#4012\nG67"), 66.0);  // O100 is needed only by a move
    EXPECT_EQ(value_after("G66 P100\nG67\n#1=#4012"), 67.0);
    EXPECT_EQ(value_after("G96 S100\n#1=#4013"), 96.0);
    EXPECT_EQ(value_after("G57\n#1=#4014"), 57.0);
    EXPECT_EQ(value_after("G59\n#1=#4014"), 59.0);
    EXPECT_EQ(value_after("G61\n#1=#4015"), 61.0);
    EXPECT_EQ(value_after("#1=#4002"), 17.0);
    EXPECT_EQ(value_of("#4002+#4003"), 107.0);
    MachineConfig lathe_machine = lathe();
    std::vector<Io> io = only<Io>(moves_of("#1=#4002\nG96 S#1\n", lathe_machine));
    ASSERT_EQ(io.size(), 1U);
    EXPECT_EQ(io[0].value, 18.0);  // a lathe starts in G18
}

TEST(MacroSystemVariables, ModalValues) {
    EXPECT_EQ(value_after("G1 X1 F250\n#1=#4109"), 250.0);
    EXPECT_NEAR(*value_after("G20\nG1 X1 F12.5\n#1=#4109"), 12.5, 1e-12);  // program units: in/min
    EXPECT_EQ(value_after("M8\n#1=#4113"), 8.0);
    EXPECT_EQ(value_after("M8 M3 S100\n#1=#4113"), 3.0);
    EXPECT_EQ(value_after("N50 G1 X1 F100\n#1=#4114"), 50.0);
    EXPECT_EQ(value_after("N60 #1=#4114"), 60.0);
    EXPECT_EQ(value_after("S1500 M3\n#1=#4119"), 1500.0);
    EXPECT_EQ(value_after("G96 S200\n#1=#4119"), 200.0);
    EXPECT_NEAR(*value_after("G20 G96 S500\n#1=#4119"), 500.0, 1e-9);  // ft/min, as programmed
    EXPECT_NEAR(*value_after("G20 G96 S500\nG21\n#1=#4119"), 152.4, 1e-9);
    EXPECT_EQ(value_after("T5 M6\n#1=#4120"), 5.0);
    EXPECT_EQ(value_of("#4107"), 0.0);  // no cutter compensation: D0
    EXPECT_EQ(value_of("#4111"), 0.0);  // no tool length offsets: H0
}

TEST(MacroSystemVariables, ProgramNumber) {
    EXPECT_EQ(value_of("#4115"), 0.0);  // a main program without an O line
    EXPECT_EQ(value_after("O1234\n#1=#4115"), 1234.0);
    EXPECT_EQ(xs("O1\nM98 P200\nG65 P300\nG1 X#4115 F100\nM30\nO200\nG1 X#4115 F100\nM99\nO300\nG1 X#4115\nM99\n"),
              (std::vector<double>{200, 300, 1}));
}

// ---- positions -----------------------------------------------------------------------------

TEST(MacroSystemVariables, EndPointInWorkCoordinates) {
    EXPECT_EQ(value_after("G1 X1 Y2 Z3 F100\n#1=#5001+#5002*10+#5003*100"), 321.0);
    EXPECT_EQ(value_after("G10 L2 P1 X100\nG0 X5\n#1=#5001"), 5.0);
    EXPECT_EQ(value_after("G10 L2 P1 X100\nG0 X5\n#1=#5041"), 5.0);
    EXPECT_EQ(value_after("G10 L2 P1 X100\nG0 X5\n#1=#5021"), 105.0);             // machine coordinates
    EXPECT_EQ(value_after("G20\nG0 X1\n#1=#5001+#5021"), 2.0);                    // inch
    EXPECT_EQ(value_after("#1=#5004"), std::nullopt);                             // a 3-axis mill has no 4th axis
    EXPECT_EQ(value_after("G0 X10\nG92 X0\nG0 X3\n#1=#5001+#5021*100"), 1303.0);  // G92 counts
}

TEST(MacroSystemVariables, RotaryAxisIsTheFourth) {
    std::vector<Io> io = only<Io>(moves_of("G0 A45\n#1=#5004+#5024\nG96 S#1\n", mill_with_a()));
    ASSERT_EQ(io.size(), 1U);
    EXPECT_EQ(io[0].value, 90.0);
}

TEST(MacroSystemVariables, LatheXIsADiameter) {
    std::vector<Io> io = only<Io>(moves_of("G0 X20 Z-5\n#1=#5001*100-#5002\nG96 S#1\n", lathe()));
    ASSERT_EQ(io.size(), 1U);
    EXPECT_EQ(io[0].value, 2005.0);  // X20 (diameter), Z-5: lathe axes are 1 = X, 2 = Z
}

// ---- work offsets --------------------------------------------------------------------------

TEST(MacroSystemVariables, WorkOffsetsReadBack) {
    EXPECT_EQ(value_after("G10 L2 P2 X7 Y8\n#1=#5241+#5242*10"), 87.0);
    EXPECT_EQ(value_after("G10 L2 P6 Z4\n#1=#5323"), 4.0);
    EXPECT_EQ(value_of("#5221+#5222+#5223"), 0.0);
    EXPECT_EQ(value_of("#5226"), std::nullopt);    // G54 of a 6th axis this machine lacks
    EXPECT_EQ(alarm_of("#1=#5227\n"), "115 1:4");  // between two systems
}

TEST(MacroSystemVariables, WritingAWorkOffsetShiftsTheMove) {
    EXPECT_EQ(texts("#5221=10\n#5222=-20\nG54 G0 X0 Y0\n", wide_mill()), (Texts{"G0 X10.0000 Y-20.0000 Z0.0000"}));
    // Written while its system is active: the next move uses it.
    EXPECT_EQ(xs("G55\nG0 X1\n#5241=5\nG0 X1\n"), (std::vector<double>{1, 6}));
    const char* systems = "G54G55G56G57G58G59";
    for (int s = 0; s < 6; ++s) {
        std::string program = "#" + std::to_string(5221 + 20 * s) + "=" + std::to_string(s + 1) + "\n" +
                              std::string(systems + 3 * s, 3) + " G0 X0\n";
        EXPECT_EQ(xs(program), (std::vector<double>{s + 1.0})) << program;
    }
}

TEST(MacroSystemVariables, WorkOffsetsAreInProgramUnits) {
    EXPECT_EQ(xs("G20\n#5221=1\nG0 X0\n"), (std::vector<double>{25.4}));
    EXPECT_EQ(value_after("G20\n#5221=1\nG21\n#1=#5221"), 25.4);
    // A lathe's X offset is a diameter.
    std::vector<Line> lines = only<Line>(moves_of("#5221=10\nG0 X0\n", lathe()));
    ASSERT_EQ(lines.size(), 1U);
    EXPECT_EQ(lines[0].to[Axis::X], 5.0);
}

TEST(MacroSystemVariables, WorkOffsetOfAMissingAxisIsIllegal) {
    EXPECT_EQ(alarm_of("#5224=1\n"), "115 1:1");
    EXPECT_EQ(alarm_of("#5240=1\n"), "115 1:1");
}

}  // namespace
}  // namespace nckit::test
