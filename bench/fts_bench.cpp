// The fast tool servo simulation of the oval piston job (docs/processes/piston.md): z 0 .. 50 mm at
// 0.1 mm/rev, 2500 rpm, 360 counts per turn, 20 air turns: 520 turns, 187,201 ticks per run, three
// runs (uncompensated, feedforward, learning). Timed whole; the profile errors ride along as
// counters (µm), so one run of this target gives the figures and their cost.
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

#include "nckit/process/fts/fast_tool_servo.hpp"

namespace {

//! D 89.8 .. 89.98 mm (barrel), ovality 0.4 .. 0.8 mm, r = D/2 - (E/4)(1 - cos 2 phi), cut about
//! the section's mean radius.
nckit::FtsDemand piston(double theta_deg, double z_mm) {
    const double d = 89.98 - 0.18 * std::pow((z_mm - 30.0) / 30.0, 2);
    const double e = 0.4 + 0.4 * z_mm / 50.0;
    const double r = d / 2 - e / 4 * (1 - std::cos(2 * theta_deg * std::numbers::pi / 180));
    return {r, r - (d / 2 - e / 4)};
}

// Arguments: model error in percent, synchronous ripple in 0.1 %, slow ripple in 0.1 %.
void BM_PistonJob(benchmark::State& state) {
    nckit::FtsParameters p;
    p.servo.model_error = static_cast<double>(state.range(0)) / 100.0;
    p.ripple.fraction = static_cast<double>(state.range(1)) / 1000.0;
    p.ripple.slow_fraction = static_cast<double>(state.range(2)) / 1000.0;
    nckit::FtsSimulation last;
    for (auto _ : state) {
        nckit::Result<nckit::FtsSimulation> done = nckit::simulate_fast_tool_servo(p, piston);
        if (!done) {
            state.SkipWithError("simulation failed");
            return;
        }
        last = std::move(*done);
        benchmark::DoNotOptimize(last);
    }
    state.counters["none_pv_um"] = last.uncompensated.pv_um;
    state.counters["none_rms_um"] = last.uncompensated.rms_um;
    state.counters["ff_pv_um"] = last.feedforward.pv_um;
    state.counters["ff_rms_um"] = last.feedforward.rms_um;
    state.counters["learn_pv_um"] = last.learning.pv_um;
    state.counters["learn_rms_um"] = last.learning.rms_um;
    state.counters["turns_to_1um"] = nckit::settled_turn(last.learning.turn_pv_um, 1.0);
    state.counters["turns_to_0.1um"] = nckit::settled_turn(last.learning.turn_pv_um, 0.1);
    state.counters["contraction"] = last.learning_contraction.any_frequency;
    state.counters["ticks_per_s"] =
        benchmark::Counter(3.0 * static_cast<double>(last.ticks), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_PistonJob)
    ->Args({10, 2, 0})
    ->Args({-10, 2, 0})
    ->Args({10, 0, 0})
    ->Args({-10, 0, 0})
    ->Args({10, 2, 2})
    ->Args({-10, 2, 2})
    ->ArgNames({"model_error_pct", "ripple_permille", "slow_permille"})
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
