#pragma once
// What happens where two path segments meet: pass at speed (tangent), round the corner with a
// blend arc (two straight lines under G64), or stop.
#include <optional>

#include "nckit/plan/path_segment.hpp"

namespace nckit::plan_detail {

//! Two segments are tangent when their direction vectors dq/ds (all axes) at the junction differ
//! by at most this, per axis (for unit directions: a turning angle up to about 1e-6 rad). Passing
//! such a junction at speed v jumps each axis's velocity by at most 1e-6·v, e.g. 1e-4 mm/s at
//! 100 mm/s: spread over a 1 ms servo period that is 0.1 mm/s², nothing against any machine's
//! limits; and it is a million times the rounding of arc end points computed from centres
//! (~1e-12), so G2/G3 arcs joined tangentially by the CAM are seen as tangent.
inline constexpr double tangent_tolerance = 1e-6;

//! Reversals (turning angle above π minus this) are not blended: the arc would be a point.
inline constexpr double reversal_margin_rad = 1e-6;
//! Blend arcs smaller than this radius (mm) are not worth their numerics: stop instead.
inline constexpr double min_blend_radius_mm = 1e-6;

[[nodiscard]] bool tangent(const PathSegment& before, const PathSegment& after);

struct Blend {
    PathSegment arc;          //!< from before's new end to after's new start, tangent to both
    double trim_mm = 0;       //!< mm cut from before's end and from after's start
    double deviation_mm = 0;  //!< mm, distance of the arc's midpoint from the corner
};

//! The blend of a corner between two lines whose measured length is XYZ and whose other axes
//! move at the same rate along both (else none). The trim is at most half of either line's
//! programmed length (before_full_mm for `before`, which may already be trimmed at its start
//! by up to half of it; `after` untrimmed), and the arc's deviation is at most tolerance_mm:
//! R = tol / (1/cos(φ/2) − 1), trim = R·tan(φ/2), for turning angle φ.
[[nodiscard]] std::optional<Blend> blend_lines(const PathSegment& before, double before_full_mm,
                                               const PathSegment& after, double tolerance_mm);

//! A trapezoid corner between the same lines as blend_lines, as the parabola
//! q(s) = P0 + d1·s + ½·K·s², K = (d2 − d1)/(2·trim), s in [0, 2·trim] (shape quintic, only
//! its s² term non-zero), from `trim` before the corner to `trim` after it. At constant ṡ every
//! axis accelerates at K_i·ṡ², constant over the whole corner: the axis that stops brakes while
//! the one that starts speeds up, over the same time, instead of a circle handing the turning
//! from one axis to the other. Its midpoint is trim·|d2 − d1|/4 from the corner and the rest
//! is nearer, so trim = 4·tol/|d2 − d1| = 2·tol/sin(φ/2), at most half of either line.
//! Per axis |K_i| <= sin²(φ/2)/(2·tol), never above a circle's 1/R = (1/cos(φ/2) − 1)/tol
//! at the same deviation (a 90° corner: 17.7 against 41.4 /mm at tol 0.01 mm).
[[nodiscard]] std::optional<Blend> parabolic_corner(const PathSegment& before, double before_full_mm,
                                                    const PathSegment& after, double tolerance_mm);

}  // namespace nckit::plan_detail
