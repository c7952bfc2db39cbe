#pragma once
// Limits along a path segment that provably keep every axis within its machine limits.
#include "nckit/core/machine.hpp"
#include "nckit/plan/path_segment.hpp"
#include "nckit/plan/profile.hpp"

namespace nckit::plan_detail {

//! For axis i with bounds d1, d2, d3 on |q'|, |q''|, |q'''| over the segment (derivative_bounds)
//! the axis moves with q̇ = q'ṡ, q̈ = q''ṡ² + q's̈, q⃛ = q'''ṡ³ + 3q''ṡs̈ + q's⃛, so by the
//! triangle inequality it stays within (vmax, amax, jmax) when
//!   d1·v ≤ vmax;
//!   curved (d2 > 0): d2·v² ≤ amax/2 and d1·a ≤ amax/2   (a straight axis: d1·a ≤ amax);
//!   curved: d3·v³ ≤ jmax/3, 3·d2·v·a ≤ jmax/3, d1·j ≤ jmax/3 (straight: d1·j ≤ jmax),
//! with v, a, j the path's speed, acceleration and jerk limits. The profile keeps |ṡ| ≤ v,
//! |s̈| ≤ a and |s⃛| ≤ j at every instant, so each term stays within its share. Trapezoids have
//! no jerk limit (their jerk is infinite at phase switches), so only v and a apply.
//! feed_mm_s is the programmed speed (already overridden); +infinity for rapids. Axes the
//! machine lacks must not move (unchecked here). Returns max_velocity 0 when nothing moves.
[[nodiscard]] ProfileLimits segment_limits(const PathSegment& segment, const MachineConfig& machine,
                                           double feed_mm_s, ProfileKind kind);

}  // namespace nckit::plan_detail
