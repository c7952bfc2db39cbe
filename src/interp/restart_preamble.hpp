#pragma once
// The pieces of a restart program before the rest of the run (docs/restart.md): the spindle,
// tool and I/O state, the program's frame, the approach. Private to restart.cpp.
#include <string>

#include "nckit/core/machine.hpp"
#include "nckit/interp/move_gcode.hpp"
#include "nckit/interp/restart.hpp"

namespace nckit::restart_detail {

//! Folds one I/O event of the search into the state the preamble switches on again.
void note_io(const Io& io, const MachineConfig& machine, RestartIo& state);
//! "FILE:LINE" of a block, for messages and comments.
[[nodiscard]] std::string location_text(const SourceLocation& where);
[[nodiscard]] const char* plane_code(Plane plane);
void frame_comments(std::string& out, const ModalView& s, const MachineConfig& machine, bool set_again);
//! The rest can be written in the program's own frame, set again as blocks: in one of G54-G59.
[[nodiscard]] bool frame_can_be_set(const ModalView& s);
//! Program coordinates of `s`: origin = work offset + G92 + G52 + tool length offset, with its
//! diameter mode and transforms.
[[nodiscard]] GcodeFrame program_frame(const ModalView& s, const MachineConfig& machine);
//! The blocks that set `s`'s frame again after the approach, with the tool at `point` (machine
//! coordinates; none when nothing moves, then G92 cannot be set): units, the work system and its
//! offset, G52, the tool length offset, G92. Distance mode comes with the last modes block.
void frame_blocks(std::string& out, const ModalView& s, const MachineConfig& machine, const AxisVector* point);
//! The mirror, scaling and rotation in force at the target (after frame_blocks), then a rapid
//! to `point` in their coordinates so that the programmed point is the original run's.
void transform_blocks(std::string& out, const ModalView& s, const MachineConfig& machine, const AxisVector* point);
void io_blocks(std::string& out, const RestartIo& io, const MachineConfig& machine);
[[nodiscard]] Axis retract_axis_of(const MachineConfig& machine);
void approach_blocks(std::string& out, RestartApproach& a, const MachineConfig& machine, int decimals, double& worst);

}  // namespace nckit::restart_detail
