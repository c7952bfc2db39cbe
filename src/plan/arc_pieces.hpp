#pragma once
// Arcs whose speed is set by their curvature, cut into short pieces with limits of their own, so
// the planned speed follows the time-optimal limit along the arc (docs/planner.md, "Speed along
// an arc").
#include <vector>

#include "nckit/core/machine.hpp"
#include "nckit/plan/path_segment.hpp"
#include "nckit/plan/profile.hpp"

namespace nckit::plan_detail {

//! One piece of an arc and its (v, a) limits: every axis keeps d1·v <= vmax and
//! d2·v² + d1·a <= amax with the derivative bounds over the piece itself.
struct ArcPiece {
    PathSegment path;
    ProfileLimits limits;
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

}  // namespace nckit::plan_detail
