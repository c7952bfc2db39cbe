// Throughput of the motion profile generator: profiles planned per second for random requests
// (fixed seed), each kind; the requests mix feasible and clamped ones, like a look-ahead pass.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

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

void BM_PlanProfileSCurve(benchmark::State& state) { plan_all(state, nckit::ProfileKind::scurve, false); }
void BM_PlanProfileTrapezoid(benchmark::State& state) { plan_all(state, nckit::ProfileKind::trapezoid, false); }
void BM_PlanProfileSCurveFeasible(benchmark::State& state) { plan_all(state, nckit::ProfileKind::scurve, true); }
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
        profiles.push_back(nckit::plan_profile(r.distance_mm, r.v_start, r.v_end, r.limits, nckit::ProfileKind::scurve));
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

}  // namespace

BENCHMARK_MAIN();
