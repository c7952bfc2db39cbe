// Nose radius compensation with an imaginary tool tip (orientations 1-8): the programmed point
// is the tip the offsets measure, not the nose centre. Worked numbers for a 45-degree chamfer and
// a taper, the tip shifts of all eight orientations, G70 with compensation in its shape, and
// random profiles: the nose circle (centre = commanded point less the tip shift) touches every
// programmed block and never cuts past the profile.
#include <algorithm>
#include <cmath>
#include <random>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "interp_support.hpp"
#include "lathe_test_machine.hpp"

namespace nckit::test {
namespace {

constexpr double nose_mm = 0.8;

MachineConfig lathe_with_tip(int tip) {
    MachineConfig m = system_a_lathe(300);
    ToolEntry e;
    e.number = 2;
    e.radius_mm = nose_mm;
    e.orientation = tip;
    m.tools.insert(e);
    return m;
}

//! Signed distance (radius, Z plane) of p from the line through (r0,z0) with unit normal (nr,nz).
double distance_from(const AxisVector& p, double r0, double z0, double nr, double nz) {
    return nr * (p[Axis::X] - r0) + nz * (p[Axis::Z] - z0);
}

std::vector<Line> feeds_of_line(const std::vector<Move>& moves, std::uint32_t line) {
    std::vector<Line> out;
    for (const Move& m : moves) {
        if (const auto* l = std::get_if<Line>(&m.what); l != nullptr && m.where.line == line) out.push_back(*l);
    }
    return out;
}

const char* profile =
    "T0202\nG0 X30. Z5.\nG42 G1 X16. Z2. F0.2\nG1 Z0.\nX20. Z-2.\nX30. Z-12.\nZ-20.\nG40 G0 X40.\nM30\n";

TEST(LatheNoseTip, ChamferAndTaperWithTip3) {
    // Tip 3 (outside turning tool): the tip lies 0.8 below the nose centre in X and 0.8 towards
    // the chuck in Z. G42 puts the centre 0.8 outside the contour along the outward normal n, so
    // the commanded tip lies at  R (n - (1, 1))  from the contour: its distance along n is
    // R (1 - n_r - n_z).
    //   The chamfer (r8, Z0) -> (r10, Z-2): n = (1, 1)/sqrt 2, distance 0.8 (1 - sqrt 2) = -0.331371.
    //   The taper (r10, Z-2) -> (r15, Z-12): direction (5, -10)/sqrt 125, n = (2, 1)/sqrt 5 =
    //   (0.894427, 0.447214), distance 0.8 (1 - 1.341641) = -0.273313.
    //   Along Z at r15 the tip runs at r15 exactly (n = (1, 0): the centre is 0.8 out, the tip 0.8 in).
    const auto moves = moves_of(profile, lathe_with_tip(3));
    const auto chamfer = feeds_of_line(moves, 5);
    ASSERT_EQ(chamfer.size(), 1u);
    for (const AxisVector& p : {chamfer[0].from, chamfer[0].to}) {
        EXPECT_NEAR(distance_from(p, 8, 0, std::sqrt(0.5), std::sqrt(0.5)), -0.331371, 1e-6);
    }
    const auto taper = feeds_of_line(moves, 6);
    ASSERT_EQ(taper.size(), 1u);
    for (const AxisVector& p : {taper[0].from, taper[0].to}) {
        EXPECT_NEAR(distance_from(p, 10, -2, 2 / std::sqrt(5.0), 1 / std::sqrt(5.0)), -0.273313, 1e-6);
    }
    const auto along = feeds_of_line(moves, 7);
    ASSERT_FALSE(along.empty());
    EXPECT_NEAR(along.back().to[Axis::X], 15.0, 1e-9);
    EXPECT_NEAR(along.back().to[Axis::Z], -20.0 - nose_mm, 1e-9);
    // The exit goes from the shifted point back to the programmed one.
    const auto exit = feeds_of_line(moves, 8);
    ASSERT_EQ(exit.size(), 1u);
    EXPECT_NEAR(exit[0].from[Axis::Z], -20.0 - nose_mm, 1e-9);
    EXPECT_NEAR(exit[0].to[Axis::X], 20.0, 1e-9);
    EXPECT_NEAR(exit[0].to[Axis::Z], -20.0, 1e-9);
}

TEST(LatheNoseTip, EveryOrientationShiftsByItsTip) {
    // Against tip 0 (the nose centre programmed), tip k moves every compensated point by its tip
    // vector: 1 (+,+) 2 (+,-) 3 (-,-) 4 (-,+) 5 Z+ 6 X+ 7 Z- 8 X-, in (X radius, Z), times R.
    const int x_side[9] = {0, 1, 1, -1, -1, 0, 1, 0, -1};
    const int z_side[9] = {0, 1, -1, -1, 1, 1, 0, -1, 0};
    const auto centre = feeds_of_line(moves_of(profile, lathe_with_tip(0)), 6);
    for (int tip = 1; tip <= 9; ++tip) {
        SCOPED_TRACE(tip);
        const auto shifted = feeds_of_line(moves_of(profile, lathe_with_tip(tip)), 6);
        ASSERT_EQ(shifted.size(), centre.size());
        const double dx = tip == 9 ? 0 : x_side[tip] * nose_mm;
        const double dz = tip == 9 ? 0 : z_side[tip] * nose_mm;
        EXPECT_NEAR(shifted[0].to[Axis::X] - centre[0].to[Axis::X], dx, 1e-9);
        EXPECT_NEAR(shifted[0].to[Axis::Z] - centre[0].to[Axis::Z], dz, 1e-9);
    }
}

TEST(LatheNoseTip, G70RunsTheCompensatedShape) {
    // G42 in the P block, G40 in the Q block: G70 cuts the same path as the blocks run directly.
    const std::string shape = "N10 G42 G1 X16. Z2. F0.2\nG1 Z0.\nX20. Z-2.\nX30. Z-12.\nZ-20.\nN20 G40 G0 X40.\n";
    const auto direct = moves_of("T0202\nG0 X30. Z5.\n" + shape + "M30\n", lathe_with_tip(3));
    const auto cycle = moves_of("T0202\nG0 X30. Z5.\nG70 P10 Q20\nM30\n" + shape, lathe_with_tip(3));
    std::vector<Line> a;
    std::vector<Line> b;
    for (const Move& m : direct) {
        if (const auto* l = std::get_if<Line>(&m.what)) a.push_back(*l);
    }
    for (const Move& m : cycle) {
        if (const auto* l = std::get_if<Line>(&m.what); l != nullptr && m.where.line >= 4) b.push_back(*l);
    }
    ASSERT_GE(b.size() + 1, a.size());
    for (std::size_t i = 1; i < a.size(); ++i) {
        EXPECT_NEAR(a[i].to[Axis::X], b[i - 1].to[Axis::X], 1e-9) << i;
        EXPECT_NEAR(a[i].to[Axis::Z], b[i - 1].to[Axis::Z], 1e-9) << i;
    }
}

TEST(LatheNoseTip, G71RoughsToTheCompensatedShape) {
    // With no allowance the last roughing pass of G71 is the compensated shape itself: every
    // point G70 reaches is a point the last pass reached.
    const std::string program =
        "T0202\nG0 X40. Z5.\nG71 U1. R0.5\nG71 P10 Q20 U0 W0 F0.2\n"
        "N10 G0 G42 X16.\nG1 Z0.\nX20. Z-2.\nX30. Z-12.\nZ-20.\nN20 G40 G0 X40.\nG70 P10 Q20\nM30\n";
    const auto moves = moves_of(program, lathe_with_tip(3));
    std::vector<AxisVector> rough;
    std::vector<AxisVector> finish;
    for (const Move& m : moves) {
        const AxisVector* to = nullptr;
        if (const auto* l = std::get_if<Line>(&m.what); l != nullptr && !l->rapid) to = &l->to;
        if (const auto* a = std::get_if<Arc>(&m.what)) to = &a->to;
        if (to == nullptr) continue;
        if (m.where.line == 4) rough.push_back(*to);
        if (m.where.line >= 6 && m.where.line <= 9) finish.push_back(*to);
    }
    ASSERT_GE(finish.size(), 4u);
    for (const AxisVector& p : finish) {
        const bool found = std::any_of(rough.begin(), rough.end(), [&](const AxisVector& q) {
            return std::abs(q[Axis::X] - p[Axis::X]) < 1e-9 && std::abs(q[Axis::Z] - p[Axis::Z]) < 1e-9;
        });
        EXPECT_TRUE(found) << "X" << p[Axis::X] << " Z" << p[Axis::Z];
    }
}

double distance_to_segment(double r, double z, double r0, double z0, double r1, double z1) {
    const double dr = r1 - r0;
    const double dz = z1 - z0;
    const double t = std::clamp(((r - r0) * dr + (z - z0) * dz) / (dr * dr + dz * dz), 0.0, 1.0);
    return std::hypot(r - (r0 + t * dr), z - (z0 + t * dz));
}

TEST(LatheNoseTip, RandomProfilesTheNoseTouchesEveryBlock) {
    std::mt19937 rng(20261127);
    auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
    const int x_side[9] = {0, 1, 1, -1, -1, 0, 1, 0, -1};
    const int z_side[9] = {0, 1, -1, -1, 1, 1, 0, -1, 0};
    for (int trial = 0; trial < 100; ++trial) {
        const int tip = std::uniform_int_distribution<int>(1, 8)(rng);
        // An outside profile rising in radius towards the chuck: along Z, tapers, faces.
        std::vector<std::pair<double, double>> points{{uniform(4, 10), 0.0}};  // (r, z)
        for (int i = 0; i < 5; ++i) {
            auto [r, z] = points.back();
            const int kind = i == 0 ? 0 : std::uniform_int_distribution<int>(0, 2)(rng);
            if (kind != 2) z -= uniform(3, 10);
            if (kind != 0) r += uniform(2, 6);
            points.emplace_back(r, z);
        }
        std::string text = fmt::format("T0202\nG0 X{:.3f} Z5.\nG42 G1 X{:.3f} Z{:.3f} F0.2\n",
                                       2 * points.front().first + 20, 2 * points.front().first, 2.0);
        text += fmt::format("G1 Z{:.3f}\n", points.front().second);
        for (std::size_t i = 1; i < points.size(); ++i) {
            text += fmt::format("X{:.3f} Z{:.3f}\n", 2 * points[i].first, points[i].second);
        }
        text += fmt::format("G40 G0 X{:.3f}\nM30\n", 2 * points.back().first + 20);
        SCOPED_TRACE(text);
        for (auto& [r, z] : points) {
            r = std::stod(fmt::format("{:.3f}", 2 * r)) / 2;
            z = std::stod(fmt::format("{:.3f}", z));
        }
        points.insert(points.begin(), {points.front().first, 2.0});
        const auto moves = moves_of(text, lathe_with_tip(tip));
        const double sr = x_side[tip] * nose_mm;
        const double sz = z_side[tip] * nose_mm;
        auto nearest = [&](double r, double z) {
            double best = 1e9;
            for (std::size_t i = 1; i < points.size(); ++i) {
                best = std::min(best, distance_to_segment(r, z, points[i - 1].first, points[i - 1].second,
                                                          points[i].first, points[i].second));
            }
            return best;
        };
        for (const Move& m : moves) {
            if (m.where.line < 4 || m.where.line >= 4 + points.size() - 1) continue;
            std::vector<AxisVector> samples;
            if (const auto* l = std::get_if<Line>(&m.what)) {
                for (int k = 0; k <= 10; ++k) {
                    AxisVector p = l->from;
                    for (Axis axis : {Axis::X, Axis::Z}) p[axis] += k / 10.0 * (l->to[axis] - l->from[axis]);
                    samples.push_back(p);
                }
                // The block's own move ends with the nose touching its programmed segment.
                const std::size_t block = m.where.line - 4;  // segment points[block] -> points[block + 1]
                const double r = l->to[Axis::X] - sr;
                const double z = l->to[Axis::Z] - sz;
                if (l->to != l->from) {
                    EXPECT_NEAR(distance_to_segment(r, z, points[block].first, points[block].second,
                                                    points[block + 1].first, points[block + 1].second),
                                nose_mm, 1e-6)
                        << "line " << m.where.line;
                }
            } else if (const auto* a = std::get_if<Arc>(&m.what)) {
                samples.push_back(a->from);
                samples.push_back(a->to);
                // A corner arc turns about the programmed corner: its centre less the shift.
                EXPECT_NEAR(nearest(a->center[Axis::X] - sr, a->center[Axis::Z] - sz), 0.0, 1e-6);
            }
            // Corners within 0.05 rad count as tangent (docs/cutter-compensation.md): the next
            // move starts where the last one ended, up to R (1 - cos 0.05) nearer its own segment.
            for (const AxisVector& p : samples) {
                EXPECT_GE(nearest(p[Axis::X] - sr, p[Axis::Z] - sz), nose_mm * std::cos(0.05) - 1e-6)
                    << "line " << m.where.line;
            }
        }
    }
}

}  // namespace
}  // namespace nckit::test
