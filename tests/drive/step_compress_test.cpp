// Step compression: every reproduced step within the bound, and real compression on smooth motion.
#include <gtest/gtest.h>

#include <cstdlib>
#include <random>
#include <vector>

#include "nckit/drive/step_compress.hpp"
#include "nckit/drive/step_generator.hpp"
#include "nckit/plan/planner.hpp"

namespace nckit {
namespace {

// Compresses one direction-run and checks every step against its exact time.
std::size_t check_runs(const std::vector<std::int64_t>& times, std::int64_t t_prev, std::int64_t max_error) {
    std::int64_t cursor = t_prev;
    const std::vector<StepRun> runs = compress_steps(times, cursor, max_error);
    std::size_t k = 0;
    std::int64_t t = t_prev;
    for (const StepRun& run : runs) {
        EXPECT_GE(run.count, 1U);
        for (std::int64_t made : expand_run(run, t)) {
            EXPECT_LE(std::llabs(made - times[k]), max_error) << "step " << k;
            ++k;
            t = made;
        }
    }
    EXPECT_EQ(k, times.size());
    EXPECT_EQ(cursor, t);
    return runs.size();
}

TEST(StepCompress, ExactWithZeroError) {
    const std::vector<std::int64_t> times{100, 200, 300, 410, 530, 660, 1000};
    check_runs(times, 0, 0);
}

TEST(StepCompress, ConstantAccelerationIsOneRun) {
    std::vector<std::int64_t> times;
    std::int64_t t = 0;
    std::int64_t interval = 100000;
    for (int k = 0; k < 1000; ++k) {
        t += interval;
        interval += 7;
        times.push_back(t);
    }
    EXPECT_EQ(check_runs(times, 0, 0), 1U);
}

TEST(StepCompress, RandomJitterStaysWithinTheBound) {
    std::mt19937_64 rng(3);
    std::uniform_int_distribution<std::int64_t> jitter(0, 40000);
    std::vector<std::int64_t> times;
    std::int64_t t = 5000;
    for (int k = 0; k < 20000; ++k) {
        t += 20000 + jitter(rng);
        times.push_back(t);
    }
    check_runs(times, 0, 25000);
    check_runs(times, 0, 1000);
}

TEST(StepCompress, PlannedMotionCompressesWithinTheBound) {
    MachineConfig machine = default_mill();
    std::vector<Move> moves;
    AxisVector at;
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> delta(-20, 20);
    for (int n = 0; n < 200; ++n) {
        AxisVector to = at;
        to[Axis::X] += delta(rng);
        to[Axis::Y] += delta(rng);
        Move m;
        m.what = Line{at, to, Feed{FeedMode::per_minute, 3000, 0}, false, {}};
        moves.push_back(m);
        at = to;
    }
    const PlanResult plan = plan_moves(moves, machine);
    ASSERT_TRUE(plan.diagnostics.empty());
    const std::vector<StepEvent> events = generate_steps(plan.trajectory, machine);
    std::size_t total_runs = 0;
    for (std::uint8_t axis = 0; axis < 3; ++axis) {
        std::vector<std::int64_t> times;
        int direction = 0;
        std::int64_t t_prev = 0;
        auto flush = [&] {
            if (times.empty()) return;
            total_runs += check_runs(times, t_prev, 25000);
            std::int64_t cursor = t_prev;
            (void)compress_steps(times, cursor, 25000);
            t_prev = cursor;
            times.clear();
        };
        for (const StepEvent& e : events) {
            if (e.axis != axis) continue;
            if (e.direction != direction) flush();
            direction = e.direction;
            times.push_back(e.t_ns);
        }
        flush();
    }
    ASSERT_GT(total_runs, 0U);
    const double ratio = static_cast<double>(events.size()) / static_cast<double>(total_runs);
    EXPECT_GT(ratio, 20.0) << "steps " << events.size() << " runs " << total_runs;
}

}  // namespace
}  // namespace nckit
