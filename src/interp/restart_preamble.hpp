#pragma once
// The pieces of a restart program before the rest of the run (docs/restart.md): the spindle,
// tool and I/O state, the program's frame, the approach. Private to restart.cpp.
#include <string>

#include "nckit/core/machine.hpp"
#include "nckit/interp/restart.hpp"

namespace nckit::restart_detail {

//! Folds one I/O event of the search into the state the preamble switches on again.
void note_io(const Io& io, const MachineConfig& machine, RestartIo& state);
//! "FILE:LINE" of a block, for messages and comments.
[[nodiscard]] std::string location_text(const SourceLocation& where);
[[nodiscard]] const char* plane_code(Plane plane);
void frame_comments(std::string& out, const ModalView& s, const MachineConfig& machine);
void io_blocks(std::string& out, const RestartIo& io);
[[nodiscard]] Axis retract_axis_of(const MachineConfig& machine);
void approach_blocks(std::string& out, RestartApproach& a, const MachineConfig& machine, int decimals, double& worst);

}  // namespace nckit::restart_detail
