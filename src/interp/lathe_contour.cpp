#include "lathe_contour.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "nckit/interp/arc_geometry.hpp"

namespace nckit::interp {

namespace {
constexpr double two_pi = 2.0 * std::numbers::pi;
constexpr double on_arc_rad = 1e-9;

double angle_in_plane(const Arc& arc, const AxisVector& point) {
    PlaneAxes p = plane_axes(arc.plane);
    return std::atan2(point[p.second] - arc.center[p.second], point[p.first] - arc.center[p.first]);
}

//! How far along the arc (from its start, in its direction) the angle lies, rad in [0, 2π).
double angle_from_start(const Arc& arc, double angle) {
    double start = angle_in_plane(arc, arc.from);
    double delta = arc.direction == ArcDirection::counterclockwise ? angle - start : start - angle;
    delta = std::fmod(delta, two_pi);
    return delta < 0 ? delta + two_pi : delta;
}
}  // namespace

std::optional<AxisVector> move_start(const Move& move) {
    if (const auto* line = std::get_if<Line>(&move.what)) return line->from;
    if (const auto* arc = std::get_if<Arc>(&move.what)) return arc->from;
    return std::nullopt;
}

std::optional<AxisVector> move_end(const Move& move) {
    if (const auto* line = std::get_if<Line>(&move.what)) return line->to;
    if (const auto* arc = std::get_if<Arc>(&move.what)) return arc->to;
    return std::nullopt;
}

Move shifted(const Move& move, const AxisVector& shift) {
    Move out = move;
    if (auto* line = std::get_if<Line>(&out.what)) {
        line->from = line->from + shift;
        line->to = line->to + shift;
    } else if (auto* arc = std::get_if<Arc>(&out.what)) {
        arc->from = arc->from + shift;
        arc->to = arc->to + shift;
        arc->center = arc->center + shift;
    }
    return out;
}

std::vector<double> level_crossings(const Move& element, ContourAxes axes, double level) {
    std::vector<double> found;
    if (const auto* line = std::get_if<Line>(&element.what)) {
        const double d0 = line->from[axes.depth];
        const double d1 = line->to[axes.depth];
        if ((level - d0) * (level - d1) > 0) return found;
        if (d0 == d1) return {line->from[axes.length], line->to[axes.length]};
        const double t = (level - d0) / (d1 - d0);
        found.push_back(line->from[axes.length] + t * (line->to[axes.length] - line->from[axes.length]));
        return found;
    }
    const auto* arc = std::get_if<Arc>(&element.what);
    if (arc == nullptr) return found;
    const double radius = arc_start_radius(*arc);
    const double offset = level - arc->center[axes.depth];
    if (std::abs(offset) > radius) return found;
    const double half = std::sqrt(std::max(0.0, radius * radius - offset * offset));
    const double sweep = arc_sweep_rad(*arc);
    std::vector<std::pair<double, double>> on_arc;  // (angle from the start, length)
    for (double sign : {-1.0, 1.0}) {
        AxisVector point = arc->center;
        point[axes.depth] = level;
        point[axes.length] = arc->center[axes.length] + sign * half;
        double delta = angle_from_start(*arc, angle_in_plane(*arc, point));
        if (delta > two_pi - on_arc_rad) delta = 0;
        if (delta <= sweep + on_arc_rad) on_arc.emplace_back(delta, point[axes.length]);
    }
    std::sort(on_arc.begin(), on_arc.end());
    for (const auto& [delta, length] : on_arc) found.push_back(length);
    return found;
}

std::optional<double> level_crossing(const Move& element, ContourAxes axes, double level) {
    // The first crossing in the element's direction (a line along the level: its start).
    const std::vector<double> found = level_crossings(element, axes, level);
    if (found.empty()) return std::nullopt;
    return found.front();
}

std::optional<double> depth_at(const std::vector<Move>& shape, ContourAxes axes, double length) {
    const ContourAxes across{axes.length, axes.depth};
    for (const Move& element : shape) {
        if (auto d = level_crossing(element, across, length)) return d;
    }
    return std::nullopt;
}

Extent extent_along(const Move& element, Axis axis) {
    if (const auto* arc = std::get_if<Arc>(&element.what)) {
        AxisBox box = arc_bounds(*arc);
        return Extent{box.low[axis], box.high[axis]};
    }
    auto from = move_start(element);
    auto to = move_end(element);
    if (!from || !to) return Extent{};
    return Extent{std::min((*from)[axis], (*to)[axis]), std::max((*from)[axis], (*to)[axis])};
}

}  // namespace nckit::interp
