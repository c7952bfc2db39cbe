// The planner on fixed programs: junction rules, a square, a circle of short lines, stops.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "move_builder.hpp"
#include "nckit/plan/planner.hpp"
#include "trajectory_check.hpp"

namespace nckit {
namespace {

using plan_test::MoveBuilder;
using plan_test::xyz;

struct Planned {
    std::vector<TrajectoryPiece> pieces;
    plan_test::CheckStats stats;
};

Planned plan_and_check(const MoveBuilder& b, const MachineConfig& m, PlannerOptions o = {}) {
    const ProfileKind kind = o.profile.value_or(m.profile);
    PlanResult r = plan_moves(b.moves, m, o);
    EXPECT_TRUE(r.diagnostics.empty());
    Planned out;
    out.pieces = std::move(r.trajectory.pieces);
    auto feed_of = [&](const TrajectoryPiece& p) {
        return b.feeds_mm_s[static_cast<std::size_t>(p.sequence_number)] * o.feed_override;
    };
    out.stats = plan_test::check_trajectory(out.pieces, m, kind, b.position, feed_of);
    return out;
}

double duration(const std::vector<TrajectoryPiece>& pieces) {
    return pieces.empty() ? 0 : pieces.back().start_time_s + pieces.back().duration_s;
}

//! Speed ṡ at the end of the motion piece made by move `seq` (the last such piece).
double end_speed_of(const std::vector<TrajectoryPiece>& pieces, std::int64_t seq) {
    double v = -1;
    for (const TrajectoryPiece& p : pieces) {
        if (p.kind == PieceKind::motion && p.sequence_number == seq && !p.blend) {
            v = sample(p, p.start_time_s + p.duration_s).path_velocity;
        }
    }
    return v;
}

TEST(Planner, SquareExactStopTakesTheRestToRestOptimum) {
    for (ProfileKind kind : {ProfileKind::scurve, ProfileKind::trapezoid}) {
        MachineConfig m = plan_test::test_machine(kind);
        MoveBuilder b;
        PathControl stop{true, 0};
        b.line(xyz(100, 0), 3000, stop);
        b.line(xyz(100, 100), 3000, stop);
        b.line(xyz(0, 100), 3000, stop);
        b.line(xyz(0, 0), 3000, stop);
        const Planned p = plan_and_check(b, m);
        ASSERT_EQ(p.pieces.size(), 4U);
        const ProfileLimits lim{50, 500, kind == ProfileKind::scurve ? 50000 : 1e300};
        const double side = plan_profile(100, 0, 0, lim, kind).duration_s();
        EXPECT_NEAR(duration(p.pieces), 4 * side, 1e-8 * side);  // runs plan at limits − 1e-9
        EXPECT_NEAR(p.stats.max_xyz_speed, 50, 1e-7);
    }
}

class PlannerSquare : public ::testing::TestWithParam<double> {};

TEST_P(PlannerSquare, BlendsStayWithinTolerance) {
    MachineConfig m = plan_test::test_machine();
    MoveBuilder b;
    // With 0.05 mm a 90° corner's transition allows only a few mm/s, and crossing it takes
    // longer than that speed saves: the corners are stopped at, exactly (corner_stop.hpp). With
    // 1 mm (R = 2.4 mm) it passes at 24.5 mm/s and saves about 20 ms a corner.
    const double tolerance = GetParam();
    PathControl g64{false, tolerance};
    b.line(xyz(100, 0), 3000, g64);
    b.line(xyz(100, 100), 3000, g64);
    b.line(xyz(0, 100), 3000, g64);
    b.line(xyz(0, 0), 3000, g64);
    const Planned p = plan_and_check(b, m);
    const double side = plan_profile(100, 0, 0, {50, 500, 50000}, ProfileKind::scurve).duration_s();
    if (tolerance >= 1) {
        ASSERT_EQ(p.pieces.size(), 7U);                  // 4 sides, 3 blends
        EXPECT_LT(duration(p.pieces), 4 * side - 0.05);  // 8.376 s vs 8.44 s
    } else {
        ASSERT_EQ(p.pieces.size(), 4U);  // 4 sides, stopped at each corner
        EXPECT_NEAR(duration(p.pieces), 4 * side, 1e-8 * side);
    }
    for (const TrajectoryPiece& piece : p.pieces) {
        if (!piece.blend) continue;
        // Every transition of a 90° corner keeps within the tolerance of the two sides and uses
        // most of it.
        const auto seq = static_cast<std::size_t>(piece.sequence_number);
        const double deviation = plan_test::deviation_from(piece, b.moves[seq], b.moves[seq + 1]);
        EXPECT_LE(deviation, tolerance * (1 + 1e-9));
        EXPECT_GT(deviation, 0.8 * tolerance);
        EXPECT_GT(sample(piece, piece.start_time_s).path_velocity, 0);
    }
}
INSTANTIATE_TEST_SUITE_P(Tolerances, PlannerSquare, ::testing::Values(0.05, 1.0));

TEST(Planner, CircleOfShortLinesReachesTheFeed) {
    MachineConfig m = plan_test::test_machine();
    MoveBuilder b;
    const double r = 10;
    b.position = xyz(r, 0);
    const int n = 2000;
    for (int k = 1; k <= n; ++k) {
        const double t = 2 * std::numbers::pi * k / n;
        b.line(xyz(r * std::cos(t), r * std::sin(t)), 3000);
    }
    const Planned p = plan_and_check(b, m);
    // Blends of radius ~10 mm: 50 mm/s needs v²/r = 250 = a/2, exactly the arc allocation.
    EXPECT_GT(p.stats.max_xyz_speed, 0.999 * 50);
    // Close to the time at full feed: length / feed plus a start and a stop.
    EXPECT_LT(duration(p.pieces), 2 * std::numbers::pi * r / 50 + 0.5);
}

TEST(Planner, TangentLineArcPassesAtSpeedAndCornerStops) {
    for (ProfileKind kind : {ProfileKind::trapezoid, ProfileKind::scurve}) {
        MachineConfig m = plan_test::test_machine(kind);
        MoveBuilder b;
        b.line(xyz(10, 0), 1200);                                               // 0
        b.arc(xyz(20, 10), xyz(10, 10), ArcDirection::counterclockwise, 1200);  // 1 tangent
        b.line(xyz(20, 20), 1200);                                              // 2 tangent
        b.arc(xyz(30, 20), xyz(25, 20), ArcDirection::counterclockwise, 1200);  // 3 reversal
        b.line(xyz(40, 20), 1200, {true, 0});                                   // 4 G9
        b.line(xyz(50, 20), 1200);                                              // 5 reversal next
        b.line(xyz(45, 20), 1200);                                              // 6
        const Planned p = plan_and_check(b, m);
        if (kind == ProfileKind::trapezoid) {
            // The acceleration may step: tangent joins pass at the feed.
            EXPECT_NEAR(end_speed_of(p.pieces, 0), 20, 1e-7);
            EXPECT_NEAR(end_speed_of(p.pieces, 1), 20, 1e-7);
        } else {
            // The curvature jumps: a transition within the default tolerance, nearly at the feed.
            EXPECT_GT(end_speed_of(p.pieces, 0), 15);
            EXPECT_GT(end_speed_of(p.pieces, 1), 15);
        }
        // The line turns back into the arc: a reversal stops.
        EXPECT_EQ(end_speed_of(p.pieces, 2), 0.0);
        EXPECT_EQ(end_speed_of(p.pieces, 4), 0.0);
        EXPECT_EQ(end_speed_of(p.pieces, 5), 0.0);
        int transitions = 0;
        // A transition next to an arc may be planned in pieces: the later ones continue it.
        for (const TrajectoryPiece& piece : p.pieces) transitions += piece.blend && !piece.continues_move ? 1 : 0;
        // Arc 3 meets line 4 at a right angle: rounded in both kinds.
        EXPECT_EQ(transitions, kind == ProfileKind::trapezoid ? 1 : 3);
    }
}

TEST(Planner, ArcSpeedKeepsNormalAccelerationWithinTheLimit) {
    MachineConfig m = plan_test::test_machine();
    MoveBuilder b;
    b.position = xyz(1, 0);
    b.arc(xyz(1, 0), xyz(0, 0), ArcDirection::counterclockwise, 6000);  // full circle r = 1
    const Planned p = plan_and_check(b, m);
    // In pieces, the speed follows the pointwise limit (docs/planner.md, "Speed along an arc
    // (S-curve)"): above the whole-arc speed with half of a for the turning (v²/r <= a/2:
    // sqrt(250) mm/s), below the highest pointwise limit, at 45° where both axes share the
    // turning (v²·cos 45°/r <= a: sqrt(500·√2) mm/s). Where a run holds its speed it may pass
    // sqrt(500), the limit where one axis takes all of a (cruise_raise.hpp). A run of pieces may
    // take higher rates where its pieces allow (run_merge.hpp): it then reaches a lower peak
    // sooner, 18.87 mm/s and 0.396 s (before that 22.28 mm/s and 0.418 s).
    EXPECT_GT(p.stats.max_xyz_speed, 1.15 * std::sqrt(250.0));
    EXPECT_LE(p.stats.max_xyz_speed, std::sqrt(500.0 * std::sqrt(2.0)));
    EXPECT_LT(p.pieces.back().start_time_s + p.pieces.back().duration_s, 0.40);
}

TEST(Planner, WaitingMcodesStopOthersPassAtSpeed) {
    MachineConfig m = plan_test::test_machine();
    MoveBuilder b;
    b.line(xyz(10, 0), 1200);  // 0
    b.mcode(7);                // 1: the machine's exact-stop M-code
    b.line(xyz(20, 0), 1200);  // 2
    b.mcode(3);                // 3: passes at speed
    b.line(xyz(30, 0), 1200);  // 4
    b.mcode(0, true);          // 5: M0 waits
    b.line(xyz(40, 0), 1200);  // 6
    b.dwell(0.5);              // 7
    b.line(xyz(50, 0), 1200);  // 8
    const Planned p = plan_and_check(b, m);
    EXPECT_EQ(end_speed_of(p.pieces, 0), 0.0);
    EXPECT_NEAR(end_speed_of(p.pieces, 2), 20, 1e-7);
    EXPECT_EQ(end_speed_of(p.pieces, 4), 0.0);
    EXPECT_EQ(end_speed_of(p.pieces, 6), 0.0);
    int events = 0;
    for (const TrajectoryPiece& piece : p.pieces) {
        if (piece.kind == PieceKind::io) {
            ++events;
            EXPECT_NEAR(start_point(piece.segment)[0],
                        piece.io.number == 3   ? 20
                        : piece.io.number == 7 ? 10
                                               : 30,
                        1e-12);
        }
        if (piece.kind == PieceKind::dwell) {
            EXPECT_DOUBLE_EQ(piece.duration_s, 0.5);
        }
    }
    EXPECT_EQ(events, 3);
}

TEST(Planner, RapidsRunAtTheAxisLimitsInStraightLines) {
    MachineConfig m = plan_test::test_machine();
    MoveBuilder b;
    b.rapid(xyz(200, 0));
    b.rapid(xyz(200, 200, 0, 90));
    const Planned p = plan_and_check(b, m);
    ASSERT_EQ(p.pieces.size(), 2U);
    EXPECT_NEAR(p.stats.max_xyz_speed, 100, 1e-6);
    EXPECT_EQ(sample(p.pieces[0], p.pieces[0].duration_s).path_velocity, 0.0);
}

TEST(Planner, FeedOverrideScalesFeeds) {
    MachineConfig m = plan_test::test_machine();
    MoveBuilder b;
    b.line(xyz(100, 0), 1200);
    PlannerOptions o;
    o.feed_override = 1.5;
    const Planned p = plan_and_check(b, m, o);
    EXPECT_NEAR(p.stats.max_xyz_speed, 30, 1e-7);
}

TEST(Planner, StreamingEmitsFinalPiecesBeforeTheEnd) {
    MachineConfig m = plan_test::test_machine();
    MoveBuilder b;
    // Under a jerk limit the collinear lines are merged 16 to one (chain_smoother.hpp): 20,000
    // of them leave 1,250 segments, five runs of at most a quarter of the window.
    for (int k = 1; k <= 20000; ++k) b.line(xyz(0.01 * k, 0), 3000);
    PlannerOptions o;
    o.window_moves = 1000;
    Planner planner(m, o);
    TrajectoryPiece piece;
    std::size_t popped = 0;
    for (const Move& move : b.moves) {
        planner.push(move);
        while (planner.pop(piece)) ++popped;
    }
    const std::size_t before_finish = popped;
    planner.finish();
    while (planner.pop(piece)) ++popped;
    // Same result as unlimited look-ahead here: the braking needs far fewer than 500 segments.
    const Planned whole = plan_and_check(b, m);
    EXPECT_EQ(popped, whole.pieces.size());
    EXPECT_GE(before_finish, whole.pieces.size() * 3 / 4);  // all but the last run
}

TEST(Planner, HelixOfRadiusZeroRunsAsItsPlunge) {
    // An arc whose centre is its start and end in the plane (LinuxCNC's compensated hole of the
    // tool's diameter): the plunge runs at the feed along Z, the full circle of radius 0 after it
    // makes no motion, and the trajectory's checks (limits, continuity, end state) hold.
    for (ProfileKind kind : {ProfileKind::trapezoid, ProfileKind::scurve}) {
        MachineConfig m = plan_test::test_machine(kind);
        MoveBuilder b;
        b.line(xyz(10, 0, 0), 600);
        b.arc(xyz(10, 0, -2), xyz(10, 0, 0), ArcDirection::counterclockwise, 600);
        b.arc(xyz(10, 0, -2), xyz(10, 0, -2), ArcDirection::counterclockwise, 600);
        b.line(xyz(20, 0, -2), 600);
        const Planned p = plan_and_check(b, m);
        double plunge_s = 0;
        for (const TrajectoryPiece& piece : p.pieces) {
            if (piece.sequence_number == 1) plunge_s += piece.duration_s;
            EXPECT_NE(piece.sequence_number, 2) << "the circle of radius 0 moves nothing";
        }
        EXPECT_GT(plunge_s, 2.0 / 10.0);  // 2 mm at 10 mm/s, with its acceleration
    }
}

TEST(Planner, ReportsMovesWithoutFeed) {
    MachineConfig m = plan_test::test_machine();
    MoveBuilder b;
    b.line(xyz(10, 0), 0);
    PlanResult r = plan_moves(b.moves, m);
    ASSERT_EQ(r.diagnostics.size(), 1U);
    EXPECT_EQ(r.diagnostics[0].code, "no-feed");
}

}  // namespace
}  // namespace nckit

