#include "nckit/interp/arc_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace nckit {

namespace {
constexpr double two_pi = 2.0 * std::numbers::pi;
// End points closer than this in the plane make a full circle (mm).
constexpr double same_point_mm = 1e-9;
}  // namespace

PlaneAxes plane_axes(Plane plane) {
    switch (plane) {
        case Plane::xy:
            return {Axis::X, Axis::Y, Axis::Z};
        case Plane::zx:
            return {Axis::Z, Axis::X, Axis::Y};
        case Plane::yz:
            return {Axis::Y, Axis::Z, Axis::X};
    }
    return {Axis::X, Axis::Y, Axis::Z};
}

double arc_start_radius(const Arc& arc) {
    PlaneAxes p = plane_axes(arc.plane);
    return std::hypot(arc.from[p.first] - arc.center[p.first], arc.from[p.second] - arc.center[p.second]);
}

double arc_end_radius(const Arc& arc) {
    PlaneAxes p = plane_axes(arc.plane);
    return std::hypot(arc.to[p.first] - arc.center[p.first], arc.to[p.second] - arc.center[p.second]);
}

double arc_sweep_rad(const Arc& arc) {
    PlaneAxes p = plane_axes(arc.plane);
    double turns = two_pi * arc.full_turns;
    double chord = std::hypot(arc.to[p.first] - arc.from[p.first], arc.to[p.second] - arc.from[p.second]);
    if (chord < same_point_mm) return two_pi + turns;
    double a0 = std::atan2(arc.from[p.second] - arc.center[p.second], arc.from[p.first] - arc.center[p.first]);
    double a1 = std::atan2(arc.to[p.second] - arc.center[p.second], arc.to[p.first] - arc.center[p.first]);
    double sweep = arc.direction == ArcDirection::counterclockwise ? a1 - a0 : a0 - a1;
    while (sweep <= 0) sweep += two_pi;
    while (sweep > two_pi) sweep -= two_pi;
    return sweep + turns;
}

AxisBox arc_bounds(const Arc& arc) {
    constexpr double angle_eps_rad = 1e-9;
    AxisBox box;
    for (std::size_t i = 0; i < axis_count; ++i) {
        box.low[i] = std::min(arc.from[i], arc.to[i]);
        box.high[i] = std::max(arc.from[i], arc.to[i]);
    }
    PlaneAxes p = plane_axes(arc.plane);
    double radius = std::max(arc_start_radius(arc), arc_end_radius(arc));
    double start = std::atan2(arc.from[p.second] - arc.center[p.second], arc.from[p.first] - arc.center[p.first]);
    double sweep = arc_sweep_rad(arc);
    double sign = arc.direction == ArcDirection::counterclockwise ? 1.0 : -1.0;
    // Visit every quarter-turn angle (where an axis peaks) that the sweep passes.
    for (int k = 0; k < 4; ++k) {
        double extreme = k * std::numbers::pi / 2;
        double travel = sign * (extreme - start);
        travel = std::fmod(travel, two_pi);
        if (travel < 0) travel += two_pi;
        if (travel > sweep) continue;
        // An extreme the arc starts or ends on is already in the box as that end point; taken at
        // the larger radius it would stick out past it when the two radii differ (CAM output
        // rounded to 3-4 decimals), and a G71 shape would seem to turn back there.
        if (travel < angle_eps_rad || travel > sweep - angle_eps_rad) continue;
        double first = arc.center[p.first] + radius * std::cos(extreme);
        double second = arc.center[p.second] + radius * std::sin(extreme);
        box.low[p.first] = std::min(box.low[p.first], first);
        box.high[p.first] = std::max(box.high[p.first], first);
        box.low[p.second] = std::min(box.low[p.second], second);
        box.high[p.second] = std::max(box.high[p.second], second);
    }
    return box;
}

}  // namespace nckit
