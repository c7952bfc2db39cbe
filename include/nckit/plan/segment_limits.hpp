#pragma once
// Limits along a path segment that provably keep every axis within its machine limits: what the
// planner gives each segment, and what a process generator needs to predict the planner.
#include "nckit/core/machine.hpp"
#include "nckit/plan/path_segment.hpp"
#include "nckit/plan/profile.hpp"

namespace nckit {

//! The most of an axis's acceleration the curvature term d2·v² may take (the rest, at least a
//! tenth, is left to the path acceleration, so a > 0 on every segment).
inline constexpr double max_normal_share = 0.9;
//! The normal share of a corner blend's arc in a trapezoid plan. A blend is short and sits
//! where the path is slowest: its speed is what the corner costs, and the tangential share
//! matters little (speed changes happen on the lines around it), so it gets most of amax
//! (LinuxCNC gives its blends sqrt(1 - 0.5²) ≈ 0.87 of a in the normal direction). With jerk
//! limits the fixed half stays (a small tangential share would slow the jerk phases on it).
inline constexpr double trapezoid_blend_normal_share = 0.9;

//! For axis i with bounds d1, d2, d3 on |q'|, |q''|, |q'''| over the segment (derivative_bounds,
//! over the segment's own extent) the axis moves with q̇ = q'ṡ, q̈ = q''ṡ² + q's̈,
//! q⃛ = q'''ṡ³ + 3q''ṡs̈ + q's⃛, so by the triangle inequality it stays within (vmax, amax, jmax)
//! whenever the path's speed, acceleration and jerk limits v, a, j satisfy, for every axis,
//!   d1·v <= vmax,   d2·v² + d1·a <= amax,   d3·v³ + 3·d2·v·a + d1·j <= jmax.
//! The profile keeps |ṡ| <= v, |s̈| <= a and |s⃛| <= j at every instant. The budget is split per
//! segment: v first (feed, axis speeds, d2·v² <= normal_share·amax, d3·v³ <= jmax/3), then a
//! takes what d2·v² leaves (>= (1 − normal_share)·amax, all of amax on a straight axis), then j
//! what the rest leaves, the coupling term taking at most half of it (so d1·j >= jmax/3).
//! With the default normal_share of 1/2 every limit is thus at least what fixed shares (amax/2
//! and jmax/3 for each term) give. normal_share is clamped into [0, max_normal_share].
//! Trapezoids have no jerk limit (their jerk is infinite at phase switches): only v and a apply.
//! feed_mm_s is the programmed speed (already overridden); +infinity for rapids. Axes the
//! machine lacks must not move (unchecked here). Returns max_velocity 0 when nothing moves.
[[nodiscard]] ProfileLimits segment_limits(const PathSegment& segment, const MachineConfig& machine, double feed_mm_s,
                                           ProfileKind kind, double normal_share = 0.5);

}  // namespace nckit
