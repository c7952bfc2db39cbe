// Following error of servo axes: the steady lag of a ramp (2 zeta T v for gain 1, plus half a
// period of hold; exactly the discrete steady state), a held setpoint under a gain below 1, and random
// programs against a plain loop over Trajectory::sample and ServoModel.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "nckit/drive/servo_follow.hpp"
#include "nckit/plan/planner.hpp"

namespace nckit {
namespace {

using drive::FollowingError;
using drive::ServoFollower;
using drive::ServoFollowReport;
using drive::ServoSample;

MachineConfig servo_mill(double natural_frequency_hz, double damping, double gain, double period_s) {
    MachineConfig machine = default_mill();
    machine.servo_period_s = period_s;
    for (AxisConfig& axis : machine.axes) axis.servo = AxisServoConfig{natural_frequency_hz, damping, gain};
    return machine;
}

// X moving at v from 0 for duration_s: a pure ramp (one cruise phase).
Trajectory ramp(double v_mm_s, double duration_s) {
    AxisVector to;
    to[Axis::X] = v_mm_s * duration_s;
    TrajectoryPiece piece;
    piece.segment = make_line(AxisVector{}, to);
    piece.profile.start_velocity = v_mm_s;
    piece.profile.end_velocity = v_mm_s;
    piece.profile.distance = v_mm_s * duration_s;
    piece.profile.phases[0] = ProfilePhase{duration_s, 0.0, 0.0};
    piece.profile.phase_count = 1;
    piece.duration_s = duration_s;
    Trajectory trajectory;
    trajectory.pieces.push_back(piece);
    return trajectory;
}

TEST(ServoFollow, RampLagIsTwoZetaTVForGainOne) {
    const double v = 100.0;  // mm/s
    for (const double damping : {0.5, 0.7, 1.0, 2.0}) {
        for (const double period_s : {1e-3, 1e-4, 1e-5}) {
            const MachineConfig machine = servo_mill(20.0, damping, 1.0, period_s);
            const double T = 1.0 / (2 * std::numbers::pi * 20.0);
            std::vector<ServoSample> x;
            const ServoFollowReport report = drive::follow_trajectory(ramp(v, 1.0), machine, [&](const ServoSample& s) {
                if (s.axis == Axis::X) x.push_back(s);
            });
            ASSERT_EQ(report.axes.size(), 3U);
            // The discrete steady state of a held ramp: y_n = v n h - E, and a velocity w at the
            // samples (not v: inside a period the setpoint stands still). From
            // x_{n+1} - (u_n, 0) = Phi (x_n - (u_n, 0)): E = v h (1 - Phi11) / det(I - Phi).
            const drive::ServoModel model(drive::servo_parameters(*machine.axes[0].servo), period_s);
            const auto& phi = model.transition();
            const double steady =
                v * period_s * (1 - phi[1][1]) / ((1 - phi[0][0]) * (1 - phi[1][1]) - phi[0][1] * phi[1][0]);
            // The analytic lag of the continuous loop, 2 zeta T v, plus half a period of hold.
            EXPECT_NEAR(steady, 2 * damping * T * v + v * period_s / 2, 0.01 * v * period_s) << damping;
            const ServoSample& last = x.back();
            EXPECT_NEAR(last.following_error_mm, steady, 1e-9 * steady);
            EXPECT_NEAR(last.following_error_mm, 2 * damping * T * v, 0.51 * v * period_s);
            EXPECT_NEAR(x[x.size() / 2].following_error_mm, steady, 1e-7 * steady);
            // Critically damped and over: the lag grows to its steady value without overshoot.
            if (damping >= 1.0) {
                EXPECT_NEAR(report.axes[0].max_following_error_mm, steady, 1e-9 * steady);
            } else {
                EXPECT_GT(report.axes[0].max_following_error_mm, steady);
            }
            // Y and Z stand still at 0: no error at all.
            EXPECT_EQ(report.axes[1].max_following_error_mm, 0.0);
            EXPECT_EQ(report.axes[2].rms_following_error_mm, 0.0);
        }
    }
}

TEST(ServoFollow, HeldSetpointUnderAGainBelowOneLeavesTheGainError) {
    MachineConfig machine = servo_mill(30.0, 0.8, 0.98, 1e-3);
    machine.axes[1].servo.reset();  // Y is a stepper axis: not reported
    AxisVector at;
    at[Axis::X] = 10.0;
    at[Axis::Z] = -5.0;
    TrajectoryPiece dwell;
    dwell.kind = PieceKind::dwell;
    dwell.segment = make_line(at, at);
    dwell.duration_s = 0.5;
    Trajectory trajectory;
    trajectory.pieces.push_back(dwell);
    const ServoFollowReport report = drive::follow_trajectory(trajectory, machine);
    ASSERT_EQ(report.axes.size(), 2U);
    EXPECT_EQ(report.axes[0].axis, Axis::X);
    EXPECT_EQ(report.axes[1].axis, Axis::Z);
    EXPECT_EQ(report.samples, 501);  // t = 0, 1 ms, ..., 0.5 s
    EXPECT_DOUBLE_EQ(report.duration_s, 0.5);
    EXPECT_NEAR(report.axes[0].max_following_error_mm, 10.0 * 0.02, 1e-12);
    EXPECT_NEAR(report.axes[0].rms_following_error_mm, 10.0 * 0.02, 1e-12);
    EXPECT_NEAR(report.axes[1].max_following_error_mm, 5.0 * 0.02, 1e-12);
    EXPECT_EQ(report.axes[0].t_max_s, 0.0);
}

TEST(ServoFollow, MachineWithoutServoAxesHasNothingToFollow) {
    EXPECT_FALSE(ServoFollower(default_mill()).has_servo_axes());
    EXPECT_TRUE(ServoFollower(servo_mill(10, 1, 1, 1e-3)).has_servo_axes());
}

// Random programs: the follower's samples are exactly those of a plain loop over
// Trajectory::sample(n h) and one ServoModel per axis, and its statistics are theirs.
TEST(ServoFollowProperty, EqualsAPlainLoopOnRandomPrograms) {
    std::mt19937_64 rng(31);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int run = 0; run < 40; ++run) {
        const double period_s = run % 2 == 0 ? 1e-3 : 2.5e-4 * (1 + unit(rng));
        const MachineConfig machine =
            servo_mill(5 + 60 * unit(rng), 0.2 + 1.5 * unit(rng), 0.9 + 0.2 * unit(rng), period_s);
        std::vector<Move> moves;
        AxisVector at;
        for (int n = 0; n < 20; ++n) {
            AxisVector to = at;
            for (std::size_t i = 0; i < 3; ++i) to[i] = std::clamp(at[i] + 40 * unit(rng) - 20, -400.0, 400.0);
            Move m;
            PathControl path;
            path.exact_stop = unit(rng) < 0.3;
            m.what = Line{at, to, Feed{FeedMode::per_minute, 500 + 5000 * unit(rng), 0}, false, path};
            moves.push_back(m);
            at = to;
        }
        const PlanResult plan = plan_moves(moves, machine);
        ASSERT_TRUE(plan.diagnostics.empty());
        std::vector<ServoSample> samples;
        const ServoFollowReport report =
            drive::follow_trajectory(plan.trajectory, machine, [&](const ServoSample& s) { samples.push_back(s); });

        const double duration = plan.trajectory.duration_s();
        const auto expected_samples = static_cast<std::int64_t>(std::ceil(duration / period_s - 1e-9)) + 1;
        ASSERT_NEAR(static_cast<double>(report.samples), static_cast<double>(expected_samples), 1.0);
        ASSERT_EQ(samples.size(), static_cast<std::size_t>(report.samples) * 3);
        EXPECT_GE(static_cast<double>(report.samples - 1) * period_s, duration - 1e-9);
        for (std::size_t a = 0; a < 3; ++a) {
            const drive::ServoParameters parameters = drive::servo_parameters(*machine.axes[a].servo);
            const double u0 = plan.trajectory.sample(0).position[a];
            drive::ServoModel model(parameters, period_s, {parameters.gain * u0, 0.0});
            model.reset({parameters.gain * u0, 0.0}, u0);
            double max_abs = 0;
            double t_max = 0;
            double squares = 0;
            for (std::int64_t n = 0; n < report.samples; ++n) {
                const double t = static_cast<double>(n) * period_s;
                const double u = plan.trajectory.sample(std::min(t, duration)).position[a];
                const double e = u - model.state().position;
                const ServoSample& s = samples[static_cast<std::size_t>(n) * 3 + a];
                ASSERT_EQ(s.t_s, t);
                ASSERT_EQ(s.setpoint_mm, u) << "run " << run << " axis " << a << " n " << n;
                ASSERT_EQ(s.actual_mm, model.state().position);
                ASSERT_EQ(s.following_error_mm, e);
                if (std::abs(e) > max_abs) {
                    max_abs = std::abs(e);
                    t_max = t;
                }
                squares += e * e;
                model.step(u);
            }
            const FollowingError& axis = report.axes[a];
            EXPECT_EQ(axis.max_following_error_mm, max_abs);
            EXPECT_EQ(axis.t_max_s, t_max);
            EXPECT_NEAR(axis.rms_following_error_mm, std::sqrt(squares / static_cast<double>(report.samples)),
                        1e-12 * max_abs);
            EXPECT_LE(axis.rms_following_error_mm, axis.max_following_error_mm);
        }
    }
}

}  // namespace
}  // namespace nckit
