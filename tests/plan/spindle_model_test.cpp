// The spindle model against direct integration, and G32/G33 index waits in the planner.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "move_builder.hpp"
#include "nckit/plan/planner.hpp"
#include "nckit/plan/spindle_model.hpp"
#include "nckit/plan/sync_report.hpp"
#include "trajectory_check.hpp"

namespace nckit {
namespace {

SpindleConfig rippled(double fraction, int per_turn = 1, double phase_deg = 0) {
    SpindleConfig config;
    config.max_rpm = 10000;
    config.encoder_counts = 4096;
    config.ripple_fraction = fraction;
    config.ripple_per_turn = per_turn;
    config.ripple_phase_deg = phase_deg;
    return config;
}

//! dθ/dt = 6·rpm·(1 + r sin(kθ + φ)) integrated by RK4 with a small step (deg, s).
double integrate_angle_deg(const SpindleConfig& c, double rpm, double t_s) {
    const int steps = 100000;
    const double h = t_s / steps;
    auto rate = [&](double theta) {
        return 6.0 * rpm *
               (1.0 + c.ripple_fraction *
                          std::sin((c.ripple_per_turn * theta + c.ripple_phase_deg) * std::numbers::pi / 180.0));
    };
    double theta = 0;
    for (int i = 0; i < steps; ++i) {
        const double k1 = rate(theta);
        const double k2 = rate(theta + h / 2 * k1);
        const double k3 = rate(theta + h / 2 * k2);
        const double k4 = rate(theta + h * k3);
        theta += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
    return theta;
}

TEST(SpindleModel, WithoutRippleTheAngleIsSpeedTimesTime) {
    SpindleModel spindle(rippled(0));
    spindle.set_speed(0.5, 600);  // 3600 deg/s from t = 0.5 s
    EXPECT_DOUBLE_EQ(spindle.angle_deg(0.25), 0.0);
    EXPECT_NEAR(spindle.angle_deg(0.6), 360.0, 1e-9);
    EXPECT_NEAR(*spindle.next_index_s(0.61), 0.7, 1e-12);
    EXPECT_NEAR(*spindle.next_index_s(0.7), 0.7, 1e-12);  // on the index: the pulse is now
    EXPECT_EQ(spindle.count_at(0.55), 2048);              // half a turn of 4096 counts
    spindle.set_speed(1.0, 0);
    EXPECT_FALSE(spindle.next_index_s(1.2).has_value());
    EXPECT_NEAR(spindle.angle_deg(2.0), 1800.0, 1e-9);
}

TEST(SpindleModel, RippledAngleMatchesDirectIntegration) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> fraction(0.0, 0.3);
    std::uniform_real_distribution<double> phase(0.0, 360.0);
    std::uniform_real_distribution<double> time(0.01, 3.0);
    for (int trial = 0; trial < 40; ++trial) {
        const SpindleConfig config = rippled(fraction(random), 1 + trial % 4, phase(random));
        const double rpm = trial % 2 == 0 ? 750.0 : -1234.0;
        SpindleModel spindle(config);
        spindle.set_speed(0.0, rpm);
        const double t = time(random);
        SCOPED_TRACE(trial);
        // M4 turns backwards through the same ripple: integrate with the signed rate.
        EXPECT_NEAR(spindle.angle_deg(t), integrate_angle_deg(config, rpm, t), 1e-7);
    }
}

TEST(SpindleModel, RippleSlowsATurnAndIndexPulsesComeOncePerTurn) {
    const SpindleConfig config = rippled(0.2, 1, 30);
    SpindleModel spindle(config);
    spindle.set_speed(0.0, 600);
    const double turn_s = 0.1 / std::sqrt(1 - 0.04);
    double t = *spindle.next_index_s(1e-6);
    EXPECT_NEAR(t, turn_s, 1e-12);
    for (int i = 2; i < 50; ++i) {
        t = *spindle.next_index_s(t + 1e-9);
        EXPECT_NEAR(t, i * turn_s, 1e-10);
        EXPECT_NEAR(std::remainder(spindle.angle_deg(t), 360.0), 0.0, 1e-8);
    }
    EXPECT_NEAR(spindle.mean_rpm(), 600 * std::sqrt(1 - 0.04), 1e-12);
}

// A start angle past the index (G32/G92 Q): without ripple, 600 rpm turns 3.6 deg per ms, so
// 90 deg past the index is 25 ms into each 100 ms turn.
TEST(SpindleModel, StartAnglePastTheIndex) {
    SpindleModel spindle(rippled(0));
    spindle.set_speed(0.0, 600);
    EXPECT_NEAR(*spindle.next_index_s(0.01, 90), 0.025, 1e-12);
    EXPECT_NEAR(*spindle.next_index_s(0.025, 90), 0.025, 1e-12);  // there now
    EXPECT_NEAR(*spindle.next_index_s(0.03, 90), 0.125, 1e-12);
    EXPECT_NEAR(*spindle.next_index_s(0.03, 0), 0.1, 1e-12);
    SpindleModel backwards(rippled(0));
    backwards.set_speed(0.0, -600);  // M4: 90 deg past the index is the angle -90, -450, ...
    EXPECT_NEAR(*backwards.next_index_s(0.03, 90), 0.125, 1e-12);
    EXPECT_NEAR(backwards.angle_deg(0.125), -450.0, 1e-9);
}

// Property: with ripple, the spindle stands at the asked angle (in its turning sense) at the
// time returned, and no earlier time after the asked one has it there (within one turn).
TEST(SpindleModel, StartAngleWithRippleLandsOnTheAngle) {
    std::mt19937 random(11);
    std::uniform_real_distribution<double> angle(0.0, 360.0);
    std::uniform_real_distribution<double> time(0.0, 2.0);
    for (int trial = 0; trial < 60; ++trial) {
        SpindleModel spindle(rippled(0.2, 1 + trial % 3, 17.0 * trial));
        const double rpm = trial % 2 == 0 ? 700.0 : -900.0;
        spindle.set_speed(0.0, rpm);
        const double sense = rpm > 0 ? 1.0 : -1.0;
        const double want = angle(random);
        const double from = time(random);
        const double t = *spindle.next_index_s(from, want);
        SCOPED_TRACE(trial);
        EXPECT_NEAR(std::remainder(sense * spindle.angle_deg(t) - want, 360.0), 0.0, 1e-7);
        EXPECT_GE(t, from);
        EXPECT_LE(sense * (spindle.angle_deg(t) - spindle.angle_deg(from)), 360.0 + 1e-7);
    }
}

MachineConfig lathe_with(const SpindleConfig& spindle) {
    MachineConfig m = plan_test::test_machine(ProfileKind::scurve);
    m.spindle = spindle;
    return m;
}

// Three passes of one thread, started at different times: every pass leaves the index.
TEST(SpindleSync, EveryThreadPassStartsOnTheIndex) {
    for (double ripple : {0.0, 0.05}) {
        const MachineConfig m = lathe_with(rippled(ripple, 2, 45));
        plan_test::MoveBuilder b;
        b.spindle(3, 600);
        for (int pass = 0; pass < 3; ++pass) {
            b.rapid(plan_test::xyz(20 - pass * 0.3, 0, 5));
            b.thread(plan_test::xyz(20 - pass * 0.3, 0, -20), 1.5);
            b.rapid(plan_test::xyz(25, 0, -20 + pass * 0.1));  // passes differ: different waits
            b.rapid(plan_test::xyz(25, 0, 5));
        }
        PlanResult r = plan_moves(b.moves, m);
        ASSERT_TRUE(r.diagnostics.empty());
        SyncReport report(m.spindle);
        int waits = 0;
        for (const TrajectoryPiece& p : r.trajectory.pieces) {
            report.add(p);
            waits += p.waits_for_index ? 1 : 0;
        }
        EXPECT_EQ(waits, 3);
        ASSERT_EQ(report.count(), 3);
        EXPECT_LT(report.max_index_error_deg(), 1e-6);
        if (ripple == 0.0) {
            // Independently: the spindle started at t = 0 at 3600 deg/s.
            for (const SyncStart& s : report.starts()) {
                EXPECT_NEAR(std::remainder(s.t_s * 3600.0, 360.0), 0.0, 1e-6);
                EXPECT_GT(s.wait_s, 0.0);
                EXPECT_LT(s.wait_s, 0.1);
            }
        }
        // The thread moves the lead per turn at the mean speed: 1.5 mm × 600 rpm = 15 mm/s.
        for (const TrajectoryPiece& p : r.trajectory.pieces) {
            if (p.kind != PieceKind::motion || p.waits_for_index) continue;
            if (p.segment.rate[index(Axis::Z)] >= 0 || p.segment.rate[index(Axis::X)] != 0) continue;
            const double mid_s = p.start_time_s + p.duration_s / 2;
            EXPECT_NEAR(sample(p, mid_s).path_velocity, 15.0 * std::sqrt(1 - ripple * ripple), 1e-7);
        }
    }
}

// Chained threads of different leads, short and long, and the rapid out: a thread moves at the
// spindle's speed, so no speed change is planned across its ends together with another move
// (the look-ahead plans runs of several moves as one profile elsewhere). Each thread move's
// last piece ends its profile.
TEST(SpindleSync, ChainedThreadsKeepProfilesOfTheirOwn) {
    const MachineConfig m = lathe_with(rippled(0));
    const std::vector<std::vector<double>> chains = {{5.0, 3.68, 0.2, 2.01, 0.2, 2.81},
                                                     {0.5, 1.55, 0.2, 3.0, 1.0, 3.22},
                                                     {10.0, 2.74, 10.0, 2.18, 5.0, 2.64, 10.0, 1.46, 0.2, 3.73}};
    for (const std::vector<double>& chain : chains) {
        plan_test::MoveBuilder b;
        b.spindle(3, 1000);
        b.rapid(plan_test::xyz(10, 0, 5));
        double z = 5;
        std::vector<std::int64_t> threads;
        for (std::size_t k = 0; k + 1 < chain.size(); k += 2) {
            z -= chain[k];
            threads.push_back(static_cast<std::int64_t>(b.moves.size()));
            b.thread(plan_test::xyz(10, 0, z), chain[k + 1]);
        }
        b.rapid(plan_test::xyz(15, 0, z));
        PlanResult r = plan_moves(b.moves, m);
        ASSERT_TRUE(r.diagnostics.empty());
        const TrajectoryPiece* before = nullptr;
        int thread_ends = 0;
        for (const TrajectoryPiece& p : r.trajectory.pieces) {
            if (p.kind != PieceKind::motion) continue;
            const bool thread_now = std::find(threads.begin(), threads.end(), p.sequence_number) != threads.end();
            if (before != nullptr && before->sequence_number != p.sequence_number) {
                const bool thread_before =
                    std::find(threads.begin(), threads.end(), before->sequence_number) != threads.end();
                if (thread_before || thread_now) {
                    EXPECT_TRUE(before->ends_profile)
                        << "moves " << before->sequence_number << " and " << p.sequence_number << " share a profile";
                    ++thread_ends;
                }
            }
            before = &p;
        }
        EXPECT_GE(thread_ends, static_cast<int>(threads.size()));
    }
}

TEST(SpindleSync, ThreadWithTheSpindleStoppedOrTooFastIsRefused) {
    const MachineConfig m = lathe_with(rippled(0));
    plan_test::MoveBuilder stopped;
    stopped.thread(plan_test::xyz(0, 0, -10), 1.5);
    PlanResult r = plan_moves(stopped.moves, m);
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics[0].code, "sync-spindle-stopped");

    plan_test::MoveBuilder fast;
    fast.spindle(3, 9000);
    fast.thread(plan_test::xyz(0, 0, -10), 10.0);  // 1500 mm/s
    r = plan_moves(fast.moves, m);
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics[0].code, "sync-too-fast");
}

}  // namespace
}  // namespace nckit
