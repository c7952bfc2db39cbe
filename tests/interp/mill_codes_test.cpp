// Codes of real mill programs beyond tools and cycles: ,R / ,C corners, G31 skip with #5061-,
// #1000-#1199 inputs and outputs, #3006 program stop.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "interp_support.hpp"

namespace nckit::test {
namespace {

TEST(CornerWords, RoundingPutsATangentArcBetweenTwoLines) {
    // A right-angle corner with ,R2: both lines give up 2·tan(45°) = 2 mm; the arc's centre is
    // 2 mm inside the corner.
    EXPECT_EQ(texts("G0 X0 Y0\nG1 X10 F100 ,R2\nY10\n"),
              (Texts{"G0 X0.0000 Y0.0000 Z0.0000", "G1 X8.0000 Y0.0000 Z0.0000 F100.0000",
                     "G3 X10.0000 Y2.0000 Z0.0000 CX8.0000 CY2.0000 CZ0.0000 F100.0000",
                     "G1 X10.0000 Y10.0000 Z0.0000 F100.0000"}));
}

TEST(CornerWords, ChamferCutsTheSameDistanceFromBothLines) {
    EXPECT_EQ(texts("G0 X0 Y0\nG1 X10 F100 ,C1\nY-10\n"),
              (Texts{"G0 X0.0000 Y0.0000 Z0.0000", "G1 X9.0000 Y0.0000 Z0.0000 F100.0000",
                     "G1 X10.0000 Y-1.0000 Z0.0000 F100.0000", "G1 X10.0000 Y-10.0000 Z0.0000 F100.0000"}));
}

TEST(CornerWords, ObtuseCornerTrimsRTimesTanOfHalfTheTurn) {
    // A 60° turn: each line gives up r·tan(30°).
    const std::vector<Move> moves = moves_of("G0 X0 Y0\nG1 X10 F100 ,R3\nX15 Y8.660254\n");
    const auto lines = only<Line>(moves);
    ASSERT_EQ(lines.size(), 3U);
    EXPECT_NEAR(lines[1].to[Axis::X], 10.0 - 3.0 * std::tan(M_PI / 6), 1e-6);  // the end point has 6 decimals
}

TEST(CornerWords, RoundingBeforeAnArcIsTangentToBoth) {
    const std::vector<Move> moves = moves_of("G0 X0 Y10\nG1 X-10 F100 ,R3\nG3 X-20 Y20 I-10 J0\n");
    const auto arcs = only<Arc>(moves);
    ASSERT_EQ(arcs.size(), 2U);
    const Arc& fillet = arcs[0];
    const Arc& rest = arcs[1];
    // The fillet's centre lies 3 from the line y = 10 and 10 + 3 from the arc's centre (-20, 10).
    EXPECT_NEAR(fillet.center[Axis::Y] - 10.0, 3.0, 1e-9);
    EXPECT_NEAR(std::hypot(fillet.center[Axis::X] + 20.0, fillet.center[Axis::Y] - 10.0), 13.0, 1e-9);
    EXPECT_NEAR(std::hypot(rest.from[Axis::X] + 20.0, rest.from[Axis::Y] - 10.0), 10.0, 1e-9);
    EXPECT_EQ(fillet.to, rest.from);
    EXPECT_EQ(fillet.direction, ArcDirection::clockwise);
}

TEST(CornerWords, Errors) {
    EXPECT_EQ(error_where("G0 X0 Y0\nG1 X10 F100 ,R20\nY10\n"), "bad-corner 2:13");     // does not fit
    EXPECT_EQ(error_where("G0 X0 Y0\nG0 X10 ,R2\nY10\n"), "bad-corner 2:8");            // not G1
    EXPECT_EQ(error_where("G0 X0 Y0\nG1 X10 F100 ,R2\nM8\nY10\n"), "bad-corner 2:13");  // no move next
    EXPECT_EQ(error_where("G0 X0 Y0\nG1 X10 F100 ,C2\nZ-5\n"), "bad-corner 2:13");      // next leaves the plane
    EXPECT_EQ(error_where("G0 X0 Y0\nG1 X10 F100 ,R2\nX20\n"), "bad-corner 2:13");      // straight on
    EXPECT_EQ(error_where("G1 X10 F100 ,Q2\n"), "syntax 1:13");
    EXPECT_EQ(error_where("G1 X10 F100 ,R0\nY1\n"), "bad-value 1:13");
}

MachineConfig mill_with_probe() {
    MachineConfig m = default_mill();
    m.probe_surfaces.push_back(ProbeSurface{Axis::Z, -12.5});
    m.macro_inputs.push_back(MacroInput{1003, 1.0});
    return m;
}

TEST(SkipG31, StopsAtTheSurfaceAndKeepsThePoint) {
    // G54 shifted by Z-2: the skip point reads -10.5 in the work system.
    EXPECT_EQ(texts("G10 L2 P1 Z-2\nG54 G0 Z5\nG31 Z-50 F200\n#100 = #5063\nG0 X#100\n", mill_with_probe()),
              (Texts{"G0 X0.0000 Y0.0000 Z3.0000", "G1 X0.0000 Y0.0000 Z-12.5000 F200.0000",
                     "G0 X-10.5000 Y0.0000 Z-12.5000"}));
}

TEST(SkipG31, NeverFiringIsAnError) {
    EXPECT_EQ(error_where("G0 Z5\nG31 Z-5 F100\n", mill_with_probe()), "skip-not-reached 2:1");
    EXPECT_EQ(error_where("G0 Z5\nG31 Z-50 F100\n"), "skip-not-reached 2:1");  // no surfaces at all
    EXPECT_EQ(error_where("G31 Z-50\n", mill_with_probe()), "no-feed 1:1");
    EXPECT_EQ(error_where("G31 F100\n", mill_with_probe()), "missing-word 1:1");
}

TEST(MacroInputs, ReadTheConfiguredValueOrZero) {
    EXPECT_EQ(texts("G0 X#1003 Y#1004\n", mill_with_probe()), (Texts{"G0 X1.0000 Y0.0000 Z0.0000"}));
}

TEST(MacroInputs, OutputsReadBackInputsAreReadOnly) {
    EXPECT_EQ(texts("#1100 = 7\nG0 X#1100\n"), (Texts{"G0 X7.0000 Y0.0000 Z0.0000"}));
    EXPECT_EQ(error_where("#1003 = 1\n", mill_with_probe()), "macro-alarm 1:1");
}

TEST(ProgramStop3006, StopsAsM0) {
    EXPECT_EQ(texts("G0 X1\n#3006 = 1 (CHECK PART)\nG0 X2\n"),
              (Texts{"G0 X1.0000 Y0.0000 Z0.0000", "M0", "G0 X2.0000 Y0.0000 Z0.0000"}));
}

TEST(PolarCancel, G15InASafeStartLineChangesNothing) {
    // `G0 G17 G21 G40 G49 G54 G80 G90 G94` then `G15 G52 X0 Y0`, as a Fanuc shop program's safe
    // start writes it: the same moves as without G15.
    EXPECT_EQ(texts("G15 G52 X0 Y0\nG0 X10 Y5\nG15\nG1 X20 F100\n"), texts("G52 X0 Y0\nG0 X10 Y5\nG1 X20 F100\n"));
}

TEST(PolarCancel, G16AndATwiceWrittenG15AreErrors) {
    EXPECT_EQ(error_where("G16 X10 Y30\n"), "unsupported-gcode 1:1");
    EXPECT_EQ(error_where("G15 G15\n"), "modal-conflict 1:5");
}

}  // namespace
}  // namespace nckit::test
