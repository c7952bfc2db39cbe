#include "nckit/plan/segment_limits.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace nckit {

ProfileLimits segment_limits(const PathSegment& segment, const MachineConfig& machine, double feed_mm_s,
                             ProfileKind kind, double normal_share) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    const DerivativeBounds b = derivative_bounds(segment);
    const bool jerk_limited = kind == ProfileKind::scurve;
    const double share = std::clamp(normal_share, 0.0, max_normal_share);
    // 1. The speed: the feed, each axis's speed, and the fixed shares of the curvature terms
    //    (d2·v² <= amax/2, d3·v³ <= jmax/3): never lower than a split of the budget in halves
    //    and thirds would give.
    double v = feed_mm_s / b.speed_factor;
    for (const AxisConfig& axis : machine.axes) {
        const std::size_t i = index(axis.axis);
        if (b.d1[i] > 0) v = std::min(v, axis.max_velocity / b.d1[i]);
        if (b.d2[i] > 0) {
            // min(v, sqrt(cap)) and min(v, cbrt(cap)), the roots taken only when they bind.
            const double cap2 = share * axis.max_acceleration / b.d2[i];
            if (v * v > cap2) v = std::sqrt(cap2);
            if (jerk_limited && b.d3[i] > 0) {
                const double cap3 = axis.max_jerk / (3.0 * b.d3[i]);
                if (v * v * v > cap3) v = std::cbrt(cap3);
            }
        }
    }
    if (!std::isfinite(v)) v = 0.0;
    // 2. The acceleration gets what the curvature term leaves at that speed, per axis:
    //    d1·a <= amax − d2·v² (>= amax/2, and all of amax on a straight axis). On a gentle
    //    curve taken at the feed (a blend between nearly collinear CAM segments) that is almost
    //    the whole limit, where a fixed half would double every speed change along it.
    double a = inf;
    for (const AxisConfig& axis : machine.axes) {
        const std::size_t i = index(axis.axis);
        if (b.d1[i] > 0) a = std::min(a, (axis.max_acceleration - b.d2[i] * v * v) / b.d1[i]);
    }
    // 3. The jerk likewise: the coupling 3·d2·v·a takes at most half of what d3·v³ leaves (so
    //    a may need lowering), and d1·j gets the rest: jmax − d3·v³ − 3·d2·v·a >= jmax/3.
    double j = inf;
    if (jerk_limited) {
        if (v > 0) {
            for (const AxisConfig& axis : machine.axes) {
                const std::size_t i = index(axis.axis);
                if (b.d2[i] > 0) {
                    a = std::min(a, (axis.max_jerk - b.d3[i] * v * v * v) / (6.0 * b.d2[i] * v));
                }
            }
        }
        for (const AxisConfig& axis : machine.axes) {
            const std::size_t i = index(axis.axis);
            if (b.d1[i] > 0) {
                const double coupling = b.d2[i] > 0 ? 3.0 * b.d2[i] * v * a : 0.0;
                j = std::min(j, (axis.max_jerk - b.d3[i] * v * v * v - coupling) / b.d1[i]);
            }
        }
    }
    ProfileLimits out;
    out.max_velocity = v;
    out.max_acceleration = a;
    out.max_jerk = jerk_limited ? j : inf;
    return out;
}

}  // namespace nckit
