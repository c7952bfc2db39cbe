#pragma once
// Derivative bounds of a quintic transition segment (path_segment.hpp's derivative_bounds).
#include "nckit/plan/path_segment.hpp"

namespace nckit {

//! Bounds over s in [0, length] of |q'|, |q''|, |q'''| per axis and of |p'| on XYZ. q''' is
//! quadratic and q'' cubic: their extremes (ends, vertex, roots of q''') are exact; q' and |p'|
//! are sampled and padded by the largest slope times half the sample spacing, so no bound is
//! below the true maximum.
[[nodiscard]] DerivativeBounds quintic_bounds(const PathSegment& segment);

}  // namespace nckit
