#pragma once
// Plane geometry of cutter radius compensation: offsets of lines and arcs, the kind of corner
// two of them make for a tool on one side, and where their offsets meet in an inside corner.
// Coordinates are the plane's (first, second) axes; "left" is counter-clockwise from the motion.
#include <cmath>
#include <optional>

#include "nckit/core/vec2.hpp"
#include "nckit/interp/arc_geometry.hpp"

namespace nckit::interp::comp {

//! A machine position's coordinates in the plane, and the position with them replaced.
[[nodiscard]] inline Vec2 in_plane(const AxisVector& v, PlaneAxes p) {
    return {v[p.first], v[p.second]};
}
inline void set_in_plane(AxisVector& v, PlaneAxes p, Vec2 point) {
    v[p.first] = point.x;
    v[p.second] = point.y;
}

//! An arc's turn in its plane: +1 counter-clockwise, -1 clockwise.
[[nodiscard]] inline int turn_of(const Arc& arc) {
    return arc.direction == ArcDirection::counterclockwise ? 1 : -1;
}

//! A programmed or compensated element in the plane.
struct Segment {
    bool arc = false;
    Vec2 start;
    Vec2 end;
    Vec2 center;   //!< arcs only
    int turn = 0;  //!< arcs: +1 counter-clockwise, -1 clockwise
};

//! Unit tangent of the motion at the start and at the end.
[[nodiscard]] Vec2 start_tangent(const Segment& s);
[[nodiscard]] Vec2 end_tangent(const Segment& s);

//! side: +1 left (G41), -1 right (G42). An arc is cut from inside when it turns toward the tool.
[[nodiscard]] inline bool tool_inside(const Segment& arc, int side) {
    return side * arc.turn > 0;
}

//! Radii closer than this are the same (mm): an inside arc of the tool's radius.
inline constexpr double same_radius_mm = 1e-6;

//! The segment moved r to `side`: a line shifts along its normal, an arc keeps its centre and
//! its radius grows or shrinks by r. An inside arc of radius r shrinks to its centre (both ends
//! on it); nothing when an inside arc's radius is smaller than r.
[[nodiscard]] std::optional<Segment> offset(const Segment& s, int side, double r);

//! An offset arc shrunk to its centre at either end (offset() of an arc of the tool's radius).
[[nodiscard]] inline bool shrunk_to_center(const Segment& s) {
    return s.arc && (s.start == s.center || s.end == s.center);
}

enum class Corner { tangent, outside, inside };

//! Corners within this angle of tangent are taken as tangent, as LinuxCNC does (rad).
inline constexpr double corner_tolerance_rad = 0.05;

//! The corner the tool meets going from a to b (which start where a ends). A reversal is an
//! outside corner, except where the tool follows an arc on its outside into it (b an arc, or
//! a line after such an arc): then the tool stays on its side of the reversal, as LinuxCNC does.
[[nodiscard]] Corner classify(const Segment& a, const Segment& b, int side);

//! Where the offset elements a_off and b_off cross nearest the programmed corner; nothing when
//! they do not cross (the tool cannot reach into the corner without cutting the contour).
[[nodiscard]] std::optional<Vec2> inside_corner(const Segment& a_off, const Segment& b_off, Vec2 corner);

//! Shortest distance from p to the element (a line segment, or an arc between its ends).
[[nodiscard]] double distance_to(Vec2 p, const Segment& s);

//! Angle an arc sweeps from `from` to `to` about `center` in direction turn, rad, in (0, 2π].
[[nodiscard]] double sweep_rad(Vec2 from, Vec2 to, Vec2 center, int turn);

}  // namespace nckit::interp::comp
