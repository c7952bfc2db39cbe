// LinuxCNC's lathe cycles G70/G71/G72 through the Interpreter, seen from the moves: the levels of
// the roughing passes, the retract, the allowance left on the shape, the finishing pass on it,
// and the errors. (tests/real_linuxcnc compares the moves with rs274 on LinuxCNC's own programs.)
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "interp_support.hpp"

namespace nckit::test {
namespace {

//! A step shape: X10 from Z0 to Z-10, up to X20, on to Z-20; the block's start is X25 Z2.
constexpr std::string_view step_shape =
    "G21 G18 G90 F100\n"
    "o100 sub\n"
    "  G1 X10 Z0\n"
    "  Z-10\n"
    "  X20\n"
    "  Z-20\n"
    "o100 endsub\n"
    "G0 X30 Z5\n";

//! X of the finished step shape at Z.
double shape_x(double z) {
    return z > -10 ? 10.0 : 20.0;
}

TEST(NgcG7x, FacingLevelsStepByIAndRetractByR) {
    // LinuxCNC's facing test: levels of Z every I (3), each a feed along X to the shape, then up
    // and back by R (0.1) in both axes.
    const auto lines =
        only<Line>(moves_of("G21 G18 F400\n"
                            "o100 sub\n"
                            "G1 X50 Z-40\n"
                            "X100 Z-39.999\n"
                            "o100 endsub\n"
                            "G72 Q100 X50 Z0 I3 R0.1\n"
                            "M2\n",
                            linuxcnc_mill()));
    std::vector<double> levels;
    for (std::size_t k = 0; k + 1 < lines.size(); ++k) {
        // A cut: a feed to X100 and the retract after it (the last feed along the shape has none).
        if (lines[k].rapid || lines[k].to[Axis::X] != 100.0 || !lines[k + 1].rapid) continue;
        levels.push_back(lines[k].to[Axis::Z]);
        EXPECT_NEAR(lines[k + 1].to[Axis::X], 99.9, 1e-9);
        EXPECT_NEAR(lines[k + 1].to[Axis::Z], lines[k].to[Axis::Z] + 0.1, 1e-9);
    }
    ASSERT_EQ(levels.size(), 14u);  // Z 0, -3, ..., -39
    for (std::size_t k = 0; k < levels.size(); ++k) EXPECT_NEAR(levels[k], -3.0 * static_cast<double>(k), 1e-9);
}

TEST(NgcG7x, RoughingLeavesTheAllowanceEverywhere) {
    // Property: with D 0.5 no move of G71 ends inside the shape grown by the allowance.
    std::string program(step_shape);
    program += "G71 Q100 X25 Z2 D0.5 I1.5 R0.3\nM2\n";
    const auto moves = moves_of(program, linuxcnc_mill());
    ASSERT_GT(moves.size(), 10u);
    int cuts = 0;
    for (const Line& l : only<Line>(moves)) {
        const double z = l.to[Axis::Z];
        if (z > 0.5 || z < -20) continue;
        EXPECT_GE(l.to[Axis::X], shape_x(z) + 0.5 - 1e-6) << "at Z" << z;
        if (!l.rapid) ++cuts;
    }
    EXPECT_GT(cuts, 5);
}

TEST(NgcG7x, FinishingPassesEndOnTheShape) {
    // G70 P2 D1 E0: pass k (P down to 1) lies E + (k - 1)(D - E)/P off the shape: 0.5, then on it.
    std::string program(step_shape);
    program += "G70 Q100 X25 Z2 D1 E0 P2\nM2\n";
    const auto lines = only<Line>(moves_of(program, linuxcnc_mill()));
    std::vector<double> at_x20;
    for (const Line& l : lines) {
        if (!l.rapid && std::abs(l.to[Axis::Z] - -20.0) < 1e-9) at_x20.push_back(l.to[Axis::X]);
    }
    ASSERT_EQ(at_x20.size(), 2u);
    EXPECT_NEAR(at_x20[0], 20.5, 1e-9);
    EXPECT_NEAR(at_x20[1], 20.0, 1e-9);
}

TEST(NgcG7x, ShapePositionFollowsTheShapeAsItIsRead) {
    // #<_x> and #<_z> are the shape's own position while it is read: three steps of +5 X, -3 Z.
    const auto lines =
        only<Line>(moves_of("G21 G18 F400\n"
                            "o100 sub\n"
                            "G0 X0 Z-10\n"
                            "o101 repeat [3]\n"
                            "G1 X[#<_x>+5] Z[#<_z>-3]\n"
                            "o101 endrepeat\n"
                            "o100 endsub\n"
                            "G70 Q100 X20 Z0\n"
                            "M2\n",
                            linuxcnc_mill()));
    ASSERT_FALSE(lines.empty());
    EXPECT_NEAR(lines.back().to[Axis::X], 15.0, 1e-9);
    EXPECT_NEAR(lines.back().to[Axis::Z], -19.0, 1e-9);
}

TEST(NgcG7x, ErrorsAtTheCycle) {
    std::string shape(step_shape);
    EXPECT_EQ(where(error_of(shape + "G71 X25 Z2\nM2\n", linuxcnc_mill())), "ngc-error 9:1");
    EXPECT_EQ(where(error_of(shape + "G17\nG71 Q100 X25 Z2\nM2\n", linuxcnc_mill())), "ngc-error 10:1");
    EXPECT_EQ(where(error_of(shape + "G71 Q100 X25 Z2 I0\nM2\n", linuxcnc_mill())), "ngc-error 9:1");
    EXPECT_EQ(where(error_of(shape + "G71 Q7 X25 Z2\nM2\n", linuxcnc_mill())).substr(0, 9), "ngc-error");
    // A shape that runs back up in Z is refused: LinuxCNC's "Not monotonic".
    const Diagnostic back = error_of(
        "G21 G18 F100\no1 sub\nG1 X10 Z0\nZ-10\nX12 Z-5\nX20\no1 endsub\n"
        "G71 Q1 X25 Z2\nM2\n",
        linuxcnc_mill());
    EXPECT_EQ(where(back), "ngc-error 8:1");
    EXPECT_NE(back.message.find("monotonic"), std::string::npos) << back.message;
}

TEST(NgcG7x, FanucDialectKeepsItsOwnG71) {
    // Fanuc's G71 (P/Q sequence numbers, U/R words) is untouched by the LinuxCNC cycles.
    const Diagnostic fanuc = error_of("G21 G18 F100\nG71 Q100 X25 Z2\nM2\n", default_mill());
    EXPECT_EQ(fanuc.message.find("G7x"), std::string::npos) << fanuc.message;
}

}  // namespace
}  // namespace nckit::test
