// nckit plan FILE: interpret and plan the whole program; print the cycle time, the number of
// moves and each axis's peak |v|, |a|, |j|; optionally a trace of the exact trajectory.
#include <cstdio>
#include <variant>

#include <fmt/format.h>

#include "common.hpp"
#include "partial_file.hpp"
#include "plan_stream.hpp"
#include "nckit/plan/planner.hpp"
#include "nckit/plan/sync_report.hpp"
#include "nckit/plan/trajectory_stats.hpp"
#include "verbs.hpp"

namespace nckit::cli {

namespace {

struct PlanOptions {
    std::string program;
    MachineOptions machine;
    std::string profile;
    bool json = false;
    std::string trace;
    double period_s = 0;  // 0: the machine's servo period
    double override_pct = 100;
};

std::string sync_json(const SyncReport& sync) {
    std::string out = fmt::format("\"spindle_sync\":{{\"starts\":{},\"max_index_error_deg\":{},\"first\":[",
                                  sync.count(), sync.max_index_error_deg());
    for (std::size_t i = 0; i < sync.starts().size(); ++i) {
        const SyncStart& s = sync.starts()[i];
        out += fmt::format(
            "{}{{\"line\":{},\"t_s\":{},\"wait_s\":{},\"spindle_angle_deg\":{},\"start_angle_deg\":{},"
            "\"encoder_count\":{}}}",
            i == 0 ? "" : ",", s.where.line, s.t_s, s.wait_s, s.spindle_angle_deg, s.start_angle_deg, s.encoder_count);
    }
    return out + "]}";
}

void print_report(const PlanOptions& options, const MachineConfig& machine, double cycle_time_s, std::int64_t moves,
                  const AxisPeaks& peaks, const SyncReport& sync) {
    if (options.json) {
        std::string out = fmt::format("{{\"cycle_time_s\":{},\"moves\":{},{},\"axes\":{{", json_number(cycle_time_s),
                                      moves, sync_json(sync));
        bool first = true;
        for (std::size_t i = 0; i < axis_count; ++i) {
            auto axis = static_cast<Axis>(i);
            if (machine.find(axis) == nullptr) continue;
            out += fmt::format("{}\"{}\":{{\"max_velocity\":{},\"max_acceleration\":{},\"max_jerk\":{}}}",
                               first ? "" : ",", letter(axis), json_number(peaks.max_velocity[axis]),
                               json_number(peaks.max_acceleration[axis]), json_number(peaks.max_jerk[axis]));
            first = false;
        }
        fmt::print("{}}}}}\n", out);
        return;
    }
    fmt::print("cycle time: {:.6f} s\nmoves: {}\n", cycle_time_s, moves);
    if (sync.count() > 0) {
        fmt::print("G32/G33 starts: {}, each on its start angle past the spindle index (largest error {:.3g} deg)\n",
                   sync.count(), sync.max_index_error_deg());
    }
    fmt::print("axis {:>16} {:>18} {:>18}\n", "max |v|", "max |a|", "max |j|");
    for (const AxisConfig& axis : machine.axes) {
        const char* unit = axis.kind == AxisKind::rotary ? "deg" : "mm";
        fmt::print("{:<4} {:>11.4f} {}/s {:>12.4f} {}/s2 {:>12.4f} {}/s3\n", letter(axis.axis),
                   peaks.max_velocity[axis.axis], unit, peaks.max_acceleration[axis.axis], unit,
                   peaks.max_jerk[axis.axis], unit);
    }
}

int run_plan(const PlanOptions& options) {
    auto interpreter = open_program_or_report(options.program, options.machine, false);
    if (!interpreter) return exit_bad_input;
    ProgramProgress progress("plan", options.program, options.machine.quiet);
    const MachineConfig& machine = interpreter->machine();
    PlannerOptions planner_options;
    if (!options.profile.empty()) {
        planner_options.profile = options.profile == "trapezoid" ? ProfileKind::trapezoid : ProfileKind::scurve;
    }
    planner_options.feed_override = options.override_pct / 100.0;
    Planner planner(machine, planner_options);
    PeakTracker peaks;
    SyncReport sync(machine.spindle);
    double period_s = options.period_s > 0 ? options.period_s : machine.servo_period_s;
    TraceWriter trace(machine, period_s);
    std::optional<PartialFile> trace_file;
    std::string trace_text;
    if (!options.trace.empty()) {
        trace_file = PartialFile::create(options.trace);
        if (!trace_file) return exit_bad_input;
        trace_text = trace.header();
    }
    // A bad program plans nothing: returning drops the unfinished trace with its PartialFile.
    std::int64_t moves = 0;
    double cycle_time_s = 0;
    auto on_piece = [&](const TrajectoryPiece& piece) {
        peaks.add(piece);
        sync.add(piece);
        cycle_time_s = piece.start_time_s + piece.duration_s;
        if (trace_file) {
            trace.add(piece, trace_text);
            if (trace_text.size() > (1 << 16)) {
                trace_file->write(trace_text);
                trace_text.clear();
            }
        }
    };
    auto on_move = [&](const Move& move) {
        if (std::holds_alternative<Line>(move.what) || std::holds_alternative<Arc>(move.what) ||
            std::holds_alternative<SyncMove>(move.what)) {
            ++moves;
        }
    };
    if (!plan_program(*interpreter, planner, on_piece, on_move, &progress)) return exit_bad_input;
    if (trace_file) {
        trace.finish(trace_text);
        trace_file->write(trace_text);
        if (!trace_file->commit()) return exit_bad_input;
    }
    print_report(options, machine, cycle_time_s, moves, peaks.peaks(), sync);
    return 0;
}

}  // namespace

void add_plan_verb(CLI::App& app, int& exit_status) {
    auto options = std::make_shared<PlanOptions>();
    CLI::App* verb = app.add_subcommand("plan", "Plan a program's motion: cycle time and each axis's peaks");
    verb->add_option("FILE", options->program, "NC program ('-': standard input)")->required();
    add_machine_options(*verb, options->machine);
    verb->add_option("--profile", options->profile, "scurve (jerk-limited) or trapezoid; default: the machine's")
        ->check(CLI::IsMember({"scurve", "trapezoid"}));
    verb->add_flag("--json", options->json, "print the report as one JSON object");
    verb->add_option("--trace", options->trace, "write the trajectory as CSV, sampled every period");
    verb->add_option("--period", options->period_s,
                     "trace sampling period S, seconds, > 0 (default: the machine's servo_period_s)")
        ->check(CLI::PositiveNumber);
    verb->add_option("--override", options->override_pct,
                     "feed override PCT, percent, 1-200 (default 100; rapids keep theirs)")
        ->check(CLI::Range(1.0, 200.0));
    verb->callback([options, &exit_status] { exit_status = run_plan(*options); });
}

}  // namespace nckit::cli
