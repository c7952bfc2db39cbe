// Cam engine throughput: evaluations of r(θ, z) per second on one core for the example piston
// (examples/piston/piston.toml), at random (θ, z) and in encoder order (one count per spindle
// degree, Z advancing at the job's feed), against the exact drawing it is built from.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <functional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "nckit/cam/cam_table.hpp"
#include "nckit/cam/encoder_cam.hpp"
#include "nckit/process/piston/piston_job.hpp"

namespace {

using nckit::cam::CamTable;
using nckit::cam::PistonJob;

const PistonJob& example(const std::string& name) {
    static std::vector<std::pair<std::string, PistonJob>> loaded;
    for (const auto& [file, job] : loaded) {
        if (file == name) return job;
    }
    nckit::Result<PistonJob> job =
        nckit::cam::load_piston_job(std::string(NCKIT_SOURCE_DIR) + "/examples/piston/" + name);
    if (!job) throw std::runtime_error(nckit::format_diagnostic(job.diagnostics().front()));
    loaded.emplace_back(name, std::move(job).value());
    return loaded.back().second;
}

const CamTable& example_table() {
    static const CamTable table = nckit::cam::build_cam_table(example("piston.toml"));
    return table;
}

void describe(benchmark::State& state, const CamTable& table) {
    state.counters["theta_cells"] = static_cast<double>(table.theta_cells());
    state.counters["z_cells"] = static_cast<double>(table.z_cells());
    state.counters["bound_nm"] = table.error_bound_mm() * 1e6;
    state.counters["table_kB"] = static_cast<double>(table.memory_bytes()) / 1024.0;
}

//! Seeded random (θ, z) over the turn and the stations.
struct RandomPoints {
    std::vector<double> theta_deg, z_mm;
    explicit RandomPoints(std::size_t count) {
        std::mt19937_64 rng(42);
        std::uniform_real_distribution<double> theta(0, 360), z(0, 50);
        for (std::size_t i = 0; i < count; ++i) {
            theta_deg.push_back(theta(rng));
            z_mm.push_back(z(rng));
        }
    }
};

void BM_CamTableRandom(benchmark::State& state) {
    const CamTable& table = example_table();
    const RandomPoints points(1 << 16);
    for (auto _ : state) {
        double sum = 0;
        for (std::size_t i = 0; i < points.theta_deg.size(); ++i) {
            sum += table(points.theta_deg[i], points.z_mm[i]);
        }
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(points.theta_deg.size()));
    describe(state, table);
}
BENCHMARK(BM_CamTableRandom);

// One iteration turns the whole skirt: 500 turns of 360 counts at 0.1 mm/rev over Z 0..50.
constexpr std::int64_t counts_per_rev = 360;
constexpr std::int64_t skirt_counts = 500 * counts_per_rev;
constexpr double z_per_count_mm = 0.1 / counts_per_rev;

void BM_CamTableEncoderOrder(benchmark::State& state) {
    const CamTable& table = example_table();
    for (auto _ : state) {
        double sum = 0;
        for (std::int64_t k = 0; k < skirt_counts; ++k) {
            const double theta = static_cast<double>(k) * (360.0 / counts_per_rev);
            sum += table(theta, static_cast<double>(k) * z_per_count_mm);
        }
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * skirt_counts);
    describe(state, table);
}
BENCHMARK(BM_CamTableEncoderOrder);

void BM_EncoderCamNext(benchmark::State& state) {
    const CamTable& table = example_table();
    nckit::cam::EncoderCam encoder(table, counts_per_rev);
    for (auto _ : state) {
        double sum = 0;
        for (std::int64_t k = 0; k < skirt_counts; ++k) {
            sum += encoder.next(static_cast<double>(k) * z_per_count_mm);
        }
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * skirt_counts);
    describe(state, table);
}
BENCHMARK(BM_EncoderCamNext);

// The exact drawings, for comparison: why the servo tick reads a table.
void exact_random(benchmark::State& state, const char* name) {
    const PistonJob& job = example(name);
    const RandomPoints points(1 << 12);
    for (auto _ : state) {
        double sum = 0;
        for (std::size_t i = 0; i < points.theta_deg.size(); ++i) {
            sum += job.profile.radius_mm(points.theta_deg[i], points.z_mm[i]);
        }
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(points.theta_deg.size()));
}
BENCHMARK_CAPTURE(exact_random, spline_table_drawing, "piston.toml");
BENCHMARK_CAPTURE(exact_random, formula_drawing, "piston_formula.toml");

void build_table(benchmark::State& state, const char* name) {
    const PistonJob& job = example(name);
    for (auto _ : state) {
        CamTable table = nckit::cam::build_cam_table(job);
        benchmark::DoNotOptimize(table);
        describe(state, table);
    }
}
BENCHMARK_CAPTURE(build_table, spline_table_drawing, "piston.toml")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(build_table, formula_drawing, "piston_formula.toml")->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
