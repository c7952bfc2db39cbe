// CamFollower, the servo-tick cam the HAL component runs: exact cam values at encoder counts, the
// index and Z rules, no allocation in a tick, and the piston's feedforward error in a closed
// loop against the simulation's.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "nckit/process/piston/piston_job.hpp"
#include "nckit/drive/servo_model.hpp"
#include "nckit/process/fts/cam_follower.hpp"
#include "nckit/process/piston/piston.hpp"

namespace {
std::atomic<long> allocations{0};
}  // namespace

// Every allocation of this test program is counted, so a tick that allocates shows.
void* operator new(std::size_t size) {
    allocations.fetch_add(1, std::memory_order_relaxed);
    if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
    throw std::bad_alloc();
}
void operator delete(void* p) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
    std::free(p);
}

namespace nckit {
namespace {

constexpr int counts = 360;

struct Piston {
    cam::PistonJob job;
    cam::CamTable table;
    StrokeReference reference;
};

Piston example() {
    Result<cam::PistonJob> job =
        cam::load_piston_job(std::string(NCKIT_SOURCE_DIR) + "/examples/linuxcnc/piston_lathe/piston.toml");
    EXPECT_TRUE(job.ok());
    cam::CamTable table = cam::build_cam_table(*job);
    StrokeReference reference(table, stroke_reference_points(table));
    return {std::move(job).value(), std::move(table), std::move(reference)};
}

TEST(CamFollower, CamAtEveryCountBothWaysAndNoAllocation) {
    const Piston p = example();
    CamFollower follower(p.table, &p.reference, counts, 1.0 / 15000);
    CamFollowerSettings settings;
    settings.feedforward = true;
    settings.learning = true;
    CamFollowerInput in;
    CamFollowerOutput out;
    const long before = allocations.load();
    std::int32_t c = 0;
    for (int tick = 0; tick < 5 * counts; ++tick) {
        c += tick < 3 * counts ? 1 : -1;  // three turns forward, two back
        in.counts = c;
        in.index = ((c % counts) + counts) % counts == 0;
        in.z_mm = 25.0 + 0.001 * tick;
        in.feedback_mm = out.command_mm;
        follower.step(in, settings, out);
        const int k = ((c % counts) + counts) % counts;
        ASSERT_EQ(out.count_in_turn, k);
        ASSERT_EQ(out.cam_mm, p.table(360.0 * k / counts, in.z_mm));
        ASSERT_FALSE(out.z_fault || out.index_fault || out.input_fault || out.settings_fault);
    }
    EXPECT_EQ(allocations.load(), before) << "a tick allocated";
}

TEST(CamFollower, RevolutionInputReadsTheCamAtTheFractionOfTheTurn) {
    const Piston p = example();
    CamFollower follower(p.table, &p.reference, counts, 1.0 / 15000);
    CamFollowerSettings settings;
    settings.feedforward = true;
    CamFollowerInput in;
    in.use_counts = false;
    in.z_mm = 12.5;
    CamFollowerOutput out;
    for (int tick = 0; tick < 2000; ++tick) {
        in.revolutions = -1.3 + 0.0027 * tick;  // through zero, both signs
        follower.step(in, settings, out);
        const double turns = in.revolutions - std::floor(in.revolutions);
        ASSERT_NEAR(out.angle_deg, 360.0 * turns, 1e-9);
        ASSERT_NEAR(out.cam_mm, p.table(360.0 * turns, 12.5), 1e-12);
        ASSERT_FALSE(out.input_fault || out.z_fault);
    }
    in.revolutions = std::nan("");
    follower.step(in, settings, out);
    EXPECT_TRUE(out.input_fault);
    EXPECT_TRUE(std::isfinite(out.command_mm));
}

TEST(CamFollower, IndexAtAWrongCountIsIgnoredAndLatched) {
    const Piston p = example();
    CamFollower follower(p.table, &p.reference, counts, 1.0 / 15000);
    CamFollowerSettings settings;
    CamFollowerInput in;
    CamFollowerOutput out;
    for (std::int32_t c = 0; c < 3 * counts; ++c) {
        in.counts = c;
        // One index 100 counts off, and the third turn's one count late (within tolerance).
        in.index = (c % counts == 0 && c != 2 * counts) || c == counts + 100 || c == 2 * counts + 1;
        follower.step(in, settings, out);
        EXPECT_EQ(out.index_fault, c >= counts + 100) << c;
        // The near one (count 1) re-synchronises: the turn starts one count late from there.
        EXPECT_EQ(out.count_in_turn, c > 2 * counts ? (c - 1) % counts : c % counts) << c;
    }
    in.reset_faults = true;
    follower.step(in, settings, out);
    EXPECT_FALSE(out.index_fault);
}

TEST(CamFollower, ZOutsideTheTableHoldsTheEdgeAndFaults) {
    const Piston p = example();
    CamFollower follower(p.table, &p.reference, counts, 1.0 / 15000);
    CamFollowerSettings settings;
    CamFollowerInput in;
    CamFollowerOutput out;
    for (const double z : {-10.0, 0.0, 50.0, 75.0, std::nan("")}) {
        in.z_mm = z;
        in.counts += 7;
        follower.step(in, settings, out);
        const double held = std::isnan(z) ? 50.0 : std::clamp(z, 0.0, 50.0);  // NaN holds the last Z
        EXPECT_EQ(out.cam_mm, p.table(360.0 * static_cast<double>(out.count_in_turn) / counts, held)) << z;
        EXPECT_EQ(out.z_fault, z < 0.0 || z > 50.0 || std::isnan(z)) << z;
        EXPECT_TRUE(std::isfinite(out.command_mm));
    }
}

// The piston cut in a closed loop of CamFollower and the true axis at one count per tick: the
// feedforward's profile error is the simulation's (same job, same model error, same DAC).
TEST(CamFollower, FeedforwardErrorIsTheSimulations) {
    const Piston p = example();
    const Result<PistonSimulation> simulated = simulate_piston(p.job);
    ASSERT_TRUE(simulated.ok());
    const double period_s = 60.0 / (p.job.rpm * counts);
    CamFollower follower(p.table, &p.reference, counts, period_s);
    CamFollowerSettings settings;
    settings.feedforward = true;
    settings.model_gain = 1.1;
    settings.model_natural_frequency_hz = 135.0 * 1.1;
    settings.model_damping = 0.3 * 1.1;
    settings.dac_bits = 16;
    drive::ServoModel axis(drive::ServoParameters::from_natural_frequency(1.0, 135.0, 0.3), period_s);
    CamFollowerInput in;
    CamFollowerOutput out;
    double low = 1e9, high = -1e9;
    const int air = 20 * counts;
    const int cut = 500 * counts;
    for (int tick = 0; tick <= air + cut; ++tick) {
        in.counts = tick;
        in.index = tick % counts == 0;
        in.z_mm = tick < air ? 0.0 : 0.1 * (tick - air) / counts;
        in.feedback_mm = axis.state().position;
        follower.step(in, settings, out);
        if (tick >= air) {
            low = std::min(low, out.error_mm);
            high = std::max(high, out.error_mm);
        }
        axis.step(out.command_mm);
    }
    const double pv_um = (high - low) * 1e3;
    const double expected_um = simulated->fts.feedforward.pv_um;
    EXPECT_NEAR(pv_um, expected_um, 0.05 * expected_um);
}

}  // namespace
}  // namespace nckit
