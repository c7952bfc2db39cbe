#pragma once
// What `nckit plan`, `nckit steps` and `nckit servo` share: the program through the interpreter
// and the streaming planner, each trajectory piece handed on as soon as it is final.
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
