// A CAM chain that starts or ends at rest (src/plan/pending_motion.hpp, start_from_rest and
// end_at_rest): its first and last short lines are taken into the transitions, which leave the
// first point and reach the last one already turning with the curve, within G64 P, so the chain's
// ends are not held back by a curvature ramp at the first and last lines' middles.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "move_builder.hpp"
#include "trajectory_check.hpp"
#include "nckit/plan/planner.hpp"
#include "nckit/plan/segment_limits.hpp"

namespace nckit {
namespace {

constexpr double feed_mm_min = 3000;
constexpr double tolerance_mm = 0.01;

//! X, Y, Z at 100 mm/s, 500 mm/s² and 5,000 mm/s³ (the planner benchmarks' low jerk).
MachineConfig low_jerk_machine() {
    MachineConfig m = plan_test::test_machine(ProfileKind::scurve);
    for (AxisConfig& a : m.axes) {
        if (a.kind != AxisKind::linear) continue;
        a.max_velocity = 100;
        a.max_acceleration = 500;
        a.max_jerk = 5000;
    }
    return m;
}

//! The circle r 20 around (20, 0) from the origin as 2,000 chords with 4 decimals, G64 P0.01
//! (bench/planner_programs/circle_2000.ngc).
std::vector<Move> cam_circle() {
    plan_test::MoveBuilder b;
    constexpr double r = 20;
    for (int k = 1; k <= 2000; ++k) {
        const double angle = 2 * std::numbers::pi * k / 2000;
        AxisVector to;
        to[0] = std::round((r - r * std::cos(angle)) * 1e4) / 1e4;
        to[1] = std::round(r * std::sin(angle) * 1e4) / 1e4;
        b.line(to, feed_mm_min, PathControl{false, tolerance_mm});
    }
    return b.moves;
}

double distance_to_lines(const AxisVector& p, const std::vector<Move>& lines) {
    double best = 1e300;
    for (const Move& m : lines) {
        const Line& l = std::get<Line>(m.what);
        best = std::min(best, plan_test::distance_to_chord(p, l.from, l.to));
    }
    return best;
}

std::vector<const TrajectoryPiece*> motions(const PlanResult& r) {
    std::vector<const TrajectoryPiece*> out;
    for (const TrajectoryPiece& p : r.trajectory.pieces) {
        if (p.kind == PieceKind::motion && p.segment.length > 0) out.push_back(&p);
    }
    return out;
}

TEST(ChainEnds, ACamCircleFromRestTurnsFromItsFirstPointToItsLast) {
    const std::vector<Move> moves = cam_circle();
    const MachineConfig m = low_jerk_machine();
    const PlanResult r = plan_moves(moves, m);
    ASSERT_TRUE(r.diagnostics.empty());
    const auto pieces = motions(r);
    ASSERT_GE(pieces.size(), 2u);
    const TrajectoryPiece& first = *pieces.front();
    const TrajectoryPiece& last = *pieces.back();
    // Before, the first piece was the first half of the written line (curvature 0), and the
    // transition after it ramped the curvature to the circle's 1/20 over 0.31 mm: its third
    // derivative held it to 10.7 mm/s at this jerk.
    for (const TrajectoryPiece* piece : {&first, &last}) {
        EXPECT_EQ(piece->segment.shape, SegmentShape::quintic);
        const double s = piece == &first ? 0.0 : piece->segment.length;
        const PathPoint at = point_at(piece->segment, s);
        EXPECT_NEAR(std::hypot(at.d2[0], at.d2[1]), 1.0 / 20, 0.005) << (piece == &first ? "first" : "last");
        const ProfileLimits limits = segment_limits(piece->segment, m, feed_mm_min / 60, ProfileKind::scurve);
        EXPECT_GT(limits.max_velocity, 0.99 * feed_mm_min / 60) << (piece == &first ? "first" : "last");
        for (int k = 0; k <= 32; ++k) {
            const AxisVector p = position_at(piece->segment, piece->segment.length * k / 32);
            EXPECT_LE(distance_to_lines(p, moves), tolerance_mm) << k;
        }
    }
    const AxisVector start = position_at(first.segment, 0);
    const AxisVector end = position_at(last.segment, last.segment.length);
    const Line& written_last = std::get<Line>(moves.back().what);
    for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_NEAR(start[i], 0.0, 1e-12);
        EXPECT_NEAR(end[i], written_last.to[i], 1e-9);
    }
}

TEST(ChainEnds, LongLinesFromRestStayAsWritten) {
    // A line longer than the next one is a part's edge, not the start of a chain: it leaves its
    // start point as written, straight.
    plan_test::MoveBuilder b;
    b.line(AxisVector{10, 0, 0}, feed_mm_min, PathControl{false, tolerance_mm});
    b.line(AxisVector{10.5, 0.01, 0}, feed_mm_min, PathControl{false, tolerance_mm});
    b.line(AxisVector{11, 0.03, 0}, feed_mm_min, PathControl{false, tolerance_mm});
    const PlanResult r = plan_moves(b.moves, low_jerk_machine());
    ASSERT_TRUE(r.diagnostics.empty());
    const auto pieces = motions(r);
    ASSERT_FALSE(pieces.empty());
    EXPECT_EQ(pieces.front()->segment.shape, SegmentShape::line);
    const AxisVector start = position_at(pieces.front()->segment, 0);
    for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(start[i], 0.0);
}

}  // namespace
}  // namespace nckit
