// nckit moves FILE: the interpreter's move stream, one line per move, as text or JSON lines.
#include <cstdio>
#include <variant>

#include <fmt/format.h>

#include "common.hpp"
#include "move_pump.hpp"
#include "nckit/interp/move_format.hpp"
#include "nckit/interp/move_summary.hpp"
#include "verbs.hpp"

namespace nckit::cli {

namespace {

struct MovesOptions {
    std::string program;
    MachineOptions machine;
    bool json = false;
    bool summary = false;
    bool save_vars = false;
};

void print_summary(const MoveSummary& s, const MachineConfig& machine) {
    fmt::print("moves: {} rapid, {} linear, {} arc, {} sync, {} dwell, {} io\n", s.rapids, s.lines, s.arcs, s.syncs,
               s.dwells, s.ios);
    fmt::print("cutting length: {:.3f} mm, rapid length: {:.3f} mm\n", s.cutting_length_mm, s.rapid_length_mm);
    fmt::print("time at programmed feed: {:.3f} s, dwell: {:.3f} s\n", s.feed_time_s, s.dwell_s);
    if (!s.any_motion) return;
    for (const AxisConfig& axis : machine.axes) {
        const char* unit = axis.kind == AxisKind::rotary ? "deg" : "mm";
        fmt::print("{} range: {:.4f} .. {:.4f} {}\n", letter(axis.axis), s.low[axis.axis], s.high[axis.axis], unit);
    }
}

int run_moves(const MovesOptions& options) {
    auto interpreter = open_program_or_report(options.program, options.machine, options.save_vars);
    if (!interpreter) return exit_bad_input;
    const MachineConfig& machine = interpreter->machine();
    const std::uint64_t total_bytes = regular_file_bytes(options.program);
    std::string buffer;
    buffer.reserve(1 << 17);
    MoveSummary summary;
    auto flush = [&] {
        std::fwrite(buffer.data(), 1, buffer.size(), stdout);
        buffer.clear();
    };
    // Interpreting runs on a second thread while this one prints: on two cores a long program
    // takes little more than the slower of the two.
    // Counted here, on the printing thread; the share of the file read is the pump's to know.
    Progress progress("nckit moves", "moves", options.machine.quiet);
    std::int64_t count = 0;
    MovePump pump(*interpreter);
    for (std::vector<InterpResult> batch = pump.next_batch(); !batch.empty(); batch = pump.next_batch()) {
        for (const InterpResult& result : batch) {
            if (const auto* diagnostic = std::get_if<Diagnostic>(&result)) {
                flush();
                print_diagnostic(*diagnostic);
                return exit_bad_input;
            }
            const auto* move = std::get_if<Move>(&result);
            if (move == nullptr) break;  // ProgramEnd
            progress.update(++count, pump.fraction_read(total_bytes));
            if (options.summary) {
                summary.add(*move);
                continue;
            }
            if (options.json) {
                append_move_json(buffer, *move, machine);
            } else {
                append_move_text(buffer, *move, machine);
            }
            buffer += '\n';
            if (buffer.size() > (1 << 16)) flush();
        }
    }
    flush();
    progress.finish();
    if (options.summary) print_summary(summary, machine);
    return 0;
}

}  // namespace

void add_moves_verb(CLI::App& app, int& exit_status) {
    auto options = std::make_shared<MovesOptions>();
    CLI::App* verb = app.add_subcommand("moves", "Print the moves a program makes, in machine coordinates");
    verb->add_option("FILE", options->program, "NC program ('-': standard input)")->required();
    add_machine_options(*verb, options->machine);
    CLI::Option* json = verb->add_flag("--json", options->json, "one JSON object per line");
    verb->add_flag("--summary", options->summary, "totals instead of the moves (text)")->excludes(json);
    verb->add_flag("--save-vars", options->save_vars,
                   "write #500-#999 back to their file at the end (--vars, or the machine file with .vars)");
    verb->callback([options, &exit_status] { exit_status = run_moves(*options); });
}

}  // namespace nckit::cli
