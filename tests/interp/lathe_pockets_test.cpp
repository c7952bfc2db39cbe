// G71 type II (a P block naming X and Z): roughing follows pockets. A worked example computed by
// hand, the errors, and random pocket shapes: no roughing move cuts inside the moved shape.
#include <random>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "interp_support.hpp"
#include "lathe_test_machine.hpp"

namespace nckit::test {
namespace {

using Point = LathePoint;

std::vector<Point> path_of(const std::vector<Move>& moves) {
    return lathe_path_of(moves);
}

TEST(LathePockets, G71TypeIIRoughsTheLevelsAndThePocket) {
    // A = (r25, Z2). Shape: (15,2) -> (15,-10) -> (10,-15) -> (10,-25) -> (20,-30) -> (20,-40),
    // a pocket from Z-10 to Z-30 whose bottom is r10. Levels every 2 mm from r25 while above
    // r10: 23 21 19 17 15 13 11.
    //   23, 21: the shape lies below all the way: cut from A's Z2 to its end, Z-40.
    //   19: the far wall (10,-25)-(20,-30) rises through it at Z = -25 - 5 * 9/10 = -29.5;
    //   17: at Z-28.5.  15: the shape's first stretch lies on the level (nothing to cut there);
    //   the near wall (15,-10)-(10,-15) falls through it at Z-10, the far wall rises at Z-27.5.
    //   13: near wall Z = -10 - 5 * 2/5 = -12, far wall -26.5.  11: Z-14 and Z-25.5.
    // A stretch from A goes in at rapid (the P block is G0); a pocket stretch comes down at rapid
    // to the level above and feeds the last 2 mm. Each stretch escapes R0.5 at 45 degrees and
    // goes up to A's depth, r25 (the shape's highest point, r20, is lower).
    const std::string program =
        "G0 X50. Z2.\nG71 U2. R0.5\nG71 P10 Q20 U0 W0 F0.2\n"
        "N10 G0 X30. Z2.\nG1 Z-10.\nX20. Z-15.\nZ-25.\nX40. Z-30.\nN20 Z-40.\nM30\n";
    const auto path = path_of(moves_of(program, system_a_lathe()));
    std::vector<Point> want{{25, 2, true}};
    auto from_start = [&](double level, double end) {
        if (want.back().z != 2) want.push_back({25, 2, true});
        want.insert(want.end(),
                    {{level, 2, true}, {level, end, false}, {level + 0.5, end + 0.5, false}, {25, end + 0.5, true}});
    };
    auto pocket = [&](double level, double from, double end) {
        want.insert(want.end(), {{25, from, true},
                                 {level + 2, from, true},
                                 {level, from, false},
                                 {level, end, false},
                                 {level + 0.5, end + 0.5, false},
                                 {25, end + 0.5, true}});
    };
    from_start(23, -40);
    from_start(21, -40);
    from_start(19, -29.5);
    from_start(17, -28.5);
    pocket(15, -10, -27.5);
    pocket(13, -12, -26.5);
    pocket(11, -14, -25.5);
    // Back to A's Z at r25, then the last pass along the shape, and back to A.
    want.insert(want.end(), {{25, 2, true},
                             {15, 2, true},
                             {15, -10, false},
                             {10, -15, false},
                             {10, -25, false},
                             {20, -30, false},
                             {20, -40, false},
                             {25, -40, true},
                             {25, 2, true}});
    ASSERT_EQ(path.size(), want.size());
    for (std::size_t i = 0; i < want.size(); ++i) {
        EXPECT_NEAR(path[i].x_radius, want[i].x_radius, 1e-9) << "move " << i;
        EXPECT_NEAR(path[i].z, want[i].z, 1e-9) << "move " << i;
        EXPECT_EQ(path[i].rapid, want[i].rapid) << "move " << i;
    }
}

TEST(LathePockets, TypeIIErrors) {
    const MachineConfig lathe = system_a_lathe();
    const char* head = "G0 X50. Z2.\nG71 U2. R0.5\n";
    // Type II runs one way in Z: a shape that turns back in Z is refused at that block.
    EXPECT_EQ(error_where(std::string(head) + "G71 P10 Q20 U0.4 F0.2\nN10 G0 X30. Z2.\nG1 Z-10.\nX20.\nZ-5.\n"
                                              "N20 X40.\n",
                          lathe),
              "bad-cycle 7:1");
    // W0 still names Z: type II, so the pocket is accepted; without Z it is type I and refused.
    EXPECT_FALSE(moves_of(std::string(head) + "G71 P10 Q20 U0.4 F0.2\nN10 G0 X30. W0\nG1 Z-10.\nX20. Z-15.\n"
                                              "N20 X40. Z-20.\nM30\n",
                          lathe)
                     .empty());
    EXPECT_EQ(error_where(std::string(head) + "G71 P10 Q20 U0.4 F0.2\nN10 G0 X30.\nG1 Z-10.\nX20. Z-15.\n"
                                              "N20 X40. Z-20.\n",
                          lathe),
              "bad-cycle 6:1");
}

TEST(LathePockets, G72TypeIIFacesAPocketInZ) {
    // G72: levels of Z every 2 mm from Z2, cuts along X. The P block names X and Z (type II);
    // the shape runs inward in X, (r40,Z-10) (r30,Z-10) (r25,Z-14) (r15,Z-14) (r10,Z-6) (r0,Z-6),
    // with a pocket 4 mm deeper between r25 and r15. Levels 0 -2 ... -12; below Z-10 only the
    // pocket is cut: at Z-12 from r27.5 (the outer wall) to r13.75 (the inner wall).
    const std::string program =
        "G0 X90. Z2.\nG72 W2. R0.5\nG72 P10 Q20 U0 W0 F0.2\n"
        "N10 G0 X80. Z-10.\nG1 X60.\nX50. Z-14.\nX30.\nX20. Z-6.\nN20 X0.\nM30\n";
    auto profile_z = [](double r) {
        const double pts[][2] = {{40, -10}, {30, -10}, {25, -14}, {15, -14}, {10, -6}, {0, -6}};
        for (int i = 1; i < 6; ++i) {
            if (r <= pts[i - 1][0] && r >= pts[i][0]) {
                return pts[i - 1][1] + (r - pts[i - 1][0]) / (pts[i][0] - pts[i - 1][0]) * (pts[i][1] - pts[i - 1][1]);
            }
        }
        return -1e9;  // off the shape
    };
    bool pocket_cut = false;
    for (const Move& m : moves_of(program, system_a_lathe())) {
        const auto* l = std::get_if<Line>(&m.what);
        if (l == nullptr || m.where.line != 3) continue;
        for (int k = 0; k <= 20; ++k) {
            const double r = l->from[Axis::X] + k / 20.0 * (l->to[Axis::X] - l->from[Axis::X]);
            const double z = l->from[Axis::Z] + k / 20.0 * (l->to[Axis::Z] - l->from[Axis::Z]);
            ASSERT_GE(z, profile_z(r) - 1e-9) << "r" << r << " Z" << z;
        }
        if (!l->rapid && l->from[Axis::Z] == -12 && l->to[Axis::Z] == -12) {
            EXPECT_NEAR(l->from[Axis::X], 27.5, 1e-9);
            EXPECT_NEAR(l->to[Axis::X], 13.75, 1e-9);
            pocket_cut = true;
        }
    }
    EXPECT_TRUE(pocket_cut);
}

//! A random pocket shape: radius as a function of Z, one way in Z, down and up in X.
struct PocketCase {
    std::vector<std::pair<double, double>> shape;  // (z, r), A' first
    double start_r = 0;
    double u = 0;  // diameter
    std::string program;
};

PocketCase random_pocket(std::mt19937& rng) {
    auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
    auto num = [](double v) { return fmt::format("{:.3f}", v); };
    PocketCase c;
    double z = 2;
    double r = uniform(8, 20);
    double top = r;
    c.shape.emplace_back(z, r);
    const int segments = std::uniform_int_distribution<int>(3, 9)(rng);
    for (int i = 0; i < segments; ++i) {
        z -= uniform(0.5, 8);
        r = std::max(3.0, r + uniform(-6, 6));
        top = std::max(top, r);
        c.shape.emplace_back(z, r);
    }
    c.start_r = top + uniform(0.5, 4);
    c.u = uniform(0, 0.8);
    std::string text = fmt::format("G97 S800 M3\nG0 X{} Z2.\nG71 U{} R{}\nG71 P10 Q20 U{} W0 F0.25\n",
                                   num(2 * c.start_r), num(uniform(0.4, 3)), num(uniform(0, 0.5)), num(c.u));
    for (std::size_t i = 0; i < c.shape.size(); ++i) {
        const std::string n = i == 0 ? "N10 " : i + 1 == c.shape.size() ? "N20 " : "";
        text +=
            fmt::format("{}{} X{} Z{}\n", n, i == 0 ? "G0" : "G1", num(2 * c.shape[i].second), num(c.shape[i].first));
    }
    c.program = text + "M30\n";
    for (auto& [pz, pr] : c.shape) {
        pr = std::stod(num(2 * pr)) / 2 + std::stod(num(c.u)) / 2;  // moved by the allowance
        pz = std::stod(num(pz));
    }
    return c;
}

std::optional<double> radius_at(const PocketCase& c, double z) {
    for (std::size_t i = 1; i < c.shape.size(); ++i) {
        const auto [z0, r0] = c.shape[i - 1];
        const auto [z1, r1] = c.shape[i];
        if (z <= z0 + 1e-12 && z >= z1 - 1e-12) return r0 + (z - z0) / (z1 - z0) * (r1 - r0);
    }
    return std::nullopt;
}

TEST(LathePockets, RandomPocketsAreNeverCutInsideTheAllowance) {
    std::mt19937 rng(20261126);
    const MachineConfig lathe = system_a_lathe(400);
    for (int trial = 0; trial < 200; ++trial) {
        const PocketCase c = random_pocket(rng);
        SCOPED_TRACE(c.program);
        const auto moves = moves_of(c.program, lathe);
        std::size_t checked = 0;
        for (const Move& m : moves) {
            const auto* l = std::get_if<Line>(&m.what);
            if (l == nullptr || m.where.line != 4) continue;
            ++checked;
            for (int k = 0; k <= 20; ++k) {
                const double t = k / 20.0;
                const double z = l->from[Axis::Z] + t * (l->to[Axis::Z] - l->from[Axis::Z]);
                const double r = l->from[Axis::X] + t * (l->to[Axis::X] - l->from[Axis::X]);
                if (auto limit = radius_at(c, z)) {
                    ASSERT_GE(r, *limit - 1e-9) << "at Z" << z;
                }
            }
        }
        ASSERT_GT(checked, c.shape.size());
    }
}

}  // namespace
}  // namespace nckit::test
