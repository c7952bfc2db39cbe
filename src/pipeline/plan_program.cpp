#include "nckit/pipeline/plan_program.hpp"

#include <variant>

namespace nckit {

Diagnostics plan_program(Interpreter& interpreter, Planner& planner, const ProgramPlanCallbacks& callbacks) {
    TrajectoryPiece piece;
    auto drain = [&] {
        while (planner.pop(piece)) {
            if (callbacks.on_piece) callbacks.on_piece(piece);
        }
    };
    for (;;) {
        InterpResult result = interpreter.next();
        if (std::holds_alternative<ProgramEnd>(result)) break;
        if (const auto* diagnostic = std::get_if<Diagnostic>(&result)) return Diagnostics{*diagnostic};
        if (callbacks.on_block) callbacks.on_block(interpreter);
        const Move& move = std::get<Move>(result);
        if (callbacks.on_move) callbacks.on_move(move);
        planner.push(move);
        if (!planner.diagnostics().empty()) return planner.diagnostics();
        drain();
    }
    planner.finish();
    drain();
    return {};
}

}  // namespace nckit
