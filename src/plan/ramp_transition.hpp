#pragma once
// Transitions with a curvature ramp (docs/planner.md, "Ramp transitions"): where two tangent
// pieces of path in one plane meet with a jump in curvature (arcs turning opposite ways, a line
// into an arc), one quintic from side to side must curve more than the arcs near its ends to come
// back onto the path, and that overshoot caps the speed. Here the curve follows the programmed
// path a little inside it (its curvature slightly above the arc's, eased in), and changes the
// curvature linearly over a short ramp at the join: a chain of quintics, each matching position,
// direction and curvature at its ends.
#include "nckit/core/machine.hpp"
#include "transition.hpp"

namespace nckit::plan_detail {

//! The ramp transition between `before` and `after` (each trimmed by at most its room, the same
//! rule as make_transition), with its deviation from the programmed path measured within
//! tolerance_mm; false when the join is not one it handles (not tangent within 2e-3 rad, not in
//! one plane, a helix, two lines, no curvature jump) or no ramp keeps the tolerance.
[[nodiscard]] bool make_ramp_transition(const PathSegment& before, double before_room, const PathSegment& after,
                                        double after_room, double tolerance_mm, const TurningLimits& limits,
                                        Transition& out);

//! A share of the jerk the turning may take at constant path speed (the rest is left for the
//! path's own acceleration and jerk), for comparing transitions.
inline constexpr double turning_jerk_share = 0.8;

//! The lowest speed (mm/s) the transition's curves allow at constant path speed: the minimum
//! over sampled points and axes of sqrt(amax/|q''|) and cbrt(turning_jerk_share·jmax/|q'''|).
[[nodiscard]] double turning_speed(const Transition& transition, const TurningLimits& limits);

//! The machine's X, Y, Z limits; an axis the machine lacks cannot move (check_axes), so it
//! limits nothing (infinite).
[[nodiscard]] TurningLimits turning_limits(const MachineConfig& machine);

}  // namespace nckit::plan_detail
