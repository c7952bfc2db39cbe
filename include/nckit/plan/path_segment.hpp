#pragma once
// The geometry of one piece of path, parameterised by its length s: straight lines, circular
// arcs or helices in any plane of XYZ, and quintic transitions. G2/G3 arcs and the planner's
// corner blends share it.
#include <array>

#include "nckit/core/axes.hpp"
#include "nckit/interp/move.hpp"

namespace nckit {

//! quintic: a curvature-continuous transition the planner puts where two pieces of path meet
//! with a corner or a jump in curvature (docs/planner.md); s is then its polynomial parameter,
//! close to but not exactly its arc length.
enum class SegmentShape { line, arc, quintic };

//! position(s) = origin + rate·s + radius·(cos θ·u + sin θ·v) with θ = angle_rate·s, for
//! s in [0, length]; the circular term acts on X, Y, Z only (u, v are XYZ vectors), the linear
//! term on every axis (a line; a helix's axis; rotary and UVW axes along an arc).
//! s is the XYZ arc length; a move without XYZ motion measures UVW, and then ABC (in degrees),
//! as LinuxCNC does. Derivatives w.r.t. s are exact; |position'| is 1 on the measured axes
//! (up to an arc's radius mismatch, which the linear part absorbs).
struct PathSegment {
    SegmentShape shape = SegmentShape::line;
    double length = 0;          //!< mm (deg for a rotary-only move): the range of s
    AxisVector origin;          //!< mm/deg; for arcs the centre on X, Y, Z
    AxisVector rate;            //!< mm (deg) per unit s: the linear part
    std::array<double, 3> u{};  //!< XYZ unit vector from the centre to the start (arcs)
    std::array<double, 3> v{};  //!< XYZ unit vector, ⟂ u, the direction of travel at the start
    double radius_mm = 0;       //!< mm, 0 for lines
    double angle_rate = 0;      //!< rad per unit s (sweep / length), 0 for lines
    //! quintic only: XYZ coefficients of s², s³, s⁴, s⁵ added to origin + rate·s.
    std::array<std::array<double, 3>, 4> poly{};

    //! rad, the angle the arc sweeps (0 for lines).
    [[nodiscard]] double sweep_rad() const { return angle_rate * length; }
};

//! Position and its exact derivatives w.r.t. s at one s.
struct PathPoint {
    AxisVector position;  //!< mm/deg
    AxisVector d1;        //!< dq/ds
    AxisVector d2;        //!< d²q/ds²
    AxisVector d3;        //!< d³q/ds³
};

[[nodiscard]] AxisVector position_at(const PathSegment& segment, double s);
[[nodiscard]] PathPoint point_at(const PathSegment& segment, double s);
[[nodiscard]] inline AxisVector start_point(const PathSegment& segment) {
    return position_at(segment, 0.0);
}
[[nodiscard]] inline AxisVector end_point(const PathSegment& segment) {
    return position_at(segment, segment.length);
}

//! For every axis, bounds over the whole segment of |dq/ds|, |d²q/ds²|, |d³q/ds³|, and of the
//! speed factor |p'| on the measured axes (the programmed feed applies to ṡ·|p'|).
struct DerivativeBounds {
    AxisVector d1;
    AxisVector d2;
    AxisVector d3;
    double speed_factor = 1;
};
[[nodiscard]] DerivativeBounds derivative_bounds(const PathSegment& segment);

//! Moves whose measured length is not above this (mm, or deg for rotary-only moves) do not move
//! the machine: the planner makes no trajectory piece of them.
inline constexpr double min_move_length = 1e-9;

//! The path length of a displacement: XYZ, else UVW, else ABC in degrees (LinuxCNC's rule).
[[nodiscard]] double measured_length(const AxisVector& displacement);

//! A straight line; length 0 (and a zero rate) when the points coincide.
[[nodiscard]] PathSegment make_line(const AxisVector& from, const AxisVector& to);

//! A G2/G3 arc or helix, full turns included. It starts exactly at arc.from; its end is arc.to
//! up to rounding (a radius mismatch between start and end becomes a small linear in-plane part).
[[nodiscard]] PathSegment make_arc(const Arc& arc);

//! The quintic of length `length` (> 0) with the given position, first and second derivative
//! w.r.t. s at both ends (quintic Hermite interpolation on XYZ). Every other axis moves at
//! `other_rate` per unit s from start.position.
[[nodiscard]] PathSegment make_quintic(const PathPoint& start, const PathPoint& end, double length,
                                       const AxisVector& other_rate);

//! The segment without its first `trim` of s (0 <= trim <= length; lines, arcs and quintics).
[[nodiscard]] PathSegment trim_start(const PathSegment& segment, double trim);

//! A circular arc of XYZ through `start` with the given centre, starting along unit `tangent`
//! and sweeping sweep_rad, with the other axes moving at `other_rate` per mm (used for blends).
[[nodiscard]] PathSegment make_circular(const AxisVector& start, const std::array<double, 3>& centre,
                                        const std::array<double, 3>& tangent, double sweep_rad,
                                        const AxisVector& other_rate);

}  // namespace nckit
