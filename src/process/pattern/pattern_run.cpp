// Layout, order, bound, program and plan of one sole.
#include "nckit/process/pattern/pattern_run.hpp"

#include <set>

#include "nckit/interp/interpreter.hpp"
#include "nckit/pipeline/plan_program.hpp"
#include "nckit/plan/planner.hpp"

namespace nckit::pattern {

namespace {

// Plans `program` and splits its time between rapids (lines that start with G0) and the rest.
Result<std::array<double, 2>> plan_times(const std::string& program, const MachineConfig& machine) {
    std::set<std::uint32_t> rapid_lines;
    std::uint32_t line = 0;
    for (std::size_t at = 0; at < program.size();) {
        ++line;
        if (program.compare(at, 3, "G0 ") == 0) rapid_lines.insert(line);
        const std::size_t end = program.find('\n', at);
        at = end == std::string::npos ? program.size() : end + 1;
    }
    Interpreter interpreter(machine, ProgramSource::from_string(program, "pattern.nc"));
    Planner planner(machine);
    std::array<double, 2> times{0, 0};
    ProgramPlanCallbacks callbacks;
    callbacks.on_piece = [&](const TrajectoryPiece& piece) {
        times[rapid_lines.count(piece.where.line) ? 0 : 1] += piece.duration_s;
    };
    const Diagnostics diagnostics = plan_program(interpreter, planner, callbacks);
    if (!diagnostics.empty()) return diagnostics;
    return times;
}

}  // namespace

Result<SoleRun> run_pattern_sole(const PatternJob& job, const OutlinePoints& points, const Grading& grading,
                                 const MachineConfig& machine, const std::string& title, bool optimise) {
    Result<SoleLayout> layout = lay_out_sole(job, points, grading);
    if (!layout) return layout.diagnostics();
    SoleRun run;
    run.layout = std::move(*layout);
    for (const Cut& cut : run.layout.cuts) {
        run.ends.push_back(describe_cut(cut.curve, spline_chord_tolerance_mm));
        run.cut_length_mm += curve_length(cut.curve);
    }
    OrderCosts costs{AirTimer(machine), {0, 0}, Vec2{0, 0}};
    for (int axis = 0; axis < 2; ++axis) {
        costs.reversal_s[static_cast<std::size_t>(axis)] = job.reversal_cost_s.value_or(costs.timer.reversal_s(axis));
    }
    const Tour drawn = drawing_tour(run.ends.size());
    if (optimise) {
        run.search = optimise_tour(run.ends, costs);
        run.tour = run.search.tour;
    } else {
        run.tour = drawn;
    }
    // Both orders are reported as the program cuts them: starts on whole steps.
    auto as_cut = [&](const Tour& tour) {
        std::vector<CutEnds> ends;
        for (const ProgramCut& cut : program_cuts(run.layout, tour, machine)) {
            ends.push_back(describe_cut(cut.curve, spline_chord_tolerance_mm));
        }
        return evaluate_tour(ends, drawing_tour(ends.size()), costs);
    };
    run.drawing = as_cut(drawn);
    run.optimised = as_cut(run.tour);
    run.bound_distance_mm =
        air_cost_lower_bound(
            run.ends, costs.home, [](Vec2 a, Vec2 b) { return length(b - a); }, run.optimised.air_distance_mm)
            .value;
    run.bound_time_s =
        air_cost_lower_bound(
            run.ends, costs.home, [&](Vec2 a, Vec2 b) { return costs.timer.rapid_s(b - a); }, run.optimised.air_time_s)
            .value;
    // The rapids in Z: up from the surface once, then per groove up from its depth and down to
    // the approach height.
    run.z_air_time_s = costs.timer.rapid_s(0, 0, job.clearance_mm);
    for (const Cut& cut : run.layout.cuts) {
        run.z_air_time_s += costs.timer.rapid_s(0, 0, cut.depth_mm + job.clearance_mm) +
                            costs.timer.rapid_s(0, 0, job.clearance_mm - job.approach_mm);
    }
    run.program_cuts = program_cuts(run.layout, run.tour, machine);
    run.program = pattern_program(run.program_cuts, job, title);
    Result<std::array<double, 2>> times = plan_times(run.program, machine);
    if (!times) return times.diagnostics();
    run.planned_air_s = (*times)[0];
    run.planned_cut_s = (*times)[1];
    run.planned_cycle_s = run.planned_air_s + run.planned_cut_s;
    return run;
}

}  // namespace nckit::pattern
