// Cutter radius compensation through the interpreter: worked cases whose numbers are worked out
// by hand in docs/cutter-compensation.md, and every malformed use with its code, line and column.
#include <gtest/gtest.h>

#include "interp_support.hpp"

namespace nckit::test {
namespace {

// ---- worked cases -----------------------------------------------------------------------------

TEST(CutterComp, SquareCornerOutsideGetsAnArcAroundTheCorner) {
    // Tool radius 5 on the left of X0Y0 → X50 → Y30: the start-up move from (-20,-20) ends 5 mm
    // left of its own direction at (0,0): (-3.5355, 3.5355); the tool then rolls around (0,0) to
    // (0,5), the start of the X move's offset.
    Texts t = texts("G0 X-20 Y-20 Z0\nG41.1 D10 G1 X0 Y0 F300\nX50\nY30\nG40 X60 Y40\n");
    ASSERT_EQ(t.size(), 6U);
    EXPECT_EQ(t[1], "G1 X-3.5355 Y3.5355 Z0.0000 F300.0000");
    EXPECT_EQ(t[2], "G2 X0.0000 Y5.0000 Z0.0000 CX0.0000 CY0.0000 CZ0.0000 F300.0000");
    // Left of an X move that turns left into Y: an inside corner, cut at the offsets' crossing.
    EXPECT_EQ(t[3], "G1 X45.0000 Y5.0000 Z0.0000 F300.0000");
    EXPECT_EQ(t[4], "G1 X45.0000 Y30.0000 Z0.0000 F300.0000") << "held move ends perpendicular at G40";
    EXPECT_EQ(t[5], "G1 X60.0000 Y40.0000 Z0.0000 F300.0000") << "the exit move ends on the programmed point";
}

TEST(CutterComp, RightSideAndInsideArcShrinkTheRadius) {
    // G42 on a G2 arc: the tool is inside the arc, whose radius 10 becomes 10 - 3 = 7.
    Texts t = texts("G0 X0 Y-10 Z0\nG42.1 D6 G1 X0 Y0 F100\nG2 X20 Y0 R10\nG40 G1 X20 Y-10\n");
    ASSERT_EQ(t.size(), 4U);
    EXPECT_EQ(t[1], "G1 X3.0000 Y0.0000 Z0.0000 F100.0000");
    EXPECT_EQ(t[2], "G2 X17.0000 Y0.0000 Z0.0000 CX10.0000 CY0.0000 CZ0.0000 F100.0000");
}

TEST(CutterComp, InsideArcOfTheToolsRadiusPivotsAtItsCentre) {
    // Radius 5 inside a G3 of radius 5 centred on (40, 5): the tool stays on the centre (a move
    // that goes nowhere), then rolls around the arc's end (45, 5) onto the next line, as rs274.
    Texts t = texts("G0 X-20 Y0 Z0\nG41.1 D10 G1 X0 Y0 F100\nX40\nG3 X45 Y5 R5\nG1 X60\nG40 X70 Y-10\n");
    ASSERT_EQ(t.size(), 7U);
    EXPECT_EQ(t[2], "G1 X40.0000 Y5.0000 Z0.0000 F100.0000");
    EXPECT_EQ(t[3], "G1 X40.0000 Y5.0000 Z0.0000 F100.0000") << "the arc shrunk to its centre";
    EXPECT_EQ(t[4], "G2 X45.0000 Y10.0000 Z0.0000 CX45.0000 CY5.0000 CZ0.0000 F100.0000");
    EXPECT_EQ(t[5], "G1 X60.0000 Y10.0000 Z0.0000 F100.0000");
    // A helix of that radius keeps its Z: a plunge on the centre.
    std::vector<Line> lines =
        only<Line>(moves_of("G0 X-20 Y0 Z0\nG41.1 D10 G1 X0 Y0 F100\nX40\nG3 X45 Y5 Z-2 R5\n"
                            "G1 X60\nG40 X70 Y-10\n"));
    ASSERT_GE(lines.size(), 4U);
    EXPECT_DOUBLE_EQ(lines[3].from[Axis::Z], 0.0);
    EXPECT_DOUBLE_EQ(lines[3].to[Axis::Z], -2.0);
    EXPECT_DOUBLE_EQ(lines[3].to[Axis::X], 40.0);
}

TEST(CutterComp, InchDiameterIsReadInProgramUnits) {
    Texts t = texts("G20 G0 X-1 Y0 Z0\nG41.1 D0.5 G1 X0 Y0 F10\nX2\nG40 X3\n");
    ASSERT_EQ(t.size(), 4U);
    EXPECT_EQ(t[1], "G1 X0.0000 Y6.3500 Z0.0000 F254.0000") << "0.25 in = 6.35 mm to the left";
}

TEST(CutterComp, NonPlaneBlocksWaitBehindTheHeldMove) {
    // The Z move and the coolant come between two planar moves: they happen at the corner,
    // after the first move has been settled, in program order.
    std::vector<Move> moves = moves_of("G0 X-10 Y0 Z0\nG41.1 D4 G1 X0 Y0 F100\nX30\nM8\nG1 Z-1\nY30\nG40 X40\nM2\n");
    std::vector<std::string> kinds;
    for (const Move& m : moves) {
        if (const auto* line = std::get_if<Line>(&m.what)) {
            kinds.push_back("L" + std::to_string(m.where.line) + (line->from[Axis::Z] != line->to[Axis::Z] ? "z" : ""));
        } else if (std::holds_alternative<Arc>(m.what)) {
            kinds.push_back("A" + std::to_string(m.where.line));
        } else if (const auto* io = std::get_if<Io>(&m.what)) {
            kinds.push_back("M" + std::to_string(io->number));
        }
    }
    EXPECT_EQ(kinds, (std::vector<std::string>{"L1", "L2", "L3", "M8", "L5z", "L6", "L7", "M2"}));
    std::vector<Line> lines = only<Line>(moves);
    // Left of X+ turning left into Y+: inside corner at (28, 2); the Z move goes down there.
    EXPECT_DOUBLE_EQ(lines[2].to[Axis::X], 28.0);
    EXPECT_DOUBLE_EQ(lines[3].from[Axis::X], 28.0);
    EXPECT_DOUBLE_EQ(lines[3].to[Axis::Y], 2.0);
    EXPECT_DOUBLE_EQ(lines[3].to[Axis::Z], -1.0);
    EXPECT_DOUBLE_EQ(lines[4].from[Axis::Y], 2.0);
}

TEST(CutterComp, StartupTypeAEndsPerpendicularToTheNextBlock) {
    MachineConfig m = default_mill();
    m.cutter_comp_startup = CompStartup::type_a;
    Texts t = texts("G0 X-20 Y-20 Z0\nG41.1 D10 G1 X0 Y0 F300\nX50\nG40 X60\n", m);
    ASSERT_EQ(t.size(), 4U);
    EXPECT_EQ(t[1], "G1 X0.0000 Y5.0000 Z0.0000 F300.0000") << "no corner arc: straight to the next offset";
    EXPECT_EQ(t[2], "G1 X50.0000 Y5.0000 Z0.0000 F300.0000");
}

TEST(CutterComp, ZeroDiameterCompensatesNothing) {
    Texts t = texts("G41.1 D0 G1 X10 Y0 F100\nY10\nG40 X0\n");
    EXPECT_EQ(t, (Texts{"G1 X10.0000 Y0.0000 Z0.0000 F100.0000", "G1 X10.0000 Y10.0000 Z0.0000 F100.0000",
                        "G1 X0.0000 Y10.0000 Z0.0000 F100.0000"}));
}

TEST(CutterComp, NegativeDiameterSwitchesSides) {
    EXPECT_EQ(texts("G0 X-10 Y0 Z0\nG41.1 D-4 G1 X0 F100\nX10\nG40 X20\n"),
              texts("G0 X-10 Y0 Z0\nG42.1 D4 G1 X0 F100\nX10\nG40 X20\n"));
}

TEST(CutterComp, ProgramEndReleasesTheHeldMove) {
    Texts t = texts("G0 X-10 Y0 Z0\nG41.1 D4 G1 X0 F100\nX10\n");
    ASSERT_EQ(t.size(), 3U);
    EXPECT_EQ(t[2], "G1 X10.0000 Y2.0000 Z0.0000 F100.0000");
}

TEST(CutterComp, ModalCodeAndDReadBack) {
    // #4007 is the cutter compensation code of the block before.
    Texts t = texts("G41.1 D4\n#100 = #4007\nG40\n#101 = #4007\nG1 X#100 Y#101 F100\n");
    EXPECT_EQ(t.back(), "G1 X41.0000 Y40.0000 Z0.0000 F100.0000");
}

MachineConfig mill_with_tools() {
    MachineConfig m = default_mill();
    ToolEntry t3;
    t3.number = 3;
    t3.radius_mm = 4.0;
    t3.radius_wear_mm = -0.1;
    m.tools.insert(t3);
    return m;
}

TEST(CutterComp, DReadsRadiusPlusWearFromTheToolTable) {
    // Radius 4 - 0.1 wear = 3.9 to the left of X0 → X20.
    Texts t = texts("G0 X-10 Y0 Z0\nG41 D3 G1 X0 F100\nX20\nG40 X30\n", mill_with_tools());
    ASSERT_EQ(t.size(), 4U);
    EXPECT_EQ(t[1], "G1 X0.0000 Y3.9000 Z0.0000 F100.0000");
    // D is modal: a later G42 without D takes D3 again.
    t = texts("D3\nG0 X-10 Y0 Z0\nG42 G1 X0 F100\nX20\nG40 X30\n", mill_with_tools());
    ASSERT_EQ(t.size(), 4U);
    EXPECT_EQ(t[1], "G1 X0.0000 Y-3.9000 Z0.0000 F100.0000");
}

// ---- malformed use ----------------------------------------------------------------------------

TEST(CutterCompErrors, D0AndMissingTableEntry) {
    Diagnostic d = error_of("G41 D0 G1 X10 F100\n");
    EXPECT_EQ(where(d), "cutter-comp 1:5");
    EXPECT_EQ(d.message, "G41 with D0: D0 is no offset, give the tool's offset number");
    EXPECT_EQ(error_where("G42 G1 X10 F100\n"), "cutter-comp 1:1") << "no D at all";
    d = error_of("G41 D7 G1 X10 F100\n");
    EXPECT_EQ(where(d), "unknown-tool 1:5");
    EXPECT_EQ(d.message, "D7 needs a tool table (--tools FILE or tools = \"FILE\")");
    d = error_of("G41 D4 G1 X10 F100\n", mill_with_tools());
    EXPECT_EQ(where(d), "unknown-tool 1:5");
    EXPECT_EQ(d.message, "D4 has no entry in the tool table");
    EXPECT_EQ(error_where("G41 D1.5 G1 X10 F100\n"), "bad-value 1:5");
    EXPECT_EQ(error_where("G41.1 G1 X10 F100\n"), "missing-word 1:1");
}

TEST(CutterCompErrors, RadiusLargerThanAnInsideArc) {
    Diagnostic d = error_of("G0 X0 Y-20\nG42.1 D24 G1 X0 Y0 F100\nG2 X20 Y0 R10\nG1 Y-10\n");
    EXPECT_EQ(where(d), "cutter-gouge 3:1");
    EXPECT_EQ(d.message,
              "the tool radius 12.0000 mm is larger than the radius 10.0000 mm of this arc, "
              "which the tool cuts from inside");
}

TEST(CutterCompErrors, InsideCornerTooSmallForTheTool) {
    // A 4 mm step cut from inside with a radius 5 tool: the offset of the step runs backwards.
    Diagnostic d = error_of("G0 X-10 Y20\nG41.1 D10 G1 X0 Y20 F100\nY0\nX4\nY20\nG40 X10\n");
    EXPECT_EQ(d.code, "cutter-gouge");
    EXPECT_EQ(d.location.line, 4U) << "the block that cannot be cut: " << d.message;
}

TEST(CutterCompErrors, StartAndCancelRules) {
    EXPECT_EQ(error_where("G41.1 D4 G2 X10 Y0 R5 F100\n"), "cutter-comp 1:1") << "arc start-up";
    EXPECT_EQ(error_where("G0 X-10\nG41.1 D4 G1 X0 F100\nX10\nG40 G2 X20 R5\n"), "cutter-comp 4:1") << "arc exit";
    EXPECT_EQ(error_where("G0 X-1\nG41.1 D4 G1 X0 F100\nX10\n"), "cutter-comp 2:1")
        << "start-up shorter than the radius";
    EXPECT_EQ(error_where("G41.1 D4\nG42.1 D4\n"), "cutter-comp 2:1");
    EXPECT_EQ(error_where("G41.1 D4\nG18\n"), "cutter-comp 2:1");
    EXPECT_EQ(error_where("G41.1 D4\nG28 X0\n"), "cutter-comp 2:1");
    EXPECT_EQ(error_where("G41.1 D4\nG53 G0 X0\n"), "cutter-comp 2:1");
    EXPECT_EQ(error_where("G41.1 D4\nG81 X0 Y0 Z-1 R1 F100\n"), "cutter-comp 2:1");
    EXPECT_EQ(error_where("G41.1 D4\nT2 M6\n"), "cutter-comp 2:4");
    EXPECT_EQ(error_where("G41.1 D4\nG92 X0\n"), "cutter-comp 2:1");
    EXPECT_EQ(error_where("G41.1 D4\nG55\n"), "cutter-comp 2:1");
    EXPECT_EQ(error_where("G0 X-10\nG41.1 D4 G1 X0 F100\nG33 X10 K1\n"), "cutter-comp 3:1");
}

TEST(CutterCompErrors, AnErrorKeepsTheHeldMovesBack) {
    // The move before the failing corner never leaves: nothing of the contour is cut.
    RunResult r = run_program("G0 X0 Y-20\nG42.1 D24 G1 X0 Y0 F100\nG2 X20 Y0 R10\n");
    ASSERT_TRUE(r.error.has_value());
    ASSERT_EQ(r.moves.size(), 1U) << "only the rapid before G42";
    EXPECT_TRUE(std::get<Line>(r.moves[0].what).rapid);
}

}  // namespace
}  // namespace nckit::test
