// The chain smoother (src/plan/chain_smoother.hpp): what it hands the planner stays within its
// shares of the G64 P tolerance of the written lines, keeps the chain's ends and corners, and
// smooths the rounding noise of a CAM circle.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "../../src/plan/chain_smoother.hpp"
#include "move_builder.hpp"
#include "trajectory_check.hpp"

namespace nckit {
namespace {

using plan_detail::ChainSmoother;

double distance_to_polyline(const AxisVector& p, const std::vector<Move>& lines) {
    double best = 1e300;
    for (const Move& m : lines) {
        const Line& l = std::get<Line>(m.what);
        best = std::min(best, plan_test::distance_to_chord(p, l.from, l.to));
    }
    return best;
}

//! The lines ready to leave, taken as the planner takes them (ready, then drop_ready).
void drain(ChainSmoother& chains, std::vector<Move>& out) {
    while (const Move* m = chains.ready()) {
        out.push_back(*m);
        chains.drop_ready();
    }
}

std::vector<Move> smooth(const std::vector<Move>& moves, double tolerance_mm) {
    ChainSmoother chains;
    std::vector<Move> out;
    for (const Move& move : moves) {
        if (!chains.push(move, tolerance_mm)) {
            chains.flush();
            drain(chains, out);
            out.push_back(move);
        }
        drain(chains, out);
    }
    chains.flush();
    drain(chains, out);
    return out;
}

//! A circle of radius r around (r, 0) from the origin as `count` chords, end points rounded.
std::vector<Move> rounded_circle(int count, double r, int decimals, double tolerance_mm) {
    plan_test::MoveBuilder b;
    const double scale = std::pow(10.0, decimals);
    for (int k = 1; k <= count; ++k) {
        const double angle = 2 * std::numbers::pi * k / count;
        AxisVector to;
        to[0] = std::round((r - r * std::cos(angle)) * scale) / scale;
        to[1] = std::round(r * std::sin(angle) * scale) / scale;
        b.line(to, 3000, PathControl{false, tolerance_mm});
    }
    return b.moves;
}

// Every point handed on lies within the smoothing and merging shares of the tolerance of the
// written lines, the lines join end to end, the chain starts and ends where it was written, and
// the first and last lines are as written (the joins with other moves keep the whole tolerance).
TEST(ChainSmoother, StaysWithinItsShareOfTheToleranceAndKeepsTheEnds) {
    std::mt19937 random(7);
    for (int trial = 0; trial < 6; ++trial) {
        const double tolerance = std::uniform_real_distribution<double>(0.002, 0.05)(random);
        const int count = std::uniform_int_distribution<int>(3, 400)(random);
        const std::vector<Move> written = rounded_circle(count, 5 + trial * 7, 3 + trial % 2, tolerance);
        const std::vector<Move> out = smooth(written, tolerance);
        ASSERT_FALSE(out.empty());
        ASSERT_LE(out.size(), written.size());
        const double share = (plan_detail::chain_budget_share + plan_detail::chain_merge_share) * tolerance;
        for (std::size_t k = 0; k < out.size(); ++k) {
            const Line& l = std::get<Line>(out[k].what);
            if (k > 0) {
                EXPECT_EQ(std::get<Line>(out[k - 1].what).to, l.from);
            }
            for (int step = 0; step <= 16; ++step) {
                AxisVector p;
                for (std::size_t i = 0; i < 3; ++i) p[i] = l.from[i] + (l.to[i] - l.from[i]) * step / 16.0;
                EXPECT_LE(distance_to_polyline(p, written), share * (1 + 1e-9) + 1e-12)
                    << "trial " << trial << " line " << k;
            }
            // The whole tolerance only at a join of lines as written (the chain's last line, or
            // lines of a chain too short to smooth, or parted by corners).
            const double left = l.path.tolerance_mm;
            if (left == tolerance) {
                const bool as_written = std::any_of(written.begin(), written.end(), [&](const Move& w) {
                    return std::get<Line>(w.what).from == l.from && std::get<Line>(w.what).to == l.to;
                });
                EXPECT_TRUE(as_written) << "trial " << trial << " line " << k;
            } else {
                EXPECT_NEAR(left, tolerance - share, 1e-15);
            }
        }
        const Line& first = std::get<Line>(out.front().what);
        const Line& last = std::get<Line>(out.back().what);
        EXPECT_EQ(first.from, std::get<Line>(written.front().what).from);
        EXPECT_EQ(first.to, std::get<Line>(written.front().what).to);
        EXPECT_EQ(last.from, std::get<Line>(written.back().what).from);
        EXPECT_EQ(last.to, std::get<Line>(written.back().what).to);
        EXPECT_EQ(last.path.tolerance_mm, tolerance);
    }
}

// A corner of the part (a turn above chain_max_turn_rad), a long line, a rapid and an exact stop
// end a chain: such a vertex is handed on as written.
TEST(ChainSmoother, CornersRapidsAndExactStopsStayAsWritten) {
    plan_test::MoveBuilder b;
    const PathControl blend{false, 0.01};
    for (int k = 1; k <= 50; ++k) b.line(AxisVector{0.05 * k, 0.0001 * (k % 3), 0}, 3000, blend);
    const AxisVector corner = b.position;
    for (int k = 1; k <= 50; ++k) b.line(AxisVector{corner[0], corner[1] + 0.05 * k, 0}, 3000, blend);
    b.line(AxisVector{corner[0], corner[1] + 50, 0}, 3000, blend);  // 47.5 mm: not a sample of a curve
    b.rapid(AxisVector{0, 0, 5});
    b.line(AxisVector{0.05, 0, 5}, 3000, PathControl{true, 0.01});
    const std::vector<Move> out = smooth(b.moves, 0.01);
    auto has_vertex = [&](const AxisVector& p) {
        return std::any_of(out.begin(), out.end(), [&](const Move& m) {
            const auto* l = std::get_if<Line>(&m.what);
            return l != nullptr && l->to == p;
        });
    };
    EXPECT_TRUE(has_vertex(corner));
    for (std::size_t k = 101; k < b.moves.size(); ++k) {
        EXPECT_TRUE(has_vertex(std::get<Line>(b.moves[k].what).to)) << k;
    }
    EXPECT_EQ(std::get<Line>(out.back().what).to, b.position);
    EXPECT_TRUE(std::get<Line>(out.back().what).path.exact_stop);
}

// The written circle's rounding noise is gone: the turning from line to line of what comes out
// follows the circle's (third differences of direction, the curvature's change, shrink).
TEST(ChainSmoother, SmoothsTheRoundingNoiseOfACamCircle) {
    const std::vector<Move> written = rounded_circle(2000, 20, 4, 0.01);
    const std::vector<Move> out = smooth(written, 0.01);
    EXPECT_LT(out.size(), written.size() / 4);  // 0.06 mm chords merged into chords of about 0.5 mm
    // Each output vertex lies on a circle of radius 20 around (20, 0) within a tenth of a micrometre
    // (the written points lie up to 0.07 µm off it; the filter keeps the radius).
    double worst = 0;
    for (const Move& m : out) {
        const Line& l = std::get<Line>(m.what);
        worst = std::max(worst, std::abs(std::hypot(l.to[0] - 20, l.to[1]) - 20));
    }
    EXPECT_LT(worst, 1e-4);
}

}  // namespace
}  // namespace nckit
