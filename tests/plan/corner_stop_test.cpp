// Sharp corners under a jerk limit: stopped at where the transition would be slower to cross
// than a stop (corner_stop.hpp). Checked against the planner's own plans both ways.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <variant>
#include <vector>

#include "move_builder.hpp"
#include "nckit/plan/planner.hpp"
#include "trajectory_check.hpp"

namespace nckit {
namespace {

using plan_test::xyz;

double cycle_s(const std::vector<Move>& moves, const MachineConfig& m, bool stop_sharp_corners) {
    PlannerOptions options;
    options.stop_sharp_corners = stop_sharp_corners;
    const PlanResult r = plan_moves(moves, m, options);
    EXPECT_TRUE(r.diagnostics.empty());
    const TrajectoryPiece& last = r.trajectory.pieces.back();
    return last.start_time_s + last.duration_s;
}

//! A corner of `angle_rad` between lines of the given lengths, in the XY plane, under G64 P.
std::vector<Move> corner(double angle_rad, double first_mm, double second_mm, double tolerance_mm, double feed) {
    plan_test::MoveBuilder b;
    const PathControl g64{false, tolerance_mm};
    b.line(xyz(first_mm, 0), feed, g64);
    b.line(xyz(first_mm + second_mm * std::cos(angle_rad), second_mm * std::sin(angle_rad)), feed, g64);
    return b.moves;
}

// A 90° corner at P0.01 between 1 mm lines (a raster's step between rows): the transition is
// held to a few mm/s and the stop is faster; at P1 between long lines passing is faster.
TEST(CornerStop, TightCornersStopAndWideOnesPass) {
    const MachineConfig m = plan_test::test_machine();
    const std::vector<Move> tight = corner(std::numbers::pi / 2, 1.0, 1.0, 0.01, 3000);
    EXPECT_LT(cycle_s(tight, m, true), cycle_s(tight, m, false));
    const PlanResult stopped = plan_moves(tight, m);
    EXPECT_EQ(stopped.trajectory.pieces.size(), 2u);  // two lines, no transition
    const std::vector<Move> wide = corner(std::numbers::pi / 2, 50.0, 50.0, 1.0, 3000);
    EXPECT_DOUBLE_EQ(cycle_s(wide, m, true), cycle_s(wide, m, false));
    EXPECT_EQ(plan_moves(wide, m).trajectory.pieces.size(), 3u);
}

// Property over random corners, tolerances, feeds, lengths and jerks: a corner the rule stops at
// is never slower than the same corner passed through its transition (the rule decides from a
// model of the two speed changes, not by planning both; 5,000 such corners were tried once), and
// the plan keeps every limit.
TEST(CornerStop, RandomCornersChooseTheFasterWay) {
    std::mt19937 random(20261126);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int stops = 0;
    int passes = 0;
    for (int trial = 0; trial < 400; ++trial) {
        MachineConfig m = plan_test::test_machine();
        const double jerk = unit(random) < 0.5 ? 5000.0 : 50000.0;
        for (AxisConfig& axis : m.axes) {
            if (axis.kind == AxisKind::linear) axis.max_jerk = jerk;
        }
        const double angle = (0.2 + 2.7 * unit(random));
        const double tolerance = std::pow(10.0, -3.0 + 2.0 * unit(random));
        const double feed = 600 + 5400 * unit(random);
        const double first = std::pow(10.0, -0.5 + 2.0 * unit(random));
        const double second = std::pow(10.0, -0.5 + 2.0 * unit(random));
        const std::vector<Move> moves = corner(angle, first, second, tolerance, feed);
        const double chosen = cycle_s(moves, m, true);
        const double passing = cycle_s(moves, m, false);
        SCOPED_TRACE(testing::Message() << "trial " << trial << ": angle " << angle << " rad, P " << tolerance << ", F "
                                        << feed << ", " << first << " + " << second << " mm, j " << jerk);
        EXPECT_LE(chosen, passing * (1 + 1e-9));
        (chosen < passing ? stops : passes) += 1;
        const PlanResult r = plan_moves(moves, m);
        const AxisVector end = std::get<Line>(moves.back().what).to;
        plan_test::check_trajectory(r.trajectory.pieces, m, ProfileKind::scurve, end,
                                    [&](const TrajectoryPiece&) { return feed / 60; });
    }
    // Both ways occur over this range.
    EXPECT_GT(stops, 10);
    EXPECT_GT(passes, 10);
}

}  // namespace
}  // namespace nckit