namespace nckit {
namespace {

// Trims of two corners that nearly meet leave no sub-micrometre piece of line to be planned on
// its own: the corner takes it, or leaves a whole micrometre (both kinds).
TEST(Planner, NoSubMicrometreLeftoverBetweenCorners) {
    for (const ProfileKind kind : {ProfileKind::trapezoid, ProfileKind::scurve}) {
        const MachineConfig m = plan_test::test_machine(kind);
        MoveBuilder b;
        const double tolerance = 0.01;
        // A 90° parabola corner trims 4·P/√2 from each line: lines of twice that plus 0.5 µm.
        const double side = 2 * 4 * tolerance / std::sqrt(2.0) + 0.0005;
        for (int k = 1; k <= 20; ++k) {
            const AxisVector to =
                k % 2 ? xyz(b.position[0] + side, b.position[1]) : xyz(b.position[0], b.position[1] + side);
            b.line(to, 3000, PathControl{false, tolerance});
        }
        const Planned planned = plan_and_check(b, m);
        std::size_t lines = 0;
        for (const TrajectoryPiece& p : planned.pieces) {
            if (p.kind != PieceKind::motion || p.blend) continue;
            ++lines;
            EXPECT_GE(p.segment.length, 1e-3 * (1 - 1e-9)) << static_cast<int>(kind);
        }
        // The trapezoid's corners leave a micrometre of each line; transitions may eat them whole.
        if (kind == ProfileKind::trapezoid) {
            EXPECT_GT(lines, 0U);
        }
    }
}

}  // namespace
}  // namespace nckit
