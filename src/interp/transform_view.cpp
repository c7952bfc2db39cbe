// Mirror, scale and rotation of programmed points (Fanuc G51.1, G51, G68) and their inverse.
#include "nckit/interp/transform_view.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "nckit/interp/arc_geometry.hpp"

namespace nckit {

namespace {

//! Turns q by `deg` about (first, second) in `plane`.
void rotate(AxisVector& q, Plane plane, double first, double second, double deg) {
    const PlaneAxes axes = plane_axes(plane);
    const double angle = deg * std::numbers::pi / 180.0;
    const double c = std::cos(angle), s = std::sin(angle);
    const double u = q[axes.first] - first, v = q[axes.second] - second;
    q[axes.first] = first + c * u - s * v;
    q[axes.second] = second + s * u + c * v;
}

}  // namespace

bool TransformView::mirror_on() const {
    for (bool m : mirrored) {
        if (m) return true;
    }
    return false;
}

AxisVector TransformView::map(const AxisVector& work) const {
    AxisVector q = work;
    for (std::size_t i = 0; i < axis_count; ++i) {
        if (mirrored[i]) q[i] = 2.0 * mirror_at[i] - q[i];
        if (scale_on) q[i] = scale_center[i] + scale[i] * (q[i] - scale_center[i]);
    }
    if (rotate_on) rotate(q, rotate_plane, rotate_first, rotate_second, rotate_deg);
    return q;
}

AxisVector TransformView::unmap(const AxisVector& transformed) const {
    AxisVector q = transformed;
    // The steps of map() undone in the reverse order; a factor is never 0 (G51 refuses it).
    if (rotate_on) rotate(q, rotate_plane, rotate_first, rotate_second, -rotate_deg);
    for (std::size_t i = 0; i < axis_count; ++i) {
        if (scale_on) q[i] = scale_center[i] + (q[i] - scale_center[i]) / scale[i];
        if (mirrored[i]) q[i] = 2.0 * mirror_at[i] - q[i];
    }
    return q;
}

std::optional<double> TransformView::plane_scale(Plane plane) const {
    if (!scale_on) return 1.0;
    const PlaneAxes axes = plane_axes(plane);
    const double a = std::abs(scale[index(axes.first)]), b = std::abs(scale[index(axes.second)]);
    if (std::abs(a - b) > 1e-12 * std::max(a, b)) return std::nullopt;
    return a;
}

bool TransformView::reverses(Plane plane) const {
    const PlaneAxes axes = plane_axes(plane);
    int flips = 0;
    for (Axis a : {axes.first, axes.second}) {
        const bool negative = scale_on && scale[index(a)] < 0;
        flips += (mirrored[index(a)] ? 1 : 0) + (negative ? 1 : 0);
    }
    return flips % 2 == 1;
}

}  // namespace nckit
