// Throughput of the motion profile generator: profiles planned per second for random requests
// (fixed seed), each kind; the requests mix feasible and clamped ones, like a look-ahead pass.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "nckit/plan/planner.hpp"
#include "nckit/plan/profile.hpp"

namespace {

struct Request {
    double distance_mm;
    double v_start;
    double v_end;
    nckit::ProfileLimits limits;
};

std::vector<Request> requests(nckit::ProfileKind kind, bool feasible_only) {
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    auto decade = [&](double lo, double hi) { return std::pow(10.0, lo + (hi - lo) * unit(random)); };
    std::vector<Request> out(4096);
    for (Request& r : out) {
        r.limits = {decade(0, 3.5), decade(1, 5), decade(2, 8)};
        r.distance_mm = decade(-4, 3);
        r.v_start = r.limits.max_velocity * unit(random);
        r.v_end = r.limits.max_velocity * unit(random);
        if (feasible_only) {
            const double lo = nckit::min_end_speed(r.distance_mm, r.v_start, r.limits, kind);
            const double hi = nckit::max_end_speed(r.distance_mm, r.v_start, r.limits, kind);
            r.v_end = lo + (hi - lo) * unit(random);
        }
    }
    return out;
}

void plan_all(benchmark::State& state, nckit::ProfileKind kind, bool feasible_only) {
    const std::vector<Request> input = requests(kind, feasible_only);
    std::size_t i = 0;
    for (auto _ : state) {
        const Request& r = input[i++ & 4095];
        nckit::Profile p = nckit::plan_profile(r.distance_mm, r.v_start, r.v_end, r.limits, kind);
        benchmark::DoNotOptimize(p);
    }
    state.SetItemsProcessed(state.iterations());
}

void BM_PlanProfileSCurve(benchmark::State& state) {
    plan_all(state, nckit::ProfileKind::scurve, false);
}
void BM_PlanProfileTrapezoid(benchmark::State& state) {
    plan_all(state, nckit::ProfileKind::trapezoid, false);
}
void BM_PlanProfileSCurveFeasible(benchmark::State& state) {
    plan_all(state, nckit::ProfileKind::scurve, true);
}
void BM_PlanProfileTrapezoidFeasible(benchmark::State& state) {
    plan_all(state, nckit::ProfileKind::trapezoid, true);
}
BENCHMARK(BM_PlanProfileSCurve);
BENCHMARK(BM_PlanProfileTrapezoid);
BENCHMARK(BM_PlanProfileSCurveFeasible);
BENCHMARK(BM_PlanProfileTrapezoidFeasible);

//! Evaluating a planned profile at a random time: what sampling at the servo period costs.
void BM_ProfileAt(benchmark::State& state) {
    const std::vector<Request> input = requests(nckit::ProfileKind::scurve, true);
    std::vector<nckit::Profile> profiles;
    for (const Request& r : input) {
        profiles.push_back(
            nckit::plan_profile(r.distance_mm, r.v_start, r.v_end, r.limits, nckit::ProfileKind::scurve));
    }
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<double> fractions(4096);
    for (double& f : fractions) f = unit(random);
    std::size_t i = 0;
    for (auto _ : state) {
        const nckit::Profile& p = profiles[i & 4095];
        nckit::ProfileState s = p.at(fractions[i & 4095] * p.duration_s());
        ++i;
        benchmark::DoNotOptimize(s);
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ProfileAt);

//! A CAM-style chain: 100,000 lines of 0.01–0.1 mm along a wavy curve at F3000, G64, each
//! pushed and popped through the streaming planner with S-curve look-ahead. Items are moves.
//! With `zigzag_rad` each line turns that much more, alternately left and right, so that no
//! two lines can be merged into one chord.
std::vector<nckit::Move> short_segment_chain(std::size_t count, double zigzag_rad = 0) {
    std::mt19937_64 random(3);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<nckit::Move> moves;
    moves.reserve(count);
    nckit::AxisVector at;
    double heading = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const double step = 0.01 + 0.09 * unit(random);
        heading += 0.02 * std::sin(static_cast<double>(i) * 0.01) + 0.002 * (unit(random) - 0.5);
        const double zig_rad = (i % 2 == 0 ? 0.5 : -0.5) * zigzag_rad;
        nckit::AxisVector to = at;
        to[nckit::Axis::X] += step * std::cos(heading + zig_rad);
        to[nckit::Axis::Y] += step * std::sin(heading + zig_rad);
        nckit::Line line{at, to, nckit::Feed{nckit::FeedMode::per_minute, 3000, 0}, false, {}};
        nckit::Move move;
        move.what = line;
        moves.push_back(move);
        at = to;
    }
    return moves;
}

void plan_chain(benchmark::State& state, const std::vector<nckit::Move>& moves) {
    nckit::MachineConfig machine = nckit::default_mill();
    nckit::PlannerOptions options;
    options.profile = nckit::ProfileKind::scurve;
    double cycle_s = 0;
    for (auto _ : state) {
        nckit::Planner planner(machine, options);
        nckit::TrajectoryPiece piece;
        for (const nckit::Move& move : moves) {
            planner.push(move);
            while (planner.pop(piece)) benchmark::DoNotOptimize(piece);
        }
        planner.finish();
        while (planner.pop(piece)) cycle_s = piece.start_time_s + piece.duration_s;
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(moves.size()));
    state.counters["cycle_s"] = cycle_s;
    // Memory per move: each output piece, and at most window_moves window entries.
    state.counters["piece_bytes"] = static_cast<double>(sizeof(nckit::TrajectoryPiece));
}

void BM_PlannerShortSegmentsSCurve(benchmark::State& state) {
    plan_chain(state, short_segment_chain(100000));
}
BENCHMARK(BM_PlannerShortSegmentsSCurve)->Unit(benchmark::kMillisecond);

// The same chain with a 0.3 rad zig-zag at every vertex: every line is planned as a segment of
// its own with a transition at each corner (the chain smoother merges nothing here).
void BM_PlannerZigZagSCurve(benchmark::State& state) {
    plan_chain(state, short_segment_chain(100000, 0.3));
}
BENCHMARK(BM_PlannerZigZagSCurve)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
