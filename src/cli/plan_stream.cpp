#include "plan_stream.hpp"

#include <variant>

#include "common.hpp"

namespace nckit::cli {

bool plan_program(Interpreter& interpreter, Planner& planner,
                  const std::function<void(const TrajectoryPiece&)>& on_piece,
                  const std::function<void(const Move&)>& on_move, ProgramProgress* progress) {
    TrajectoryPiece piece;
    auto drain = [&] {
        while (planner.pop(piece)) on_piece(piece);
    };
    for (;;) {
        InterpResult result = interpreter.next();
        if (std::holds_alternative<ProgramEnd>(result)) break;
        if (const auto* diagnostic = std::get_if<Diagnostic>(&result)) {
            print_diagnostic(*diagnostic);
            return false;
        }
        if (progress != nullptr) progress->update(interpreter);
        const Move& move = std::get<Move>(result);
        if (on_move) on_move(move);
        planner.push(move);
        if (!planner.diagnostics().empty()) break;
        drain();
    }
    if (!planner.diagnostics().empty()) {
        print_diagnostics(planner.diagnostics());
        return false;
    }
    planner.finish();
    drain();
    if (progress != nullptr) progress->finish();
    return true;
}

}  // namespace nckit::cli
