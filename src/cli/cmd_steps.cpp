// nckit steps FILE: interpret, plan and turn the trajectory into exact step/direction events.
//
// Binary output (default): one 10-byte record per step, little-endian, no header:
//   bytes 0-7  int64  time, ns from the trajectory start
//   byte  8    uint8  axis index, in the machine file's axis order
//   byte  9    int8   direction, +1 or -1
// --text: one step a line, "t_ns axis dir"; for an axis with a phase table (`phase_table`) a
//   fourth column, "0x0B", the byte its port holds after the step (`port_active_low`,
//   `port_set_bits`), from the motor's absolute count, backlash steps included.
// --compress US: text commands for step-compressing firmware, per axis in time order:
//   "set_next_step_dir AXIS DIR" before each change of direction, and
//   "queue_step AXIS INTERVAL_NS COUNT ADD_NS" (Klipper's queue_step, in ns), every step within
//   US microseconds of its exact time; the compression ratio (steps / runs) goes to stderr.
// Output streams in bounded memory. With -o a regular file appears only when the whole program
// ran clean (OUT.partial, renamed at the end); standard output, a pipe or a device receives the
// steps as they come, so a bad program's output there stops at the error (exit status 2).
#include <cstdio>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <fmt/format.h>

#include "common.hpp"
#include "journal_options.hpp"
#include "partial_file.hpp"
#include "plan_stream.hpp"
#include "step_record.hpp"
#include "nckit/drive/phase_table.hpp"
#include "nckit/drive/step_queue.hpp"
#include "nckit/drive/step_generator.hpp"
#include "nckit/plan/planner.hpp"
#include "verbs.hpp"

namespace nckit::cli {

namespace {

struct StepsOptions {
    std::string program;
    MachineOptions machine;
    std::string output;
    bool text = false;
    std::string compress_text;  // --compress's value, empty for the default
    double compress_us = -1;    // < 0: no compression
    JournalCliOptions journal;
};

// Bytes for the output, flushed as they grow: memory stays bounded however long the program.
class Output {
public:
    explicit Output(std::FILE* file) : file_(file) {}
    std::string& buffer() { return buffer_; }
    void maybe_flush() {
        if (buffer_.size() > (1 << 16)) flush();
    }
    void flush() {
        std::fwrite(buffer_.data(), 1, buffer_.size(), file_);
        buffer_.clear();
    }

private:
    std::FILE* file_;
    std::string buffer_;
};

void print_commands(std::vector<StepQueueCommand>& commands, std::string& out) {
    for (const StepQueueCommand& c : commands) {
        if (c.kind == StepQueueCommand::Kind::set_direction) {
            out += fmt::format("set_next_step_dir {} {}\n", c.axis, c.direction);
        } else {
            out += fmt::format("queue_step {} {} {} {}\n", c.axis, c.run.interval_ns, c.run.count, c.run.add_ns);
        }
    }
    commands.clear();
}

int run_steps(const StepsOptions& options) {
    auto interpreter = open_program_or_report(options.program, options.machine, false);
    if (!interpreter) return exit_bad_input;
    ProgramProgress progress("steps", options.program, options.machine.quiet);
    const MachineConfig& machine = interpreter->machine();
    Planner planner(machine);
    StepGenerator steps(machine);

    std::optional<RunJournal> journal;
    if (!open_journal_or_report(options.journal, *interpreter, options.program, journal)) return exit_bad_input;
    std::optional<PartialFile> file = PartialFile::create(options.output.empty() ? "-" : options.output);
    if (!file) return exit_bad_input;
    // A bad program leaves no -o file: returning drops the unfinished output with its PartialFile.
    Output out(file->get());
    const bool compress = options.compress_us >= 0;
    std::optional<StepQueue> queue;
    if (compress) queue.emplace(machine.axes.size(), static_cast<std::int64_t>(options.compress_us * 1000.0));
    std::vector<StepQueueCommand> commands;
    // Phase-table axes' windings, started at the beat of their first position on the first step.
    std::vector<std::optional<drive::PhaseSequencer>> phases(machine.axes.size());

    auto write = [&](const StepEvent& e) {
        if (queue) {
            queue->add(e, commands);
            print_commands(commands, out.buffer());
        } else if (options.text) {
            const AxisConfig& axis = machine.axes[e.axis];
            if (axis.phase_table == PhaseTableKind::none) {
                out.buffer() += fmt::format("{} {} {}\n", e.t_ns, e.axis, e.direction);
            } else {
                std::optional<drive::PhaseSequencer>& phase = phases[e.axis];
                if (!phase) phase.emplace(axis.phase_table, drive::port_encoding(axis), steps.start_count(e.axis));
                const std::uint8_t port =
                    phase->step(e.direction > 0 ? drive::Direction::forward : drive::Direction::reverse);
                out.buffer() += fmt::format("{} {} {} 0x{:02X}\n", e.t_ns, e.axis, e.direction, port);
            }
        } else {
            append_step_record(out.buffer(), e);
        }
        out.maybe_flush();
    };
    StepEvent event;
    auto on_piece = [&](const TrajectoryPiece& piece) {
        steps.add(piece);
        while (steps.pop(event)) write(event);
    };
    const ProgramPlanCallbacks callbacks = journal_callbacks(journal, *interpreter, on_piece);
    if (!plan_program(*interpreter, planner, callbacks.on_piece, callbacks.on_move, &progress)) {
        if (file->is_stdout()) out.flush();  // what came before the error, as `moves` prints it
        return exit_bad_input;
    }
    steps.finish();
    while (steps.pop(event)) write(event);
    if (queue) {
        queue->finish(commands);
        print_commands(commands, out.buffer());
    }
    out.flush();
    if (!file->commit()) return exit_bad_input;
    if (!finish_journal_or_report(journal)) return exit_bad_input;
    if (queue) {
        fmt::print(stderr, "steps: {} runs: {} compression ratio: {:.2f}\n", queue->steps(), queue->runs(),
                   queue->compression_ratio());
    }
    return 0;
}

}  // namespace

void add_steps_verb(CLI::App& app, int& exit_status) {
    auto options = std::make_shared<StepsOptions>();
    CLI::App* verb = app.add_subcommand("steps", "Generate the exact step/direction events of a program");
    verb->add_option("FILE", options->program, "NC program ('-': standard input)")->required();
    add_machine_options(*verb, options->machine);
    add_journal_options(*verb, options->journal);
    verb->add_option("-o,--output", options->output, "output file; '-': standard output (the default)");
    verb->add_flag("--text", options->text, "one step a line: t_ns axis dir, and the port byte on phase-table axes");
    auto* compress =
        verb->add_option("--compress", options->compress_text,
                         "write queue_step runs, every step within US microseconds of its time, US >= 0 (default 25)")
            ->expected(0, 1);
    verb->callback([options, compress, &exit_status] {
        if (compress->count() > 0) {
            try {
                options->compress_us = options->compress_text.empty() ? 25.0 : std::stod(options->compress_text);
            } catch (const std::exception&) {
                options->compress_us = -1;
            }
            if (!(options->compress_us >= 0)) {
                fmt::print(stderr, "error: --compress needs a timing error in us, 0 or more\n");
                exit_status = exit_bad_input;
                return;
            }
        }
        exit_status = run_steps(*options);
    });
}

}  // namespace nckit::cli
