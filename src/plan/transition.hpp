#pragma once
// Curvature-continuous transitions where two pieces of path meet with a corner or a jump in
// curvature: a quintic that leaves `before` and joins `after` with the same position, direction
// and curvature vector, so the axes' velocity and acceleration stay continuous through it at any
// speed, and that stays within the path tolerance of the programmed path.
#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "nckit/plan/path_segment.hpp"

namespace nckit::plan_detail {

//! trim_start(g, trim) written to `out` (which may be g): a line is copied at most once (the value
//! trim_start returns would be copied again).
void trim_start_into(PathSegment& out, const PathSegment& g, double trim);

//! The join passes at speed without a transition: directions (dq/ds, every axis) equal within
//! direction_tolerance, and, when `curvature_too`, curvature vectors (d²q/ds²) within
//! curvature_tolerance (1/mm).
[[nodiscard]] bool smooth_join(const PathSegment& before, const PathSegment& after, double direction_tolerance,
                               bool curvature_too);

//! A direction step of 1e-9 at 100 mm/s changes the velocity by 1e-7 mm/s: differenced over a
//! 0.1 ms trace period that is a jerk of 10 mm/s³. A curvature step of 1e-7/mm at 100 mm/s
//! steps the acceleration by 1e-3 mm/s², the same jerk. Both are far below any jerk limit.
inline constexpr double smooth_direction_tolerance = 1e-9;
inline constexpr double smooth_curvature_tolerance = 1e-7;

struct Transition {
    PathSegment curve;              //!< quintic from before's new end to after's new start (or the first of a chain)
    std::vector<PathSegment> more;  //!< a ramp transition's further quintics, in order (ramp_transition.hpp)
    double trim_before = 0;         //!< s cut from before's end
    double trim_after = 0;          //!< s cut from after's start
    double deviation_mm = 0;        //!< mm, largest distance of the curve from the programmed path found
    PathPoint start;                //!< the state the curve leaves from (on before)
    PathPoint end;                  //!< and arrives at (on after)
    PathSegment replaced_before;    //!< the programmed path it replaces: before's tail,
    PathSegment replaced_after;     //!< and after's head
    bool chained = false;           //!< starts with a ChainStart's curvature (make_transition)
};

//! Rebuilds the transition to end at `end_position` with the given direction and curvature
//! vectors (XYZ; dq/ds and d²q/ds²), when it still keeps within tolerance_mm; false leaves it as
//! it was. A chain of transitions that eats whole short lines (a CAM polyline) meets at the
//! lines' middles; there the two transitions may agree on any state. With the direction of the
//! chord through the neighbouring joins and the curvature of the turn between them (instead of
//! the line's own direction and 0), the chain follows the curve the polyline samples, and its
//! speed is set by that curve's radius rather than by a curvature pulse at every vertex and the
//! rounding noise of the written decimals. The start state stays.
[[nodiscard]] bool rebuild_with_end_state(Transition& transition, const std::array<double, 3>& end_position,
                                          const std::array<double, 3>& end_d1, const std::array<double, 3>& end_d2,
                                          double tolerance_mm);
//! The same transition with the direction and curvature vectors at both ends replaced (its end
//! points stay), when it still keeps within tolerance_mm: for a chain that starts from rest or
//! ends at a stop (pending_motion.cpp), where the start state changes too.
struct Rebuilt {
    PathSegment curve;
    PathPoint start;
    PathPoint end;
    double deviation_mm = 0;
};
[[nodiscard]] std::optional<Rebuilt> with_end_states(const Transition& transition,
                                                     const std::array<double, 3>& start_d1,
                                                     const std::array<double, 3>& start_d2,
                                                     const std::array<double, 3>& end_d1,
                                                     const std::array<double, 3>& end_d2, double tolerance_mm);
//! The transition takes the rebuilt curve and end states.
void apply(Transition& transition, const Rebuilt& rebuilt);

//! The transition that trims at most before_room from before's end and after_room from
//! after's start (a leftover of before shorter than min_leftover_mm is taken whole), as long
//! as its deviation stays within tolerance_mm; none when the axes beyond XYZ move, when the
//! measured axes are not XYZ, or when no trim long enough fits the tolerance.
//! The transition into `before`, when there is one: a chain of transitions that eats whole
//! short lines (a CAM polyline) meets at the lines' middles, where the two may agree on any
//! state. With the curvature of the turn between their outer ends, (q'_out - q'_in) / (L1 + L2),
//! instead of the line's own 0, the chain follows the curve the polyline samples, and its speed
//! is set by that curve's radius rather than by a curvature pulse at every vertex.
struct ChainStart {
    double entry_length = 0;                 //!< L1, the parameter length of the transition into before
    std::array<double, 3> entry_start_d1{};  //!< q'_in, its direction where it leaves the move before
};

//! The axes' acceleration (mm/s²) and jerk (mm/s³) limits on X, Y, Z, by which a jerk-limited
//! plan chooses between the single quintic and a ramp transition (ramp_transition.hpp).
struct TurningLimits {
    std::array<double, 3> max_acceleration{};
    std::array<double, 3> max_jerk{};
};

//! The transition is written to `out` (which it leaves undefined when there is none). With
//! `chain`, when `before` is eaten whole, the curve first tries to start with the chain's
//! curvature (out.chained tells whether it does; the transition into before must then be rebuilt
//! to end in out.start's state, rebuild_with_end_state). With `turning` (jerk-limited plans), a tangent
//! join of an arc whose curvature jumps also gets a ramp transition (ramp_transition.hpp), kept
//! when its curves allow a higher speed (turning_speed) than the single quintic's.
[[nodiscard]] bool make_transition(const PathSegment& before, double before_room, const PathSegment& after,
                                   double after_room, double tolerance_mm, Transition& out,
                                   const ChainStart* chain = nullptr, const TurningLimits* turning = nullptr);

//! How far the curve strays from the path `replaced` (its replaced_before and replaced_after):
//! the largest distance found over 33 points of the curve (sampling stops once it exceeds
//! stop_above_mm), and the smallest |dp/ds| among them.
struct CurveDeviation {
    double deviation_mm = 0;
    double slowest = 0;
};
[[nodiscard]] CurveDeviation measure_deviation(const PathSegment& curve, const Transition& replaced,
                                               double stop_above_mm);
//! The same over `count` curves (a ramp transition's chain), measured against the path once cut.
[[nodiscard]] CurveDeviation measure_deviation(const PathSegment* curves, std::size_t count, const Transition& replaced,
                                               double stop_above_mm);

//! Pieces of path left between transitions shorter than this (mm) join the transition.
inline constexpr double min_leftover_mm = 1e-3;

}  // namespace nckit::plan_detail
