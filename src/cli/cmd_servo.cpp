// nckit servo FILE: interpret and plan the program, drive every servo axis of the machine
// ([axis.servo]) with the trajectory sampled at its servo period, and report each axis's
// following error: the largest |setpoint - actual|, its RMS and when the largest came.
//
// --json: {"axes": {"X": {"max_following_error_mm", "rms_following_error_mm", "t_max_s"}, ...},
//   "duration_s", "samples", "period_s"}, full double precision.
// --trace OUT.csv: one row per servo axis per sample,
//   "t_s,axis,setpoint_mm,actual_mm,following_error_mm" (deg on rotary axes).
// A bad program, or a machine without servo axes, writes nothing and exits 2.
#include <cstdio>
#include <optional>
#include <string>
#include <variant>

#include <fmt/format.h>

#include "common.hpp"
#include "journal_options.hpp"
#include "partial_file.hpp"
#include "plan_stream.hpp"
#include "nckit/drive/servo_follow.hpp"
#include "nckit/plan/planner.hpp"
#include "verbs.hpp"

namespace nckit::cli {

namespace {

struct ServoOptions {
    std::string program;
    MachineOptions machine;
    bool json = false;
    std::string trace;
    JournalCliOptions journal;
};

void print_report(const ServoOptions& options, const MachineConfig& machine, const drive::ServoFollowReport& report) {
    if (options.json) {
        std::string out = "{\"axes\":{";
        bool first = true;
        for (const drive::FollowingError& axis : report.axes) {
            out +=
                fmt::format("{}\"{}\":{{\"max_following_error_mm\":{},\"rms_following_error_mm\":{},\"t_max_s\":{}}}",
                            first ? "" : ",", letter(axis.axis), axis.max_following_error_mm,
                            axis.rms_following_error_mm, axis.t_max_s);
            first = false;
        }
        fmt::print("{}}},\"duration_s\":{},\"samples\":{},\"period_s\":{}}}\n", out, report.duration_s, report.samples,
                   machine.servo_period_s);
        return;
    }
    fmt::print("duration: {:.6f} s\nsamples: {} (every {} s)\n", report.duration_s, report.samples,
               machine.servo_period_s);
    fmt::print("axis {:>22} {:>22} {:>14}\n", "max |following error|", "rms following error", "at t");
    for (const drive::FollowingError& axis : report.axes) {
        const char* unit = machine.find(axis.axis)->kind == AxisKind::rotary ? "deg" : "mm";
        fmt::print("{:<4} {:>18.6f} {:<3} {:>18.6f} {:<3} {:>12.6f} s\n", letter(axis.axis),
                   axis.max_following_error_mm, unit, axis.rms_following_error_mm, unit, axis.t_max_s);
    }
}

int run_servo(const ServoOptions& options) {
    auto interpreter = open_program_or_report(options.program, options.machine, false);
    if (!interpreter) return exit_bad_input;
    ProgramProgress progress("servo", options.program, options.machine.quiet);
    const MachineConfig& machine = interpreter->machine();
    drive::ServoFollower follower(machine);
    if (!follower.has_servo_axes()) {
        fmt::print(stderr, "{}: error: machine '{}' has no servo axis: give an [[axis]] an [axis.servo] table\n",
                   options.machine.machine.empty() ? "nckit" : options.machine.machine, machine.name);
        return exit_bad_input;
    }
    std::optional<RunJournal> journal;
    if (!open_journal_or_report(options.journal, *interpreter, options.program, journal)) return exit_bad_input;
    Planner planner(machine);
    std::optional<PartialFile> trace_file;
    std::string trace_text;
    drive::ServoFollower::Sink sink;
    if (!options.trace.empty()) {
        trace_file = PartialFile::create(options.trace);
        if (!trace_file) return exit_bad_input;
        trace_text = "t_s,axis,setpoint_mm,actual_mm,following_error_mm\n";
        sink = [&](const drive::ServoSample& s) {
            // + 0.0 turns -0 into 0: a trace read by people and plotting tools.
            fmt::format_to(std::back_inserter(trace_text), "{},{},{},{},{}\n", s.t_s, letter(s.axis),
                           s.setpoint_mm + 0.0, s.actual_mm + 0.0, s.following_error_mm + 0.0);
            if (trace_text.size() > (1 << 16)) {
                trace_file->write(trace_text);
                trace_text.clear();
            }
        };
    }
    // A bad program reports nothing: returning drops the unfinished trace with its PartialFile.
    const ProgramPlanCallbacks callbacks =
        journal_callbacks(journal, *interpreter, [&](const TrajectoryPiece& piece) { follower.add(piece, sink); });
    if (!plan_program(*interpreter, planner, callbacks.on_piece, callbacks.on_move, &progress)) {
        return exit_bad_input;
    }
    follower.finish(sink);
    if (trace_file) {
        trace_file->write(trace_text);
        if (!trace_file->commit()) return exit_bad_input;
    }
    if (!finish_journal_or_report(journal)) return exit_bad_input;
    print_report(options, machine, follower.report());
    return 0;
}

}  // namespace

void add_servo_verb(CLI::App& app, int& exit_status) {
    auto options = std::make_shared<ServoOptions>();
    CLI::App* verb =
        app.add_subcommand("servo", "Drive the servo axes with a program's setpoints: each axis's following error");
    verb->add_option("FILE", options->program, "NC program ('-': standard input)")->required();
    add_machine_options(*verb, options->machine);
    add_journal_options(*verb, options->journal);
    verb->add_flag("--json", options->json, "print the report as one JSON object");
    verb->add_option("--trace", options->trace,
                     "write every sample as CSV: t_s,axis,setpoint_mm,actual_mm,following_error_mm");
    verb->callback([options, &exit_status] { exit_status = run_servo(*options); });
}

}  // namespace nckit::cli
