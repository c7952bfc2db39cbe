// The notch job: rewrite, write the plain program, read it back, plan both, measure the cuts.
#include <variant>

#include "nckit/gcode/program_source.hpp"
#include "nckit/interp/interpreter.hpp"
#include "nckit/interp/move_gcode.hpp"
#include "nckit/plan/planner.hpp"
#include "nckit/process/notch/notch.hpp"

namespace nckit {

Result<NotchJob> notch_program(const std::vector<Move>& moves, const MachineConfig& machine,
                               const std::string& source_name, const NotchOptions& options) {
    Result<NotchRewrite> rewrite = rewrite_notches(moves, machine, options);
    if (!rewrite) return rewrite.diagnostics();
    NotchJob job;
    job.cuts = std::move(rewrite->cuts);

    // A plain program (absolute machine coordinates, one move per block) rather than the
    // original text with blocks changed: shortening an approach or inserting moves in a
    // program with incremental moves, macros or calls would shift everything after it.
    GcodeWriter writer(machine);
    // Run-up and overrun points lie on the cut line in the cut's direction: the writer's exact
    // decimals keep them on it (rounded ones would bend the line, and the planner would blend
    // the bend below feed).
    writer.append_header(job.program, source_name);
    for (const Move& move : rewrite->moves) writer.append(job.program, move);
    writer.append_footer(job.program);

    // "After" is measured on the program as written, read back like any program.
    std::vector<Move> reread;
    Interpreter interpreter(machine, ProgramSource::from_string(job.program, source_name + " (notched)"));
    for (;;) {
        InterpResult result = interpreter.next();
        if (std::holds_alternative<ProgramEnd>(result)) break;
        if (auto* diagnostic = std::get_if<Diagnostic>(&result)) return std::move(*diagnostic);
        reread.push_back(std::move(std::get<Move>(result)));
    }
    PlanResult before = plan_moves(moves, machine);
    if (!before.diagnostics.empty()) return before.diagnostics;
    PlanResult after = plan_moves(reread, machine);
    if (!after.diagnostics.empty()) return after.diagnostics;
    for (NotchCut& cut : job.cuts) {
        cut.before = measure_cut_speed(before.trajectory, cut, options);
        cut.after = measure_cut_speed(after.trajectory, cut, options);
    }
    return job;
}

}  // namespace nckit
