#pragma once
// Quintic transition segments: built in place, and the bounds of their derivatives
// (path_segment.hpp's make_quintic and derivative_bounds).
#include "nckit/plan/path_segment.hpp"

namespace nckit {

//! make_quintic written into `segment` (every field set): a planner that builds a transition per
//! move saves building a value and copying it.
void write_quintic(PathSegment& segment, const PathPoint& start, const PathPoint& end, double length,
                   const AxisVector& other_rate);

//! Bounds over s in [0, length] of |q'|, |q''|, |q'''| per axis and of |p'| on XYZ. q''' is
//! quadratic and q'' cubic: their extremes (ends, vertex, roots of q''') are exact; q' and |p'|
//! are sampled and padded by the largest slope times half the sample spacing, so no bound is
//! below the true maximum.
[[nodiscard]] DerivativeBounds quintic_bounds(const PathSegment& segment);

}  // namespace nckit
