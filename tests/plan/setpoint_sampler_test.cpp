// Setpoints at a fixed period: the times are n·T without drift, every time is sampled once
// however the trajectory is cut into pieces, the two end rules stop where they say, and the
// finite differences of the sampled positions are the sampled velocities and accelerations.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "move_builder.hpp"
#include "nckit/plan/planner.hpp"
#include "nckit/plan/setpoint_sampler.hpp"
#include "trajectory_check.hpp"

namespace nckit {
namespace {

using plan_test::MoveBuilder;
using plan_test::xyz;

std::vector<TrajectoryPiece> square_with_arc() {
    MoveBuilder b;
    b.line(xyz(20, 0), 3000);
    b.line(xyz(20, 10), 3000);
    b.arc(xyz(10, 20), xyz(10, 10), ArcDirection::counterclockwise, 2400);
    b.dwell(0.0123);
    b.line(xyz(0, 0, 5), 1800);
    PlanResult r = plan_moves(b.moves, plan_test::test_machine(ProfileKind::scurve));
    EXPECT_TRUE(r.diagnostics.empty());
    return r.trajectory.pieces;
}

std::vector<TrajectorySample> run(const std::vector<TrajectoryPiece>& pieces, double period_s, SamplerEnd end) {
    SetpointSampler sampler(period_s, end);
    std::vector<TrajectorySample> out;
    const auto keep = [&](const TrajectorySample& s) { out.push_back(s); };
    for (const TrajectoryPiece& piece : pieces) sampler.add(piece, keep);
    sampler.finish(keep);
    EXPECT_EQ(sampler.samples(), static_cast<std::int64_t>(out.size()));
    return out;
}

double end_of(const std::vector<TrajectoryPiece>& pieces) {
    return pieces.back().start_time_s + pieces.back().duration_s;
}

TEST(SetpointSampler, TimesAreMultiplesOfThePeriodWithoutGapsOrRepeats) {
    const auto pieces = square_with_arc();
    for (double period_s : {1e-3, 2.5e-4, 7e-3}) {
        const auto samples = run(pieces, period_s, SamplerEnd::within_cycle);
        ASSERT_FALSE(samples.empty());
        for (std::size_t n = 0; n < samples.size(); ++n) {
            ASSERT_EQ(samples[n].t, static_cast<double>(n) * period_s) << n;
        }
    }
}

TEST(SetpointSampler, TheEndRulesStopWhereTheySay) {
    const auto pieces = square_with_arc();
    const double end = end_of(pieces);
    const double period_s = 1e-3;
    const auto trace = run(pieces, period_s, SamplerEnd::within_cycle);
    EXPECT_LE(trace.back().t, end + 1e-12);
    EXPECT_GT(trace.back().t + period_s, end + 1e-12);  // the next one would be past the cycle
    const auto servo = run(pieces, period_s, SamplerEnd::through_first_after_end);
    EXPECT_GE(servo.back().t, end);
    EXPECT_LT(servo[servo.size() - 2].t, end);  // the one before is still inside
    // Past the end the setpoint is held at the end position, at rest.
    const TrajectorySample at_end = sample(pieces.back(), end);
    for (std::size_t i = 0; i < axis_count; ++i) {
        EXPECT_EQ(servo.back().position[i], at_end.position[i]);
    }
    // No pieces: no samples.
    EXPECT_TRUE(run({}, period_s, SamplerEnd::through_first_after_end).empty());
}

TEST(SetpointSampler, HowPiecesArriveDoesNotChangeTheSamples) {
    // The same trajectory sampled as a whole and with each piece given separately to a fresh
    // sampler continuing from the same index gives the same rows: add() is a pure function
    // of the piece and the sample times.
    const auto pieces = square_with_arc();
    const auto all = run(pieces, 1e-3, SamplerEnd::within_cycle);
    std::vector<TrajectorySample> by_hand;
    for (std::int64_t n = 0; static_cast<double>(n) * 1e-3 <= end_of(pieces) + 1e-12; ++n) {
        const double t = static_cast<double>(n) * 1e-3;
        const TrajectoryPiece* holder = &pieces.back();
        for (const TrajectoryPiece& p : pieces) {
            if (t >= p.start_time_s && t < p.start_time_s + p.duration_s) {
                holder = &p;
                break;
            }
        }
        by_hand.push_back(sample(*holder, t));
    }
    ASSERT_EQ(all.size(), by_hand.size());
    for (std::size_t n = 0; n < all.size(); ++n) {
        for (std::size_t i = 0; i < axis_count; ++i) ASSERT_EQ(all[n].position[i], by_hand[n].position[i]) << n;
    }
}

// Finite differences: (q[n+1] − q[n−1]) / 2T is the velocity at n to O(T² j), and
// (q[n+1] − 2q[n] + q[n−1]) / T² the acceleration to O(T² snap); jerk is bounded, so the
// bounds below hold everywhere except that a jerk step inside the window adds O(T·j).
TEST(SetpointSampler, FiniteDifferencesOfPositionsAreTheSampledDerivatives) {
    const auto pieces = square_with_arc();
    const MachineConfig machine = plan_test::test_machine(ProfileKind::scurve);
    double max_jerk = 0;
    for (const AxisConfig& a : machine.axes) max_jerk = std::max(max_jerk, a.max_jerk);
    const double period_s = 1e-4;
    const auto s = run(pieces, period_s, SamplerEnd::within_cycle);
    ASSERT_GT(s.size(), 100U);
    // Curvature turns v² into acceleration and v³ into jerk too: allow a generous multiple.
    const double jerk_bound = 50.0 * max_jerk;
    for (std::size_t n = 1; n + 1 < s.size(); ++n) {
        for (std::size_t i = 0; i < 3; ++i) {
            const double v_fd = (s[n + 1].position[i] - s[n - 1].position[i]) / (2 * period_s);
            ASSERT_NEAR(v_fd, s[n].velocity[i], jerk_bound * period_s * period_s + 1e-9) << "n " << n << " axis " << i;
            const double a_fd =
                (s[n + 1].position[i] - 2 * s[n].position[i] + s[n - 1].position[i]) / (period_s * period_s);
            ASSERT_NEAR(a_fd, s[n].acceleration[i], jerk_bound * period_s + 1e-4) << "n " << n << " axis " << i;
        }
    }
}

TEST(SetpointSampler, APeriodThatIsNotPositiveIsAProgrammingError) {
    EXPECT_THROW(SetpointSampler(0.0, SamplerEnd::within_cycle), std::invalid_argument);
    EXPECT_THROW(SetpointSampler(-1e-3, SamplerEnd::within_cycle), std::invalid_argument);
}

}  // namespace
}  // namespace nckit
