#pragma once
// The canonical printed forms of a Move: a G-code-like line for people and diffs, a JSON object
// for programs. Both name every axis the machine has, in X Y Z A B C U V W order.
#include <string>

#include "nckit/core/machine.hpp"
#include "nckit/interp/move.hpp"

namespace nckit {

//! `G1 X1.0000 Y2.0000 Z0.0000 F600.0000` and the like: 4 decimals, mm, mm/min, s.
void append_move_text(std::string& out, const Move& move, const MachineConfig& machine);

//! One JSON object (no line end) with `line`, `kind`, `end` and the kind's own keys; numbers are
//! printed with full double precision.
void append_move_json(std::string& out, const Move& move, const MachineConfig& machine);

}  // namespace nckit
