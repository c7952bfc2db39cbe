// A lathe's tool offsets as a 0i-T: T0101, T0100, G10 P, #2001-#2999; G50 S under G96.
#include <cmath>

#include <gtest/gtest.h>

#include "interp_support.hpp"
#include "lathe_test_machine.hpp"

namespace nckit::test {
namespace {

MachineConfig lathe_with_offset() {
    MachineConfig m = system_a_lathe();
    ToolEntry e;
    e.number = 1;
    e.x_offset_mm = 1.0;  // radius
    e.x_wear_mm = 0.1;
    e.length_mm = 5.0;
    e.length_wear_mm = -0.2;
    e.radius_mm = 0.4;
    e.orientation = 3;
    m.tools.insert(e);
    return m;
}

const Line& last_line(const std::vector<Move>& moves) {
    for (auto it = moves.rbegin(); it != moves.rend(); ++it) {
        if (const auto* l = std::get_if<Line>(&it->what)) return *l;
    }
    static Line none;
    ADD_FAILURE() << "no line";
    return none;
}

TEST(LatheOffsets, T0101AppliesGeometryAndWearT0100Cancels) {
    const MachineConfig m = lathe_with_offset();
    // Offset 1: X 1.0 + 0.1 (radius), Z 5.0 - 0.2. X20 is radius 10: the slide goes to 11.1.
    auto with = moves_of("T0101\nG0 X20. Z0\nM30\n", m);
    EXPECT_DOUBLE_EQ(last_line(with).to[Axis::X], 11.1);
    EXPECT_DOUBLE_EQ(last_line(with).to[Axis::Z], 4.8);
    const auto& tool = std::get<Io>(with.at(0).what);
    EXPECT_EQ(tool.kind, IoKind::tool_select);
    EXPECT_EQ(tool.number, 101);  // the T word as written: tool 1, offset 1
    auto cancelled = moves_of("T0101\nG0 X20. Z0\nT0100\nG0 X20. Z0\nM30\n", m);
    EXPECT_DOUBLE_EQ(last_line(cancelled).to[Axis::X], 10.0);
    EXPECT_DOUBLE_EQ(last_line(cancelled).to[Axis::Z], 0.0);
    // T101 reads as T0101; an offset the table has not is zero, as a cleared offset memory.
    EXPECT_DOUBLE_EQ(last_line(moves_of("T101\nG0 X20. Z0\nM30\n", m)).to[Axis::X], 11.1);
    EXPECT_DOUBLE_EQ(last_line(moves_of("T0202\nG0 X20. Z0\nM30\n", m)).to[Axis::X], 10.0);
}

TEST(LatheOffsets, MacroVariablesReadAsA0iT) {
    const MachineConfig m = lathe_with_offset();
    // X values read as diameters on a diameter lathe: wear 0.1 radius is #2001 = 0.2.
    auto read = [&](const char* variable) {
        auto moves = moves_of(std::string("#100 = ") + variable + "\nG0 Z[#100]\nM30\n", m);
        return last_line(moves).to[Axis::Z];
    };
    EXPECT_DOUBLE_EQ(read("#2001"), 0.2);
    EXPECT_DOUBLE_EQ(read("#2101"), -0.2);
    EXPECT_DOUBLE_EQ(read("#2301"), 3.0);
    EXPECT_DOUBLE_EQ(read("#2701"), 2.0);
    EXPECT_DOUBLE_EQ(read("#2801"), 5.0);
    EXPECT_DOUBLE_EQ(read("#2901"), 0.4);
    EXPECT_DOUBLE_EQ(read("#2005"), 0.0);
    // Writing: #2801 = 7 moves the next T0101's Z.
    auto moves = moves_of("#2801 = 7.\n#2101 = 0\nT0101\nG0 X20. Z0\nM30\n", m);
    EXPECT_DOUBLE_EQ(last_line(moves).to[Axis::Z], 7.0);
    EXPECT_EQ(error_of("#2401 = 1\n", m).alarm, 115);
}

TEST(LatheOffsets, G10PWritesWearAndGeometry) {
    const MachineConfig m = lathe_with_offset();
    // G10 P1 U0.2: wear X +0.2 on the diameter (0.1 radius) -> 0.2 radius; P10001 X4.: geometry 2.
    auto moves = moves_of(
        "G10 P1 U0.2\nG10 P10001 X4. W1. R0.8 Q2\n#100 = #2901\n#101 = #2301\nT0101\nG0 X20. Z0\n"
        "G0 Z[#100 + #101]\nM30\n",
        m);
    std::vector<Line> lines;
    for (const Move& move : moves) {
        if (const auto* l = std::get_if<Line>(&move.what)) lines.push_back(*l);
    }
    ASSERT_EQ(lines.size(), 2u);
    const Line& at = lines[0];
    EXPECT_DOUBLE_EQ(at.to[Axis::X], 10.0 + 2.0 + 0.2);
    EXPECT_DOUBLE_EQ(at.to[Axis::Z], 6.0 - 0.2);
    EXPECT_DOUBLE_EQ(last_line(moves).to[Axis::Z], 0.8 + 2.0 + 5.8);
}

TEST(LatheOffsets, MalformedOffsetCodes) {
    const MachineConfig m = lathe_with_offset();
    EXPECT_EQ(error_where("G10 P200 X1.\n", m), "bad-g10 1:5");
    EXPECT_EQ(error_where("G10 X1.\n", m), "bad-g10 1:1");
    EXPECT_EQ(error_where("G10 P1 K1.\n", m), "unused-word 1:8");
    EXPECT_EQ(error_where("G10 P1 Q12\n", m), "bad-value 1:8");
    EXPECT_EQ(error_where("#2301 = 11\n", m), "macro-alarm 1:1");
}

TEST(LatheOffsets, G50ClampsTheSpindleUnderG96) {
    auto moves = moves_of("G50 S1500\nG96 S200 M3\nG0 X10. Z0\nG1 Z-10. F0.1\nM30\n", system_a_lathe());
    const Line& cut = last_line(moves);
    // 200 m/min at 10 mm diameter would be 6366 rpm: clamped to 1500, so 0.1 mm/rev = 150 mm/min.
    EXPECT_DOUBLE_EQ(cut.feed.mm_per_min, 150.0);
}

}  // namespace
}  // namespace nckit::test

