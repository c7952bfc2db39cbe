// A new cutter radius in offset mode (docs/cutter-compensation.md, "Changing the offset in
// offset mode"): the Fanuc dialect changes it over the block that brings it, LinuxCNC's refuses
// it. Worked numbers: tool 1 has radius 5, tool 2 radius 2, the contour X0Y0 → X50 → Y50 → X0
// with the tool on the left.
#include <gtest/gtest.h>

#include <cmath>

#include "interp_support.hpp"

namespace nckit::test {
namespace {

MachineConfig mill_with_offsets() {
    MachineConfig m = default_mill();
    auto add = [&](int number, double radius_mm) {
        ToolEntry t;
        t.number = number;
        t.radius_mm = radius_mm;
        m.tools.insert(t);
    };
    add(1, 5.0);
    add(2, 2.0);
    add(3, -2.0);  // a negative offset cuts on the other side
    add(4, 0.0);
    add(5, 8.0);
    return m;
}

constexpr const char* head = "G21 G17 G90\nG0 X-10 Y-10 Z0\nG1 F100 G41 D1 X0 Y0\nX50\n";

TEST(CutterCompOffsetChange, DWordAloneTakesEffectAtTheEndOfItsBlock) {
    // The corner X50 → Y50 is still cut with radius 5 (inside corner at (45, 5)); the Y50 block
    // then ends with radius 2: the crossing of x = 50 - 2 and y = 50 - 2.
    Texts t = texts(std::string(head) + "D2 Y50\nX0\nG40 X-10 Y-10\n", mill_with_offsets());
    ASSERT_EQ(t.size(), 7U);
    EXPECT_EQ(t[3], "G1 X45.0000 Y5.0000 Z0.0000 F100.0000");
    EXPECT_EQ(t[4], "G1 X48.0000 Y48.0000 Z0.0000 F100.0000") << "the block that brings D2 runs from r 5 to r 2";
    EXPECT_EQ(t[5], "G1 X0.0000 Y48.0000 Z0.0000 F100.0000");
}

TEST(CutterCompOffsetChange, DWordOnABlockOfItsOwnWaitsForTheNextPlanarMove) {
    Texts t = texts(std::string(head) + "D2\nZ-1\nY50\nX0\nG40 X-10 Y-10\n", mill_with_offsets());
    ASSERT_EQ(t.size(), 8U);
    EXPECT_EQ(t[3], "G1 X45.0000 Y5.0000 Z0.0000 F100.0000");
    EXPECT_EQ(t[4], "G1 X45.0000 Y5.0000 Z-1.0000 F100.0000") << "the Z move at the corner";
    EXPECT_EQ(t[5], "G1 X48.0000 Y48.0000 Z-1.0000 F100.0000");
}

TEST(CutterCompOffsetChange, G41AgainEndsTheMoveBeforeSquareToItself) {
    // G41 D2 on the Y50 block: X50 ends square to itself, 5 to its left at (50, 5), with no
    // corner; the Y50 block runs from there to its end with radius 2, (48, 48).
    Texts t = texts(std::string(head) + "G41 D2 Y50\nX0\nG40 X-10 Y-10\n", mill_with_offsets());
    ASSERT_EQ(t.size(), 7U);
    EXPECT_EQ(t[3], "G1 X50.0000 Y5.0000 Z0.0000 F100.0000");
    EXPECT_EQ(t[4], "G1 X48.0000 Y48.0000 Z0.0000 F100.0000");
    EXPECT_EQ(t[5], "G1 X0.0000 Y48.0000 Z0.0000 F100.0000");
}

TEST(CutterCompOffsetChange, G41AgainWithTheSameOffsetStillRestarts) {
    // A class program's second G41 D1 after Z moves: the rapid before it ends square to itself.
    Texts t = texts(std::string(head) + "G0 X60 Y0\nZ5\nG1 Z0\nG41 D1 X70\nY20\nG40 X80 Y30\n", mill_with_offsets());
    ASSERT_EQ(t.size(), 10U);
    EXPECT_EQ(t[3], "G1 X50.0000 Y5.0000 Z0.0000 F100.0000") << "the rapid along X follows: a tangent corner";
    EXPECT_EQ(t[4], "G0 X60.0000 Y5.0000 Z0.0000") << "the rapid ends square to itself, 5 to its left";
    EXPECT_EQ(t[5], "G0 X60.0000 Y5.0000 Z5.0000");
    EXPECT_EQ(t[6], "G1 X60.0000 Y5.0000 Z0.0000 F100.0000");
    EXPECT_EQ(t[7], "G1 X65.0000 Y5.0000 Z0.0000 F100.0000") << "X70 meets Y20 inside: x = 70 - 5";
}

TEST(CutterCompOffsetChange, TheSameDAgainChangesNothingEvenOnAnArc) {
    const std::string contour = "G3 X60 Y10 R10\nG1 Y30\nG40 X70 Y40\n";
    Texts plain = texts(std::string(head) + contour, mill_with_offsets());
    EXPECT_EQ(texts(std::string(head) + "D1 " + contour, mill_with_offsets()), plain);
}

TEST(CutterCompOffsetChange, BeforeTheFirstPlanarMoveTheStartUpTakesTheNewOffset) {
    Texts t = texts("G0 X-10 Y0 Z0\nG41 D1\nG41 D2\nG1 X0 F100\nX20\nG40 X30\n", mill_with_offsets());
    ASSERT_EQ(t.size(), 4U);
    EXPECT_EQ(t[1], "G1 X0.0000 Y2.0000 Z0.0000 F100.0000");
}

TEST(CutterCompOffsetChange, ALargerRadiusIsNoGougeAtTheOldCorner) {
    // D5 (radius 8) on the Y50 block: it starts 5 from X50's end and ends 8 from the contour;
    // its start is nearer X50 than 8, which the change allows.
    Texts t = texts(std::string(head) + "D5 Y50\nX0\nG40 X-10 Y-10\n", mill_with_offsets());
    ASSERT_EQ(t.size(), 7U);
    EXPECT_EQ(t[4], "G1 X42.0000 Y42.0000 Z0.0000 F100.0000");
}

TEST(CutterCompOffsetChange, ChangedBlockEndsTheNewRadiusFromItsEndProperty) {
    // For any pair of radii, the straight block with the new D ends on the normal of its end
    // point, the new radius to the left (the next block is collinear: a tangent corner).
    for (double r1 = 0.5; r1 < 12.0; r1 += 1.25) {
        for (double r2 = 0.25; r2 < 12.0; r2 += 1.5) {
            MachineConfig m = default_mill();
            ToolEntry a;
            a.number = 1;
            a.radius_mm = r1;
            ToolEntry b;
            b.number = 2;
            b.radius_mm = r2;
            m.tools.insert(a);
            m.tools.insert(b);
            std::vector<Line> lines =
                only<Line>(moves_of("G0 X-30 Y-30\nG41 D1 G1 X0 Y0 F100\nX50\nD2 X80 Y30\nX90 Y40\nG40 X120\n", m));
            ASSERT_GE(lines.size(), 5U);
            const Line& changed = lines[lines.size() - 3];
            const double n = std::sqrt(0.5);  // left of the 45° direction: (-n, n)
            EXPECT_NEAR(changed.to[Axis::X], 80.0 - r2 * n, 1e-9) << r1 << " → " << r2;
            EXPECT_NEAR(changed.to[Axis::Y], 30.0 + r2 * n, 1e-9) << r1 << " → " << r2;
        }
    }
}

// ---- malformed use ----------------------------------------------------------------------------

TEST(CutterCompOffsetChangeErrors, TheLinuxCncDialectRefusesG41WhileOn) {
    MachineConfig m = mill_with_offsets();
    m.dialect = Dialect::linuxcnc;
    Diagnostic d = error_of(std::string(head) + "G41 D2 Y50\n", m);
    EXPECT_EQ(where(d), "cutter-comp 5:1");
    EXPECT_EQ(d.message, "G41 with cutter compensation on: give G40 first");
}

TEST(CutterCompOffsetChangeErrors, ChangingSidesNeedsG40) {
    Diagnostic d = error_of(std::string(head) + "G42 D2 Y50\n", mill_with_offsets());
    EXPECT_EQ(where(d), "cutter-comp 5:1");
    EXPECT_EQ(d.message, "G42 changes the side of cutter compensation in offset mode: give G40 first");
    d = error_of(std::string(head) + "D3 Y50\n", mill_with_offsets());
    EXPECT_EQ(where(d), "cutter-comp 5:1") << "a negative offset is the other side";
    EXPECT_EQ(d.message, "D changes the side of cutter compensation in offset mode: give G40 first");
}

TEST(CutterCompOffsetChangeErrors, D0AndZeroRadiusAndUnknownOffset) {
    Diagnostic d = error_of(std::string(head) + "G41 D0 Y50\n", mill_with_offsets());
    EXPECT_EQ(where(d), "cutter-comp 5:5");
    EXPECT_EQ(d.message, "G41 with D0 in offset mode: D0 is no offset, give G40 to end the compensation");
    d = error_of(std::string(head) + "D4 Y50\n", mill_with_offsets());
    EXPECT_EQ(where(d), "cutter-comp 5:1");
    EXPECT_EQ(d.message, "D4 has radius 0: give G40 to end the compensation instead");
    EXPECT_EQ(error_where(std::string(head) + "D9 Y50\n", mill_with_offsets()), "unknown-tool 5:1");
}

TEST(CutterCompOffsetChangeErrors, TheChangedBlockMustBeALine) {
    Diagnostic d = error_of(std::string(head) + "D2\nG3 X40 Y10 R10\n", mill_with_offsets());
    EXPECT_EQ(where(d), "cutter-comp 6:1");
    EXPECT_EQ(d.message, "the cutter radius offset changes on an arc: give the new D on a straight line (G0/G1) move");
    d = error_of(std::string(head) + "G41 D2\nG3 X40 Y10 R10\n", mill_with_offsets());
    EXPECT_EQ(where(d), "cutter-comp 6:1");
}

}  // namespace
}  // namespace nckit::test
