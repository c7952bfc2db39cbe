// Mirror, scale and rotation of programmed points (Fanuc G51.1, G51, G68).
#include "program_transform.hpp"

#include <cmath>
#include <numbers>

namespace nckit::interp {

bool ProgramTransform::sets_transform(const BlockWords& words) {
    if (words.group(ModalGroup::scaling) >= 0 || words.group(ModalGroup::mirror) >= 0 ||
        words.group(ModalGroup::rotation) >= 0) {
        return true;
    }
    // G50 alone cancels scaling (Fanuc mills); with S it clamps the spindle, with axis words it
    // sets coordinates (lathes).
    if (words.group(ModalGroup::non_modal) != g(50) || words.has('S')) return false;
    for (char c : axis_letters) {
        if (words.has(c)) return false;
    }
    return true;
}

AxisVector ProgramTransform::map(const AxisVector& work) const {
    AxisVector q = work;
    for (std::size_t i = 0; i < axis_count; ++i) {
        if (mirror_on_ && mirrored_[i]) q[i] = 2.0 * mirror_at_[i] - q[i];
        if (scale_on_) q[i] = scale_center_[i] + scale_[i] * (q[i] - scale_center_[i]);
    }
    if (rotate_on_) {
        const PlaneAxes axes = plane_axes(rotate_plane_);
        const double angle = rotate_deg_ * std::numbers::pi / 180.0;
        const double c = std::cos(angle), s = std::sin(angle);
        const double u = q[axes.first] - rotate_first_, v = q[axes.second] - rotate_second_;
        q[axes.first] = rotate_first_ + c * u - s * v;
        q[axes.second] = rotate_second_ + s * u + c * v;
    }
    return q;
}

std::optional<double> ProgramTransform::plane_scale(Plane plane) const {
    if (!scale_on_) return 1.0;
    const PlaneAxes axes = plane_axes(plane);
    const double a = std::abs(scale_[index(axes.first)]), b = std::abs(scale_[index(axes.second)]);
    if (std::abs(a - b) > 1e-12 * std::max(a, b)) return std::nullopt;
    return a;
}

bool ProgramTransform::reverses(Plane plane) const {
    const PlaneAxes axes = plane_axes(plane);
    int flips = 0;
    for (Axis a : {axes.first, axes.second}) {
        const bool mirrored = mirror_on_ && mirrored_[index(a)];
        const bool negative = scale_on_ && scale_[index(a)] < 0;
        flips += (mirrored ? 1 : 0) + (negative ? 1 : 0);
    }
    return flips % 2 == 1;
}

}  // namespace nckit::interp
