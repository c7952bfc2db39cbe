// G71 and G70 on random monotonic outside shapes: roughing never cuts inside the finishing
// allowance, no pass is deeper than programmed, the last roughing pass leaves exactly the
// allowance, and G70 follows the shape as programmed.
#include <algorithm>
#include <random>
#include <set>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "interp_support.hpp"
#include "lathe_test_machine.hpp"

namespace nckit::test {
namespace {

struct ShapePoint {
    double z;
    double r;  // radius
};

struct Case {
    std::vector<ShapePoint> shape;  // A' first
    double start_r = 0;
    double depth = 0;
    double escape = 0;
    double u = 0;  // diameter
    double w = 0;
    std::string program;
};

Case random_case(std::mt19937& rng) {
    auto uniform = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
    Case c;
    ShapePoint p{2.0, uniform(3, 15)};
    c.shape.push_back(p);
    const int segments = std::uniform_int_distribution<int>(2, 7)(rng);
    for (int i = 0; i < segments; ++i) {
        // 0 along Z, 1 a taper, 2 a face. The first runs along Z from A': a taper or face there,
        // moved forward by W, would lie partly in front of the start point, where a level has
        // nothing to cut and is left to the last pass (Fanuc's behaviour too).
        const int kind = i == 0 ? 0 : std::uniform_int_distribution<int>(0, 2)(rng);
        if (kind != 2) p.z -= uniform(1, 12);
        if (kind != 0) p.r += uniform(0.5, 5);
        c.shape.push_back(p);
    }
    c.start_r = p.r + uniform(0.5, 5);
    c.depth = uniform(0.4, 3);
    c.escape = uniform(0, 0.5);
    c.u = uniform(0, 1);
    c.w = uniform(0, 0.3);
    auto num = [](double v) { return fmt::format("{:.3f}", v); };
    std::string text = fmt::format("G97 S800 M3\nG0 X{} Z2.\nG71 U{} R{}\nG71 P10 Q20 U{} W{} F0.25\n",
                                   num(2 * c.start_r), num(c.depth), num(c.escape), num(c.u), num(c.w));
    for (std::size_t i = 0; i < c.shape.size(); ++i) {
        const std::string n = i == 0 ? "N10 " : i + 1 == c.shape.size() ? "N20 " : "";
        // The P block names X only (A' lies at A's Z2): type I. Naming Z too would make type II.
        const std::string z = i == 0 ? std::string() : " Z" + num(c.shape[i].z);
        text += fmt::format("{}{} X{}{}{}\n", n, i == 0 ? "G0" : "G1", num(2 * c.shape[i].r), z, i == 1 ? " F0.1" : "");
    }
    text += "G70 P10 Q20\nM30\n";
    c.program = text;
    // The program rounds to 0.001 on the diameter: the checks use what it says.
    auto read = [](const std::string& s) { return std::stod(s); };
    for (ShapePoint& q : c.shape) {
        q.r = read(num(2 * q.r)) / 2;
        q.z = read(num(q.z));
    }
    c.start_r = read(num(2 * c.start_r)) / 2;
    c.depth = read(num(c.depth));
    c.escape = read(num(c.escape));
    c.u = read(num(c.u));
    c.w = read(num(c.w));
    return c;
}

//! Radius of the shape moved by the allowance at z, the low end on a face; none off its length.
std::optional<double> moved_radius_at(const Case& c, double z) {
    std::optional<double> best;
    for (std::size_t i = 1; i < c.shape.size(); ++i) {
        ShapePoint a{c.shape[i - 1].z + c.w, c.shape[i - 1].r + c.u / 2};
        ShapePoint b{c.shape[i].z + c.w, c.shape[i].r + c.u / 2};
        if (z < std::min(a.z, b.z) - 1e-9 || z > std::max(a.z, b.z) + 1e-9) continue;
        double r = a.z == b.z ? std::min(a.r, b.r) : a.r + (z - a.z) / (b.z - a.z) * (b.r - a.r);
        best = best ? std::min(*best, r) : r;
    }
    return best;
}

TEST(LatheCycleProperties, RandomMonotonicShapes) {
    std::mt19937 rng(20261125);
    const MachineConfig lathe = system_a_lathe(400);
    for (int trial = 0; trial < 200; ++trial) {
        const Case c = random_case(rng);
        SCOPED_TRACE(c.program);
        const auto moves = moves_of(c.program, lathe);
        std::vector<Line> rough;
        std::vector<Line> finish;
        for (const Move& m : moves) {
            const auto* line = std::get_if<Line>(&m.what);
            if (line == nullptr) continue;
            if (m.where.line == 4) rough.push_back(*line);
            if (m.where.line >= 5 && m.where.line <= 4 + c.shape.size()) finish.push_back(*line);
        }
        ASSERT_FALSE(rough.empty());
        // Never inside the allowance: every point of every G71 move is on or outside the moved shape.
        for (const Line& l : rough) {
            for (double t : {0.0, 0.25, 0.5, 0.75, 1.0}) {
                const double z = l.from[Axis::Z] + t * (l.to[Axis::Z] - l.from[Axis::Z]);
                const double r = l.from[Axis::X] + t * (l.to[Axis::X] - l.from[Axis::X]);
                if (auto limit = moved_radius_at(c, z)) {
                    ASSERT_GE(r, *limit - 1e-9) << "at Z" << z;
                }
            }
        }
        // Pass depth: the levels cut along Z, from the start radius down to the moved shape's start.
        std::set<double, std::greater<>> levels{c.start_r, c.shape[0].r + c.u / 2};
        const std::size_t contour_moves = c.shape.size() - 1;
        for (std::size_t i = 0; i + contour_moves + 3 < rough.size(); ++i) {
            const Line& l = rough[i];
            if (!l.rapid && l.from[Axis::X] == l.to[Axis::X] && l.from[Axis::Z] != l.to[Axis::Z])
                levels.insert(l.to[Axis::X]);
        }
        for (auto it = levels.begin(); std::next(it) != levels.end(); ++it) {
            EXPECT_LE(*it - *std::next(it), c.depth + 1e-9);
        }
        // The last roughing pass is the shape moved by the allowance, point for point.
        std::size_t last = rough.size();
        while (last > 0 && rough[last - 1].rapid) --last;  // the return to A
        ASSERT_GE(last, contour_moves);
        for (std::size_t k = 0; k < contour_moves; ++k) {
            const Line& l = rough[last - contour_moves + k];
            EXPECT_NEAR(l.to[Axis::X], c.shape[k + 1].r + c.u / 2, 1e-9);
            EXPECT_NEAR(l.to[Axis::Z], c.shape[k + 1].z + c.w, 1e-9);
        }
        // G70 follows the shape as programmed, at its own feed.
        ASSERT_EQ(finish.size(), c.shape.size());
        for (std::size_t k = 0; k < c.shape.size(); ++k) {
            EXPECT_NEAR(finish[k].to[Axis::X], c.shape[k].r, 1e-9);
            EXPECT_NEAR(finish[k].to[Axis::Z], c.shape[k].z, 1e-9);
            if (k > 0) {
                EXPECT_DOUBLE_EQ(finish[k].feed.mm_per_rev, 0.1);
            }
        }
    }
}

}  // namespace
}  // namespace nckit::test
