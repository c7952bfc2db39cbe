#pragma once
// Plots of a piston job as plain SVG text: the section as piston drawings show it, the drawing's
// D and E along Z, and the three runs' error turn by turn.
#include <string>

#include "nckit/process/piston/piston_job.hpp"
#include "nckit/process/fts/fast_tool_servo.hpp"

namespace nckit {

//! Polar plot of the section at every station: a base circle standing for the major radius D/2,
//! each station's radial deviation r(φ) − D/2 drawn out from it magnified (the factor stated on
//! the plot, a 1-2-5 value), rings at round deviations, the major (φ = 0°) and minor (φ = 90°)
//! axes marked; the middle station drawn heavier.
[[nodiscard]] std::string piston_section_svg(const cam::PistonJob& job);

//! D(Z) and E(Z) in two panels over the stations' Z range: the stations as points, the curve
//! the drawing defines between them (spline or formula) as a line.
[[nodiscard]] std::string piston_drawing_svg(const cam::PistonJob& job);

//! Peak to valley of the error within each turn for the three runs (log scale), with the turn
//! where the tool engages after `air_turns` marked.
[[nodiscard]] std::string piston_turn_error_svg(const FtsSimulation& simulation, int air_turns);

}  // namespace nckit
