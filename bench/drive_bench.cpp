// Step generation throughput: steps per second on one core, for long lines (the common case)
// and for arcs. The trajectory is planned once; only step generation is timed.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "nckit/drive/step_generator.hpp"
#include "nckit/plan/planner.hpp"

namespace {

nckit::Trajectory lines_trajectory(const nckit::MachineConfig& machine) {
    std::vector<nckit::Move> moves;
    nckit::AxisVector at;
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> delta(-50, 50);
    for (int n = 0; n < 200; ++n) {
        nckit::AxisVector to = at;
        for (std::size_t i = 0; i < 3; ++i) to[i] = at[i] + delta(rng);
        nckit::Move m;
        m.what = nckit::Line{at, to, nckit::Feed{nckit::FeedMode::per_minute, 6000, 0}, false, {}};
        moves.push_back(m);
        at = to;
    }
    return nckit::plan_moves(moves, machine).trajectory;
}

nckit::Trajectory arcs_trajectory(const nckit::MachineConfig& machine) {
    std::vector<nckit::Move> moves;
    nckit::AxisVector at;
    for (int n = 0; n < 50; ++n) {
        nckit::Arc a;
        a.from = at;
        a.to = at;
        a.center = at;
        a.center[nckit::Axis::X] += 10;
        a.direction = n % 2 == 0 ? nckit::ArcDirection::clockwise : nckit::ArcDirection::counterclockwise;
        a.feed = nckit::Feed{nckit::FeedMode::per_minute, 3000, 0};
        nckit::Move m;
        m.what = a;
        moves.push_back(m);
    }
    return nckit::plan_moves(moves, machine).trajectory;
}

void run(benchmark::State& state, const nckit::Trajectory& trajectory, const nckit::MachineConfig& machine) {
    for (auto _ : state) {
        nckit::StepGenerator generator(machine);
        nckit::StepEvent event;
        std::int64_t sum = 0;
        for (const nckit::TrajectoryPiece& piece : trajectory.pieces) {
            generator.add(piece);
            while (generator.pop(event)) sum += event.t_ns;
        }
        generator.finish();
        while (generator.pop(event)) sum += event.t_ns;
        benchmark::DoNotOptimize(sum);
    }
}

std::int64_t count_steps(const nckit::Trajectory& trajectory, const nckit::MachineConfig& machine) {
    return static_cast<std::int64_t>(nckit::generate_steps(trajectory, machine).size());
}

void BM_StepsLines(benchmark::State& state) {
    const nckit::MachineConfig machine = nckit::default_mill();
    const nckit::Trajectory trajectory = lines_trajectory(machine);
    const std::int64_t per_run = count_steps(trajectory, machine);
    run(state, trajectory, machine);
    state.SetItemsProcessed(state.iterations() * per_run);
}
BENCHMARK(BM_StepsLines)->Unit(benchmark::kMillisecond);

void BM_StepsArcs(benchmark::State& state) {
    const nckit::MachineConfig machine = nckit::default_mill();
    const nckit::Trajectory trajectory = arcs_trajectory(machine);
    const std::int64_t per_run = count_steps(trajectory, machine);
    run(state, trajectory, machine);
    state.SetItemsProcessed(state.iterations() * per_run);
}
BENCHMARK(BM_StepsArcs)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
