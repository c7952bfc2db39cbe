// G76 multiple threading (two-block and one-block) and G74/G75 peck grooving, on numbers worked
// by hand.
#include <cmath>
#include <numbers>
#include <string>
#include <tuple>

#include <gtest/gtest.h>

#include "interp_support.hpp"
#include "lathe_test_machine.hpp"

namespace nckit::test {
namespace {

std::vector<SyncMove> syncs_of(const std::vector<Move>& moves) {
    std::vector<SyncMove> out;
    for (const Move& m : moves) {
        if (const auto* s = std::get_if<SyncMove>(&m.what)) out.push_back(*s);
    }
    return out;
}

TEST(LatheThreading, G76TwoBlockInfeedHasConstantArea) {
    // The numbers of Fanuc's G76 example (height 3.68, first depth 1.8, lead 6, allowance 0.2,
    // smallest step 0.1, one finishing pass, chamfer 1.0 lead, 60 degrees) from X70 Z5 to a root of
    // X60.64 at Z-25. Depths 1.8·√n while below 3.68 - 0.2 = 3.48: 1.8, 2.5456, 3.1177, then
    // 1.8·√4 = 3.6 is held at 3.48; the finishing pass cuts at 3.68. Each depth puts the tip at
    // radius 30.32 + 3.68 - depth and starts depth·tan 30° nearer the thread's end.
    auto moves = moves_of("G97 S300 M3\nG0 X70. Z5.\nG76 P011060 Q100 R0.2\nG76 X60.64 Z-25. P3680 Q1800 F6.\nM30\n",
                          system_a_lathe());
    const auto syncs = syncs_of(moves);
    const double depths[] = {1.8, 1.8 * std::sqrt(2.0), 1.8 * std::sqrt(3.0), 3.48, 3.68};
    ASSERT_EQ(syncs.size(), 10u);  // each pass: the thread, then the 45-degree pull-out
    for (int n = 0; n < 5; ++n) {
        const SyncMove& cut = syncs[2 * n];
        const SyncMove& pull = syncs[2 * n + 1];
        const double x = 30.32 + 3.68 - depths[n];
        EXPECT_NEAR(cut.from[Axis::X], x, 1e-9) << n;
        EXPECT_NEAR(cut.from[Axis::Z], 5 - depths[n] * std::tan(std::numbers::pi / 6), 1e-9) << n;
        EXPECT_NEAR(cut.to[Axis::Z], -25 + 6, 1e-9);  // the chamfer: one lead before the end
        EXPECT_NEAR(pull.to[Axis::X], x + 6, 1e-9);
        EXPECT_NEAR(pull.to[Axis::Z], -25, 1e-9);
        EXPECT_DOUBLE_EQ(cut.feed.mm_per_rev, 6.0);
        EXPECT_DOUBLE_EQ(cut.feed.mm_per_min, 1800.0);
    }
    // The cut area grows by the same amount every rough pass: depth² goes 1, 2, 3 times 1.8².
    EXPECT_NEAR(depths[1] * depths[1] - depths[0] * depths[0], depths[2] * depths[2] - depths[1] * depths[1], 1e-9);
}

TEST(LatheThreading, G76OneBlockForm) {
    // K1 height, D0.4 first depth: 0.4·√n up to 1: 0.4 0.5657 0.6928 0.8 0.8944 0.9798 1.0.
    auto syncs = syncs_of(moves_of("G97 S500 M3\nG0 X24. Z5.\nG76 X18. Z-20. K1. D0.4 F1.5\nM30\n", system_a_lathe()));
    ASSERT_EQ(syncs.size(), 7u);
    EXPECT_NEAR(syncs[0].from[Axis::X], 9 + 1 - 0.4, 1e-9);
    EXPECT_NEAR(syncs[3].from[Axis::X], 9 + 1 - 0.8, 1e-9);
    EXPECT_NEAR(syncs[6].from[Axis::X], 9.0, 1e-9);
    EXPECT_NEAR(syncs[6].to[Axis::Z], -20.0, 1e-9);
}

TEST(LatheGrooving, G74PecksAlongZ) {
    // From X0 Z2, 5 mm pecks backing off 1 mm, to Z-20: -3 -2 -8 -7 -13 -12 -18 -17 -20, back to Z2.
    auto moves = moves_of("G0 X0 Z2.\nG74 R1.\nG74 Z-20. Q5000 F0.1\nM30\n", system_a_lathe());
    std::vector<double> z;
    for (const Move& m : moves) {
        if (const auto* l = std::get_if<Line>(&m.what); l != nullptr && m.where.line == 3) z.push_back(l->to[Axis::Z]);
    }
    EXPECT_EQ(z, (std::vector<double>{-3, -2, -8, -7, -13, -12, -18, -17, -20, 2}));
}

TEST(LatheGrooving, G75PecksAlongXAndStepsInZ) {
    // From X42 Z-10 (radius 21) to X30 (radius 15) Z-14: 2 mm pecks, 0.5 back-off, columns at
    // Z-10, -13 and -14 (the last step shortened to the end point).
    auto moves = moves_of("G0 X42. Z-10.\nG75 R0.5\nG75 X30. Z-14. P2000 Q3000 F0.05\n", system_a_lathe());
    std::vector<std::pair<double, double>> ends;
    for (const Move& m : moves) {
        if (const auto* l = std::get_if<Line>(&m.what); l != nullptr && m.where.line == 3 && !l->rapid) {
            ends.emplace_back(l->to[Axis::X], l->to[Axis::Z]);
        }
    }
    const std::vector<std::pair<double, double>> want{{19, -10}, {17, -10}, {15, -10}, {19, -13}, {17, -13},
                                                      {15, -13}, {19, -14}, {17, -14}, {15, -14}};
    EXPECT_EQ(ends, want);
    EXPECT_DOUBLE_EQ(std::get<Line>(moves.back().what).to[Axis::Z], -10.0);
}

TEST(LatheGrooving, G75ReliefAtTheBottom) {
    // The numbers of G75PecksAlongXAndStepsInZ with R1. (the 0i's relief at the bottom) in the
    // second block: the steps go to -Z, so at the bottom of each column but the first (radius 15)
    // the tool moves 1 mm back to +Z, into the column cut before, at rapid, then returns to
    // radius 21 there. The first column has the groove's wall behind it: no relief.
    auto moves = moves_of("G0 X42. Z-10.\nG75 R0.5\nG75 X30. Z-14. P2000 Q3000 R1. F0.05\n", system_a_lathe());
    std::vector<std::tuple<double, double, bool>> ends;
    for (const Move& m : moves) {
        if (const auto* l = std::get_if<Line>(&m.what); l != nullptr && m.where.line == 3) {
            ends.emplace_back(l->to[Axis::X], l->to[Axis::Z], l->rapid);
        }
    }
    const std::vector<std::tuple<double, double, bool>> want{
        {19, -10, false},  {19.5, -10, true}, {17, -10, false},  {17.5, -10, true}, {15, -10, false},  {21, -10, true},
        {21, -13, true},   {19, -13, false},  {19.5, -13, true}, {17, -13, false},  {17.5, -13, true}, {15, -13, false},
        {15, -12, true},   {21, -12, true},   {21, -14, true},   {19, -14, false},  {19.5, -14, true}, {17, -14, false},
        {17.5, -14, true}, {15, -14, false},  {15, -13, true},   {21, -13, true},   {21, -10, true}};
    EXPECT_EQ(ends, want);
}

TEST(LatheGrooving, G74ReliefGoesAgainstTheXSteps) {
    // G74 steps across in X: from X20 (radius 10) to X10 (radius 5) in 3 mm steps the columns are
    // at radius 10, 7, 5, stepping to -X, so the relief of 0.5 at the bottoms (Z-4) of the second
    // and third columns goes to +X; the first has none.
    auto moves = moves_of("G0 X20. Z1.\nG74 X10. Z-4. P3000 Q5000 R0.5 F0.1\nM30\n", system_a_lathe());
    std::vector<std::pair<double, double>> reliefs;  // rapids along X at the bottom
    const Line* previous = nullptr;
    for (const Move& m : moves) {
        const auto* l = std::get_if<Line>(&m.what);
        if (l == nullptr || m.where.line != 2) continue;
        if (previous != nullptr && !previous->rapid && l->rapid && l->to[Axis::Z] == previous->to[Axis::Z]) {
            reliefs.emplace_back(l->to[Axis::X], l->to[Axis::Z]);
        }
        previous = l;
    }
    const std::vector<std::pair<double, double>> want{{7.5, -4}, {5.5, -4}};
    EXPECT_EQ(reliefs, want);
}

TEST(LatheGrooving, ReliefWithoutAStepIsIgnoredWithAWarning) {
    // `G75 X30. P2000 R1.`: one column, no step across, so nothing to relieve against; the
    // cycle runs as without R and says so.
    const MachineConfig lathe = system_a_lathe();
    std::vector<std::string> warnings;
    InterpreterOptions options;
    options.on_warning = [&](const Diagnostic& d) { warnings.push_back(where(d)); };
    const auto with_r = moves_of("G0 X42. Z-10.\nG75 X30. P2000 R1. F0.05\nM30\n", lathe, options);
    const auto without = moves_of("G0 X42. Z-10.\nG75 X30. P2000 F0.05\nM30\n", lathe);
    EXPECT_EQ(with_r.size(), without.size());
    EXPECT_EQ(warnings, (std::vector<std::string>{"ignored-word 2:16"}));
}

TEST(LatheGrooving, OneBlockG75PecksByI) {
    // `G75 X0 I0.5` from X4 (radius 2): pecks of 0.5 on the radius to the centre, no back-off.
    auto moves = moves_of("G0 X4. Z-3.\nG1 F0.1\nG75 X0 I0.5\nM30\n", system_a_lathe());
    std::vector<double> x;
    for (const Move& m : moves) {
        if (const auto* l = std::get_if<Line>(&m.what); l != nullptr && m.where.line == 3) x.push_back(l->to[Axis::X]);
    }
    EXPECT_EQ(x, (std::vector<double>{1.5, 1.0, 0.5, 0.0, 2.0}));
}

TEST(LatheThreadGrooveErrors, MalformedCycles) {
    const MachineConfig lathe = system_a_lathe();
    EXPECT_EQ(error_where("G0 X24. Z5.\nG76 X18. Z-20. F1.5\n", lathe), "missing-word 2:1");
    EXPECT_EQ(error_where("G76 P1234567\n", lathe), "bad-value 1:5");
    EXPECT_EQ(error_where("G0 X24. Z5.\nG76 X18. Z-20. K0 D0.4 F1.5\n", lathe), "bad-value 2:16");
    EXPECT_EQ(error_where("G74 R-1.\n", lathe), "bad-value 1:5");
    EXPECT_EQ(error_where("G0 X42. Z-10.\nG75 X0 I0.005 J1. F0.1\n", lathe), "unused-word 2:15");
    EXPECT_EQ(error_where("G0 X42. Z-10.\nG75 X0 I0.005 P2000 F0.1\n", lathe), "bad-combination 2:15");
    EXPECT_EQ(error_where("G0 X42. Z-10.\nG75 X30. Z-14. P2000 F0.05\n", lathe), "missing-word 2:1");
    // R (the relief at the bottom): negative (it is unsigned), in the one-block I K form.
    EXPECT_EQ(error_where("G0 X42. Z-10.\nG75 X30. Z-14. P2000 Q3000 R-1. F0.05\n", lathe), "bad-value 2:28");
    EXPECT_EQ(error_where("G0 X4. Z-3.\nG1 F0.1\nG75 X0 I0.5 R1.\n", lathe), "bad-combination 3:13");
}

}  // namespace
}  // namespace nckit::test
