// The notch job in chunks of cuts: whatever the chunk size, the same rewritten program, the same
// cuts measured the same, the same errors in the same order (chunk boundaries fall between a cut
// and the cut whose approach it is, between a cut and its return, inside a refused program).
#include <gtest/gtest.h>

#include <string>
#include <variant>
#include <vector>

#include "nckit/gcode/program_source.hpp"
#include "nckit/interp/interpreter.hpp"
#include "nckit/process/notch/notch.hpp"
#include "notch_test_support.hpp"
#include "nckit/process/notch/notch_json.hpp"

namespace nckit {
namespace {

using notch_test::file;
using notch_test::interpret;
using notch_test::notcher;
using notch_test::program;

//! Everything the job gives, as text: the program, each cut's JSON, or the errors.
std::string outcome(const std::vector<Move>& moves, const MachineConfig& machine, std::size_t cuts_per_chunk) {
    NotchOptions options;
    options.cuts_per_chunk = cuts_per_chunk;
    Result<NotchJob> job = notch_program(moves, machine, "p.nc", options);
    std::string out;
    if (!job.ok()) {
        for (const Diagnostic& d : job.diagnostics()) out += format_diagnostic(d) + "\n";
        return out;
    }
    out = job->program;
    for (const NotchCut& cut : job->cuts) out += to_json(cut).dump() + "\n";
    return out;
}

TEST(NotchChunks, EveryChunkSizeGivesTheSameJob) {
    const MachineConfig machine = notcher();
    for (const char* path :
         {"examples/notch/conrod.nc", "tests/process/notch_golden/multi.nc", "tests/process/notch_golden/oblique.nc",
          "tests/process/notch_golden/macro.nc", "tests/process/notch_golden/crossing.nc"}) {
        const std::vector<Move> moves = file(path, machine);
        const std::string whole = outcome(moves, machine, 1000);
        ASSERT_FALSE(whole.empty()) << path;
        for (std::size_t chunk : {1U, 2U, 3U, 5U}) {
            EXPECT_EQ(outcome(moves, machine, chunk), whole) << path << " in chunks of " << chunk;
        }
    }
}

// Many cuts (several refused, two of them in a row) across many chunks: the errors in cut order.
TEST(NotchChunks, ErrorsComeInCutOrderAcrossChunks) {
    const MachineConfig machine = notcher();
    std::string text = "G90 G18 G1 X0 Z40 F3000\n";
    for (int i = 0; i < 23; ++i) {
        const double x = 10 + 20 * i;
        text += "G0 X" + std::to_string(x) + " Z30\nG1 Z20 F4000\nM27\nG1 Z8 F900\nM28\n";
        // Every seventh notch is followed by a move over its overrun.
        if (i % 7 == 3) text += "G1 Z7.99 F500\nG1 Z30\n";
    }
    text += "M30\n";
    const std::vector<Move> moves = interpret(ProgramSource::from_string(text, "p.nc"), machine);
    const std::string whole = outcome(moves, machine, 1000);
    EXPECT_NE(whole.find("crosses the path of line"), std::string::npos) << whole;
    for (std::size_t chunk : {1U, 2U, 4U, 7U}) {
        EXPECT_EQ(outcome(moves, machine, chunk), whole) << "chunks of " << chunk;
    }
}

}  // namespace
}  // namespace nckit
