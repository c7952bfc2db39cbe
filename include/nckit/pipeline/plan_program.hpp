#pragma once
// The loop that joins the interpreter to the planner: every move of a program pushed into a
// streaming planner, every trajectory piece handed on as soon as its timing is final, in
// bounded memory however long the program. `nckit plan`, `steps`, `servo` and `report` run it.
#include <functional>

#include "nckit/core/diagnostic.hpp"
#include "nckit/interp/interpreter.hpp"
#include "nckit/plan/planner.hpp"

namespace nckit {

//! What plan_program tells its caller while it runs; each may be empty.
struct ProgramPlanCallbacks {
    std::function<void(const TrajectoryPiece&)> on_piece;  //!< every piece, in order
    std::function<void(const Move&)> on_move;              //!< every move, before the planner sees it
    std::function<void(const Interpreter&)> on_block;      //!< after each move (progress reports)
};

//! Interprets the whole program into `planner` (then finishes it) and hands on its pieces.
//! Returns no diagnostics when the program ran to its end; otherwise the interpreter's
//! diagnostic or the planner's, and the run stops there: pieces already handed on stay handed
//! on, so a caller writing a file writes it only after an empty answer.
[[nodiscard]] Diagnostics plan_program(Interpreter& interpreter, Planner& planner,
                                       const ProgramPlanCallbacks& callbacks);

}  // namespace nckit
