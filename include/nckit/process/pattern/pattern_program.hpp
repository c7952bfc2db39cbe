#pragma once
// The NC program of one sole: absolute coordinates in mm from the reference hole (X0 Y0, where
// the tool is set), the plate surface at Z0, grooves as feed moves below it and air moves as
// rapids above it. Everything runs under G61 (each move ends at rest, so the planner's times are
// the rest-to-rest times the order was chosen by); spline grooves run their inner vertices under
// G64 P (within the chord tolerance) and stop at their end. Each groove starts on a whole motor
// step (absolute rounding per curve: the start is round(x·spu)/spu, so no rounding is carried
// from one curve to the next), and a clipped end stays where the border cuts it.
#include <string>
#include <vector>

#include "nckit/core/machine.hpp"
#include "nckit/process/pattern/cut_order.hpp"
#include "nckit/process/pattern/pattern_job.hpp"
#include "nckit/process/pattern/pattern_layout.hpp"

namespace nckit::pattern {

//! A groove as the program cuts it: the start on whole steps, the path adjusted to it.
struct ProgramCut {
    PlaneCurve curve;
    double depth_mm = 0;
};

//! The cuts in `tour` order and direction, each start moved onto the step grid of X and Y
//! (a line keeps its end; an arc keeps its end and takes the centre on the perpendicular bisector
//! nearest the old one, so start and end radii agree exactly; a spline moves its first piece).
[[nodiscard]] std::vector<ProgramCut> program_cuts(const SoleLayout& layout, const Tour& tour,
                                                   const MachineConfig& machine);

//! Chord tolerance of spline grooves, mm.
inline constexpr double spline_chord_tolerance_mm = 0.005;

//! The program text. `title` goes into the first comment.
[[nodiscard]] std::string pattern_program(const std::vector<ProgramCut>& cuts, const PatternJob& job,
                                          const std::string& title);

}  // namespace nckit::pattern
