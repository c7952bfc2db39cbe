#include "plan_stream.hpp"

#include "common.hpp"
#include "nckit/pipeline/plan_program.hpp"

namespace nckit::cli {

bool plan_program(Interpreter& interpreter, Planner& planner,
                  const std::function<void(const TrajectoryPiece&)>& on_piece,
                  const std::function<void(const Move&)>& on_move, ProgramProgress* progress) {
    ProgramPlanCallbacks callbacks;
    callbacks.on_piece = on_piece;
    callbacks.on_move = on_move;
    if (progress != nullptr) callbacks.on_block = [progress](const Interpreter& i) { progress->update(i); };
    const Diagnostics diagnostics = nckit::plan_program(interpreter, planner, callbacks);
    if (!diagnostics.empty()) {
        print_diagnostics(diagnostics);
        return false;
    }
    if (progress != nullptr) progress->finish();
    return true;
}

}  // namespace nckit::cli
