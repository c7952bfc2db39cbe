#include "segment_limits.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace nckit::plan_detail {

ProfileLimits segment_limits(const PathSegment& segment, const MachineConfig& machine, double feed_mm_s,
                             ProfileKind kind) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    const DerivativeBounds b = derivative_bounds(segment);
    const bool jerk_limited = kind == ProfileKind::scurve;
    double v = feed_mm_s / b.speed_factor;
    double a = inf;
    double j = inf;
    for (const AxisConfig& axis : machine.axes) {
        const std::size_t i = index(axis.axis);
        if (!(b.d1[i] > 0) && !(b.d2[i] > 0)) continue;
        const bool curved = b.d2[i] > 0;
        if (b.d1[i] > 0) v = std::min(v, axis.max_velocity / b.d1[i]);
        if (curved) {
            v = std::min(v, std::sqrt(0.5 * axis.max_acceleration / b.d2[i]));
            if (jerk_limited && b.d3[i] > 0) v = std::min(v, std::cbrt(axis.max_jerk / (3.0 * b.d3[i])));
        }
        if (b.d1[i] > 0) {
            a = std::min(a, (curved ? 0.5 : 1.0) * axis.max_acceleration / b.d1[i]);
            if (jerk_limited) j = std::min(j, (curved ? 1.0 / 3.0 : 1.0) * axis.max_jerk / b.d1[i]);
        }
    }
    // The coupling term 3·d2·v·a ≤ jmax/3 needs the final v.
    if (jerk_limited && v > 0) {
        for (const AxisConfig& axis : machine.axes) {
            const std::size_t i = index(axis.axis);
            if (b.d2[i] > 0) a = std::min(a, axis.max_jerk / (9.0 * b.d2[i] * v));
        }
    }
    ProfileLimits out;
    out.max_velocity = std::isfinite(v) ? v : 0.0;
    out.max_acceleration = a;
    out.max_jerk = jerk_limited ? j : inf;
    return out;
}

}  // namespace nckit::plan_detail
