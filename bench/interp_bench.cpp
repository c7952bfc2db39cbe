// Throughput of the front end: parsing blocks, and interpreting whole programs into moves.
#include <benchmark/benchmark.h>

#include <random>
#include <string>
#include <variant>

#include "nckit/gcode/parser.hpp"
#include "nckit/interp/interpreter.hpp"
#include "nckit/interp/move_format.hpp"

namespace {

//! A CAM-like raster of G1 blocks with 3-4 decimals, fixed seed.
std::string g1_program(int blocks) {
    std::mt19937 random(42);
    std::uniform_real_distribution<double> xy(-100.0, 100.0);
    std::uniform_real_distribution<double> z(-10.0, 0.0);
    std::string text = "G21 G90 G94\nG0 X0 Y0 Z5\nG1 Z0 F1200\n";
    char line[96];
    for (int i = 0; i < blocks; ++i) {
        std::snprintf(line, sizeof line, "G1 X%.3f Y%.3f Z%.4f F%d\n", xy(random), xy(random), z(random),
                      1000 + i % 500);
        text += line;
    }
    text += "M30\n";
    return text;
}

void BM_ParseBlock(benchmark::State& state) {
    nckit::Block block;
    const std::string line = "N1234 G1 X-12.345 Y67.890 Z-1.2345 F1500";
    for (auto _ : state) {
        auto error = nckit::parse_block(line, block);
        benchmark::DoNotOptimize(error);
        benchmark::DoNotOptimize(block.words.data());
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_ParseBlock);

void BM_InterpretG1(benchmark::State& state) {
    const std::string text = g1_program(static_cast<int>(state.range(0)));
    std::int64_t moves = 0;
    for (auto _ : state) {
        nckit::Interpreter interpreter(nckit::default_mill(), nckit::ProgramSource::from_string(text, "bench.ngc"));
        for (;;) {
            auto result = interpreter.next();
            if (!std::holds_alternative<nckit::Move>(result)) break;
            ++moves;
        }
    }
    state.SetItemsProcessed(moves);
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(text.size()));
}
BENCHMARK(BM_InterpretG1)->Arg(100000)->Unit(benchmark::kMillisecond);

void BM_FormatMoveText(benchmark::State& state) {
    nckit::MachineConfig machine = nckit::default_mill();
    nckit::Line line;
    line.to[nckit::Axis::X] = -12.345;
    line.to[nckit::Axis::Y] = 67.89;
    line.to[nckit::Axis::Z] = -1.2345;
    line.feed.mm_per_min = 1500;
    nckit::Move move{line, {}, -1};
    std::string out;
    for (auto _ : state) {
        out.clear();
        nckit::append_move_text(out, move, machine);
        benchmark::DoNotOptimize(out.data());
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_FormatMoveText);

}  // namespace

BENCHMARK_MAIN();
