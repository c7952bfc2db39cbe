#pragma once
// Geometry of G2/G3 arcs in their plane, shared by the interpreter and the stages after it.
#include "nckit/core/axes.hpp"
#include "nckit/interp/move.hpp"

namespace nckit {

//! The plane's first and second axes (counter-clockwise runs from first toward second when
//! looking down the normal axis) and the normal axis: G17 X,Y,Z; G18 Z,X,Y; G19 Y,Z,X.
struct PlaneAxes {
    Axis first;
    Axis second;
    Axis normal;
};

[[nodiscard]] PlaneAxes plane_axes(Plane plane);

//! Radius at the start of the arc, mm.
[[nodiscard]] double arc_start_radius(const Arc& arc);
//! Radius at the end of the arc, mm (differs from the start radius by at most the tolerance).
[[nodiscard]] double arc_end_radius(const Arc& arc);

//! Angle swept from start to end in the arc's direction, rad, in (0, 2π]; a whole turn when
//! the end lies on the start in the plane; full_turns more turns on top.
[[nodiscard]] double arc_sweep_rad(const Arc& arc);

//! Smallest box holding the whole arc, every axis (the arc bulges past its end points).
struct AxisBox {
    AxisVector low;
    AxisVector high;
};
[[nodiscard]] AxisBox arc_bounds(const Arc& arc);

}  // namespace nckit
