#pragma once
// nckit::plan_program (the library's interpreter-to-planner loop) for the verbs: its
// diagnostics printed, the progress line kept up to date.
#include <functional>

#include "nckit/interp/interpreter.hpp"
#include "nckit/plan/planner.hpp"

namespace nckit::cli {
class ProgramProgress;
}

namespace nckit::cli {

//! Interprets the whole program into `planner` and calls `on_piece` with every piece in order
//! (`on_move` first sees each move, when given). A bad program or a move the planner refuses
//! prints its diagnostics and returns false; pieces already handed on stay handed on, so the
//! caller writes its output only after a true.
[[nodiscard]] bool plan_program(Interpreter& interpreter, Planner& planner,
                                const std::function<void(const TrajectoryPiece&)>& on_piece,
                                const std::function<void(const Move&)>& on_move = {},
                                ProgramProgress* progress = nullptr);

}  // namespace nckit::cli
