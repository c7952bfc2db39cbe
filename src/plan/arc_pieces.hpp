#pragma once
// Arcs whose speed is set by their curvature, cut into short pieces with limits of their own, so
// the planned speed follows the time-optimal limit along the arc (docs/planner.md, "Speed along
// an arc").
#include <vector>

#include "cruise_raise.hpp"
#include "nckit/core/machine.hpp"
#include "nckit/plan/path_segment.hpp"
#include "nckit/plan/profile.hpp"

namespace nckit::plan_detail {

//! One piece of an arc and its (v, a) limits: every axis keeps d1·v <= vmax and
//! d2·v² + d1·a <= amax with the derivative bounds over the piece itself.
struct ArcPiece {
    PathSegment path;
    ProfileLimits limits;
    PieceCheck check;  //!< jerk-limited pieces: what the raise of a run may use (cruise_raise.hpp)
};

//! Pieces of a full turn: 256, i.e. about 1.4° each (the speed limit varies by at most about
//! 1.2 % over one piece on a circle in a plane of two equal axes).
inline constexpr int arc_pieces_per_turn = 256;
//! Most pieces one arc is cut into (a helix of many turns gets longer pieces).
inline constexpr int max_arc_pieces = 1024;

//! Trapezoid plans only. Cuts `arc` (shape arc) into pieces when its curvature term at the
//! feed takes more than a tenth of some axis's acceleration, and chooses each piece's speed
//! limit so that its acceleration limit still lets the speed follow the neighbouring pieces'
//! (forward and backward passes over the pieces, from rest when starts_at_rest / ends_at_rest).
//! Returns false (out untouched) when the arc is better left whole.
[[nodiscard]] bool split_arc(const PathSegment& arc, const MachineConfig& machine, double feed_mm_s,
                             bool starts_at_rest, bool ends_at_rest, std::vector<ArcPiece>& out);

//! What every piece of a jerk-limited arc keeps for the path's own acceleration and jerk (the
//! same on all pieces of an arc): shares of each axis's limits, chosen by measurement on the
//! planner benchmark programs (docs/planner.md, "Speed along an arc (S-curve)").
inline constexpr double jerk_limited_acceleration_share = 0.35;
inline constexpr double jerk_limited_jerk_share = 0.4;
//! The same for the pieces of a transition quintic next to an arc. A transition is short and
//! its run mostly holds the speed between two arcs, so smaller shares raise its speed limit
//! where it counts; its speed changes are bells, which the pieces' axes check, not these shares
//! (docs/planner.md, "Ramp transitions" and "Bells").
inline constexpr double transition_acceleration_share = 0.12;
inline constexpr double transition_jerk_share = 0.12;
//! At most this share of an axis's jerk goes to the coupling term 3·d2·v·a.
inline constexpr double jerk_limited_coupling_share = 0.6;

//! S-curve plans only. Cuts `arc` into pieces as split_arc does, when the limits of the whole
//! arc (segment_limits) keep it below its feed. Every piece gets the same path acceleration a and jerk j (shares of the
//! axes', so that neighbouring pieces share one S-curve run in the look-ahead) and the highest
//! speed v that its own derivative bounds allow with them:
//! d1·v <= vmax, d2·v² + d1·a <= amax and d3·v³ + 3·d2·v·a + d1·j <= jmax on every axis.
//! Returns false when the arc is better left whole (out is then not to be used).
[[nodiscard]] bool split_arc_jerk_limited(const PathSegment& arc, const MachineConfig& machine, double feed_mm_s,
                                          std::vector<ArcPiece>& out);

//! Pieces a jerk-limited transition next to an arc is cut into (split_transition_jerk_limited).
inline constexpr int transition_pieces = 32;

//! S-curve plans only. Cuts a quintic transition (make_transition) into transition_pieces pieces
//! with limits of their own, by the same rule as split_arc_jerk_limited: where it joins arcs
//! turning opposite ways its curvature runs from one arc's through 0 to the other's, and the
//! pieces let the speed follow what each part allows instead of the whole curve's worst case.
//! `pieces` overrides the count (a ramp transition's quintics share the pieces by length).
[[nodiscard]] bool split_transition_jerk_limited(const PathSegment& curve, const MachineConfig& machine,
                                                 double feed_mm_s, std::vector<ArcPiece>& out,
                                                 int pieces = transition_pieces);

}  // namespace nckit::plan_detail