namespace nckit::test {
namespace {

MachineConfig lathe_with_noses() {
    MachineConfig m = system_a_lathe();
    for (int tip : {0, 3}) {
        ToolEntry e;
        e.number = tip == 0 ? 1 : 2;
        e.radius_mm = 0.4;
        e.orientation = tip;
        m.tools.insert(e);
    }
    return m;
}

TEST(LatheNoseRadius, G42OffsetsTaperAndArcByTheNoseRadius) {
    // Tip orientation 0: the nose centre is programmed, so the path is the contour moved out by
    // r = 0.4. Along Z at radius 10 the centre runs at 10.4; on the 45-degree taper from (10,-10)
    // to (20,-20) (x + z = 0) each end lies 0.4 from the line; the concave G2 of radius 10 about
    // (30,-20) is cut at radius 9.6.
    auto moves = moves_of(
        "T0101\nG0 X60. Z5.\nG42 G1 X20. Z2. F0.2\nG1 Z-10.\nX40. Z-20.\nG2 X60. Z-30. R10.\n"
        "G40 G0 X80.\n",
        lathe_with_noses());
    std::vector<Line> feeds;
    std::vector<Arc> arcs;
    for (const Move& m : moves) {
        if (const auto* l = std::get_if<Line>(&m.what); l != nullptr && !l->rapid) feeds.push_back(*l);
        if (const auto* a = std::get_if<Arc>(&m.what)) arcs.push_back(*a);
    }
    ASSERT_EQ(feeds.size(), 3u);
    EXPECT_NEAR(feeds[1].from[Axis::X], 10.4, 1e-9);
    EXPECT_NEAR(feeds[1].to[Axis::X], 10.4, 1e-9);
    for (const AxisVector& p : {feeds[2].from, feeds[2].to}) {
        EXPECT_NEAR((p[Axis::X] + p[Axis::Z]) / std::sqrt(2.0), 0.4, 1e-9);
    }
    ASSERT_EQ(arcs.size(), 2u);  // the corner round the taper's end, then the compensated G2
    EXPECT_NEAR(arcs[1].center[Axis::X], 30.0, 1e-9);
    EXPECT_NEAR(arcs[1].center[Axis::Z], -20.0, 1e-9);
    EXPECT_NEAR(std::hypot(arcs[1].to[Axis::X] - 30.0, arcs[1].to[Axis::Z] + 20.0), 9.6, 1e-9);
}

}  // namespace
}  // namespace nckit::test
