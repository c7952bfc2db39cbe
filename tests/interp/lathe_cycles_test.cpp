// G70 G71 G72 G73 on the examples of Fanuc's lathe operator's manual, computed by hand.
#include <gtest/gtest.h>

#include "interp_support.hpp"
#include "lathe_test_machine.hpp"

namespace nckit::test {
namespace {

using Point = LathePoint;

std::vector<Point> path_of(const std::vector<Move>& moves) {
    return lathe_path_of(moves);
}

void expect_path(const std::vector<Point>& got, std::size_t from, const std::vector<Point>& want) {
    ASSERT_GE(got.size(), from + want.size());
    for (std::size_t i = 0; i < want.size(); ++i) {
        EXPECT_NEAR(got[from + i].x_radius, want[i].x_radius, 1e-9) << "move " << from + i;
        EXPECT_NEAR(got[from + i].z, want[i].z, 1e-9) << "move " << from + i;
        EXPECT_EQ(got[from + i].rapid, want[i].rapid) << "move " << from + i;
    }
}

// Fanuc's G71 example (0i-TF operator's manual, stock removal in turning), started at X176 Z132.
constexpr const char* g71_example =
    "N011 G00 X176.0 Z132.0\n"
    "N012 G71 U7.0 R1.0\n"
    "N013 G71 P014 Q020 U4.0 W2.0 F0.3 S550\n"
    "N014 G00 X40.0 S700\n"
    "N015 G01 W-40.0 F0.15\n"
    "N016 X60.0 W-30.0\n"
    "N017 W-20.0\n"
    "N018 X100.0 W-10.0\n"
    "N019 W-20.0\n"
    "N020 X140.0 W-20.0\n"
    "N021 G70 P014 Q020\n"
    "M30\n";

TEST(LatheCycles, G71RoughsTheManualsExampleLevelByLevel) {
    // A = (r88, Z132). The shape moved by the allowance (U4 = 2 on the radius, W2) runs
    // (22,134) (22,94) (32,64) (32,44) (52,34) (52,14) (72,-6). Levels every 7 mm from r88 while
    // above r22: 81 74 67 60 53 46 39 32 25. Where each meets the moved shape:
    //   81, 74: above it all -> to its end, Z-6;   67: on (52,14)-(72,-6), Z = 14 - 20*(15/20) = -1;
    //   60: Z = 14 - 20*(8/20) = 6;   53: Z = 14 - 20*(1/20) = 13;
    //   46: on (32,44)-(52,34), Z = 44 - 10*(14/20) = 37;   39: Z = 44 - 10*(7/20) = 40.5;
    //   32: the end of (22,94)-(32,64), Z64;   25: Z = 94 - 30*(3/10) = 85.
    // Each pass: rapid in (the P block is G00), feed along Z, escape R1 at 45 degrees, rapid back.
    auto path = path_of(moves_of(g71_example, system_a_lathe(300)));
    const double levels[] = {81, 74, 67, 60, 53, 46, 39, 32, 25};
    const double ends[] = {-6, -6, -1, 6, 13, 37, 40.5, 64, 85};
    std::size_t i = 1;  // after the positioning rapid
    for (int k = 0; k < 9; ++k, i += 4) {
        expect_path(path, i,
                    {{levels[k], 132, true},
                     {levels[k], ends[k], false},
                     {levels[k] + 1, ends[k] + 1, false},
                     {levels[k] + 1, 132, true}});
    }
    // The last pass follows the moved shape, then back to A at rapid.
    expect_path(path, i,
                {{22, 134, true},
                 {22, 94, false},
                 {32, 64, false},
                 {32, 44, false},
                 {52, 34, false},
                 {52, 14, false},
                 {72, -6, false},
                 {88, -6, true},
                 {88, 132, true}});
    // G70: the shape as programmed from A, then back to A.
    expect_path(path, i + 9,
                {{20, 132, true},
                 {20, 92, false},
                 {30, 62, false},
                 {30, 42, false},
                 {50, 32, false},
                 {50, 12, false},
                 {70, -8, false},
                 {88, 132, true}});
    EXPECT_EQ(path.size(), i + 17);
}

TEST(LatheCycles, G71CutsAtTheCycleFeedAndG70AtTheShapes) {
    auto moves = moves_of(g71_example, system_a_lathe(300));
    std::vector<double> feeds;
    for (const Move& m : moves) {
        if (const auto* l = std::get_if<Line>(&m.what); l != nullptr && !l->rapid) feeds.push_back(l->feed.mm_per_rev);
    }
    ASSERT_EQ(feeds.size(), 9u * 2 + 6 + 6);
    for (std::size_t k = 0; k < 24; ++k) EXPECT_DOUBLE_EQ(feeds[k], 0.3) << k;
    for (std::size_t k = 24; k < feeds.size(); ++k) EXPECT_DOUBLE_EQ(feeds[k], 0.15) << k;
}

TEST(LatheCycles, G72FacesInLevelsOfZ) {
    // Facing: A = (r80, Z2). Shape from Z-10 (G0 Z-10) outward... here a simple one: the P block
    // goes to Z-6, the shape runs X120 -> X40 at Z-6 then to Z0 at X20 (r10): monotonic.
    // Depth W2, escape R0.5, allowance U0 W0.5 (the shape moved 0.5 towards +Z).
    const char* program =
        "G0 X160. Z2.\n"
        "G72 W2. R0.5\n"
        "G72 P10 Q20 U0 W0.5 F0.2\n"
        "N10 G0 Z-6.\n"
        "G1 X40.\n"
        "N20 X20. Z0\n"
        "M30\n";
    // Moved shape: (60,-5.5) (20,-5.5) (10,0.5). Levels from Z2 every 2 while above -5.5: 0, -2, -4.
    //   Z0: on (20,-5.5)-(10,0.5): X = 20 - 10*(5.5/6) = 10.8333..;  Z-2: X = 20 - 10*(3.5/6);
    //   Z-4: X = 20 - 10*(1.5/6) = 17.5. Cuts run from X r80 inwards (-X), escape +Z and +X.
    auto path = path_of(moves_of(program, system_a_lathe()));
    const double levels[] = {0, -2, -4};
    const double ends[] = {20 - 10 * 5.5 / 6, 20 - 10 * 3.5 / 6, 17.5};
    std::size_t i = 1;
    for (int k = 0; k < 3; ++k, i += 4) {
        expect_path(path, i,
                    {{80, levels[k], true},
                     {ends[k], levels[k], false},
                     {ends[k] + 0.5, levels[k] + 0.5, false},
                     {80, levels[k] + 0.5, true}});
    }
    expect_path(path, i, {{80, -5.5, true}, {20, -5.5, false}, {10, 0.5, false}, {10, 2, true}, {80, 2, true}});
}

TEST(LatheCycles, G73RepeatsTheShapeWithShrinkingRelief) {
    // Fanuc's G73 example: A = X220 Z160, G73 U14 W14 R3, allowance U4 (2 radius) W2. The passes
    // are moved by 14+2, 7+2 and 0+2 in X (radius) and in Z: A' = (r40, Z120) becomes
    // (56,136), (49,129), (42,122).
    const char* program =
        "N011 G00 X220.0 Z160.0\n"
        "N012 G73 U14.0 W14.0 R3\n"
        "N013 G73 P014 Q019 U4.0 W2.0 F0.3 S0180\n"
        "N014 G00 X80.0 W-40.0\n"
        "N015 G01 W-20.0 F0.15 S0600\n"
        "N016 X120.0 W-10.0\n"
        "N017 W-20.0 S0400\n"
        "N018 G02 X160.0 W-20.0 R20.0\n"
        "N019 G01 X180.0 W-10.0 S0280\n"
        "N020 G70 P014 Q019\n"
        "M30\n";
    auto path = path_of(moves_of(program, system_a_lathe(300)));
    const double shift[] = {16, 9, 2};
    std::size_t i = 1;
    for (double s : shift) {
        expect_path(path, i,
                    {{40 + s, 120 + s, true},
                     {40 + s, 100 + s, false},
                     {60 + s, 90 + s, false},
                     {60 + s, 70 + s, false},
                     {80 + s, 50 + s, false},
                     {90 + s, 40 + s, false},
                     {110, 160, true}});
        i += 7;
    }
    expect_path(path, i,
                {{40, 120, true},
                 {40, 100, false},
                 {60, 90, false},
                 {60, 70, false},
                 {80, 50, false},
                 {90, 40, false},
                 {110, 160, true}});
}

TEST(LatheCycles, G73OneBlockFormRepeatsTheSameWay) {
    // The one-block form (Fanuc Series 15, Haas): I K are the relief (I a radius), D the number
    // of passes, in the P Q block. The manual's example written so runs the same passes as its
    // two-block form above: moved by 16, 9, 2 (relief 14 shrinking by 7 a pass, plus the
    // allowance 2), so the first pass goes in to (r56, Z136).
    const char* shape =
        "N014 G00 X80.0 W-40.0\n"
        "N015 G01 W-20.0 F0.15\n"
        "N016 X120.0 W-10.0\n"
        "N017 W-20.0\n"
        "N018 G02 X160.0 W-20.0 R20.0\n"
        "N019 G01 X180.0 W-10.0\n"
        "M30\n";
    const std::string two_block =
        std::string("G00 X220.0 Z160.0\nG73 U14.0 W14.0 R3\n") + "G73 P014 Q019 U4.0 W2.0 F0.3\n" + shape;
    const std::string one_block =
        std::string("G00 X220.0 Z160.0\n") + "G73 P014 Q019 I14.0 K14.0 U4.0 W2.0 D3 F0.3\n" + shape;
    const auto want = path_of(moves_of(two_block, system_a_lathe(300)));
    const auto got = path_of(moves_of(one_block, system_a_lathe(300)));
    ASSERT_EQ(got.size(), want.size());
    expect_path(got, 0, want);
    expect_path(got, 1, {{56, 136, true}});
    // Its words hold for that cycle alone: a later G73 P Q without them has no number of passes.
    EXPECT_EQ(error_where(one_block.substr(0, one_block.size() - 4) + "G73 P014 Q019 U4.0 W2.0 F0.3\nM30\n",
                          system_a_lathe(300)),
              "missing-word 9:1");
}

TEST(LatheCycles, G71R1SelectsTypeII) {
    // Haas's one-block form selects type II with R1: the pocket of lathe_pockets_test.cpp, its P
    // block naming X alone, roughs as when the P block names Z (Fanuc's rule). Level 19 ends on
    // the far wall at Z = -25 - 5 x 9/10 = -29.5.
    const std::string shape = "G1 Z-10.\nX20. Z-15.\nZ-25.\nX40. Z-30.\nN20 Z-40.\nM30\n";
    const auto with_r1 =
        path_of(moves_of("G0 X50. Z2.\nG71 P10 Q20 U0 W0 D2. R1 F0.2\nN10 G0 X30.\n" + shape, system_a_lathe()));
    const auto fanuc_rule =
        path_of(moves_of("G0 X50. Z2.\nG71 U2.\nG71 P10 Q20 U0 W0 F0.2\nN10 G0 X30. Z2.\n" + shape, system_a_lathe()));
    ASSERT_EQ(with_r1.size(), fanuc_rule.size());
    expect_path(with_r1, 0, fanuc_rule);
    expect_path(with_r1, 9, {{19, 2, true}, {19, -29.5, false}});
}

TEST(LatheCycles, OneBlockFormErrors) {
    const MachineConfig lathe = system_a_lathe();
    const std::string shape = "N10 G0 X30.\nN20 G1 Z-10.\nM30\n";
    // R on G71 P Q is R1 (type II) or nothing; the escape belongs to the block G71 U R.
    EXPECT_EQ(error_where("G0 X60. Z2.\nG71 P10 Q20 U0.4 D2. R0.5 F0.2\n" + shape, lathe), "bad-value 2:22");
    // D I K name the one-block form: not on a first block.
    EXPECT_EQ(error_where("G71 U2. R0.5 D1.\n", lathe), "unused-word 1:14");
    EXPECT_EQ(error_where("G73 U1. W1. R3 I1.\n", lathe), "unused-word 1:16");
    // G73 P Q: relief without a number of passes, passes not a whole number, R in the P Q block.
    EXPECT_EQ(error_where("G0 X60. Z2.\nG73 P10 Q20 I3. U0.4 F0.2\n" + shape, lathe), "missing-word 2:13");
    EXPECT_EQ(error_where("G0 X60. Z2.\nG73 P10 Q20 I3. D2.5 F0.2\n" + shape, lathe), "bad-value 2:17");
    EXPECT_EQ(error_where("G0 X60. Z2.\nG73 P10 Q20 I3. D0 F0.2\n" + shape, lathe), "bad-value 2:17");
    EXPECT_EQ(error_where("G0 X60. Z2.\nG73 P10 Q20 U0.4 R3 F0.2\n" + shape, lathe), "unused-word 2:18");
    // G70 takes no allowance or depth (the Haas class programs of tests/real_lathe copy them).
    EXPECT_EQ(error_where("G0 X60. Z2.\nG70 P10 Q20 U0 W0 D0.01\n" + shape, lathe), "unused-word 2:13");
    EXPECT_EQ(error_where("G0 X60. Z2.\nG70 P10 Q20 D0.01\n" + shape, lathe), "unused-word 2:13");
}

TEST(LatheCycles, ProgramGoesOnAfterTheShapeAndG70FindsItFarAway) {
    // The P-Q blocks run only through the cycles; G70 later in the program finds them again.
    const char* program =
        "G0 X60. Z2.\n"
        "G71 U2. R0.5\n"
        "G71 P10 Q20 U0.4 W0.1 F0.25\n"
        "N10 G0 X30.\n"
        "G1 Z-20.\n"
        "N20 X60.\n"
        "G0 X100. Z50.\n"
        "M1\n"
        "G0 X60. Z2.\n"
        "G70 P10 Q20\n"
        "M30\n";
    auto path = path_of(moves_of(program, system_a_lathe()));
    // The last four: the G70 pass (r15 Z2 -> r15 Z-20 -> r30 Z-20) and back to (30, 2).
    ASSERT_GE(path.size(), 4u);
    expect_path(path, path.size() - 4, {{15, 2, true}, {15, -20, false}, {30, -20, false}, {30, 2, true}});
    // No move of the program ran the shape at its own place: Z-20 appears only in the cycles.
    int deepest = 0;
    for (const Point& p : path) deepest += p.z == -20 ? 1 : 0;
    EXPECT_EQ(deepest, 2);
}

TEST(LatheCycles, FanucsErrors) {
    const MachineConfig lathe = system_a_lathe();
    const char* head = "G0 X60. Z2.\nG71 U2. R0.5\n";
    // Missing P sequence (PS0063), at the P word.
    EXPECT_EQ(error_where(std::string(head) + "G71 P10 Q20 U0.4 W0.1 F0.2\nN11 G0 X30.\nN20 G1 Z-10.\nM30\n", lathe),
              "missing-sequence 3:5");
    EXPECT_EQ(error_where(std::string(head) + "G71 P10 Q21 U0.4 W0.1 F0.2\nN10 G0 X30.\nN20 G1 Z-10.\nM30\n", lathe),
              "missing-sequence 3:9");
    EXPECT_EQ(error_where(std::string(head) + "G71 P10 U0.4 F0.2\n", lathe), "missing-word 3:1");
    // Not monotonic for type I (PS0064): the X goes back down in the third block.
    EXPECT_EQ(error_where(std::string(head) +
                              "G71 P10 Q20 U0.4 W0.1 F0.2\nN10 G0 X30.\nG1 Z-10.\nX40. Z-15.\nX34. Z-20.\nN20 X60.\n",
                          lathe),
              "bad-cycle 7:1");
    // An arc bulging past its end points is not monotonic either.
    EXPECT_EQ(error_where(std::string(head) +
                              "G71 P10 Q20 U0.4 W0.1 F0.2\nN10 G0 X30.\nG1 Z-10.\nG3 X30. Z-20. R6.\nN20 G1 X60.\n",
                          lathe),
              "bad-cycle 6:1");
    // Corner rounds posted with I or K only and rounded to 4 decimals in inch (end radius 0.00005
    // in off the start radius, so the second bulges 0.00005 in past its end point in Z) run one
    // way: accepted, as the control cuts them.
    EXPECT_FALSE(moves_of("G20\nG0 X.988 Z.1\nG71 U.035 R.01\nG71 P10 Q20 U.02 W.005 F.01\nN10 G0 X.1755\n"
                          "G1 Z0.\nG3 X.394 Z-.1092 K-.1092\nG1 Z-.1893\nG2 X.4875 Z-.236 I.0467\nN20 G1 X.988\nM30\n",
                          lathe)
                     .empty());
    // Wrong-sign allowance: U-0.4 on an outside shape would leave it inside the part.
    EXPECT_EQ(error_where(std::string(head) + "G71 P10 Q20 U-0.4 W0.1 F0.2\nN10 G0 X30.\nN20 G1 Z-10.\n", lathe),
              "bad-cycle 3:13");
    // No depth of cut given.
    EXPECT_EQ(error_where("G0 X60. Z2.\nG71 P10 Q20 U0.4 F0.2\nN10 G0 X30.\nN20 G1 Z-10.\n", lathe),
              "missing-word 2:1");
    EXPECT_EQ(error_where("G71 U0 R0.5\n", lathe), "bad-value 1:5");
    EXPECT_EQ(error_where("G71 U1. W1.\n", lathe), "unused-word 1:9");
    // A P block that names Z makes type II (lathe_pockets_test.cpp): accepted.
    EXPECT_FALSE(
        moves_of(std::string(head) + "G71 P10 Q20 U0.4 F0.2\nN10 G0 X30. Z1.\nN20 G1 Z-10.\nM30\n", lathe).empty());
    // A cycle inside the shape, and an unknown word.
    EXPECT_EQ(error_where(std::string(head) + "G71 P10 Q20 U0.4 F0.2\nN10 G0 X30.\nG70 P10 Q20\nN20 G1 Z-10.\n", lathe),
              "bad-cycle 5:1");
    EXPECT_EQ(error_where("G0 X60. Z2.\nG70 P10 Q20 K1\n", lathe), "unused-word 2:13");
    EXPECT_EQ(error_where("G0 X60. Z2.\nG73 P10 Q20 F0.2\nN10 G0 X30.\nN20 G1 Z-10.\n", lathe), "missing-word 2:1");
    EXPECT_EQ(error_where("G73 U1. W1. R0\n", lathe), "bad-value 1:13");
}

}  // namespace
}  // namespace nckit::test
