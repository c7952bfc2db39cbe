// Rest-to-rest rapid times, the planner's way.
#include "nckit/process/pattern/air_motion.hpp"

#include <cmath>
#include <limits>

#include "nckit/plan/profile.hpp"

namespace nckit::pattern {

AirTimer::AirTimer(const MachineConfig& machine) : machine_(&machine) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    vmax_.fill(inf);
    amax_.fill(inf);
    jmax_.fill(inf);
    for (const AxisConfig& axis : machine.axes) {
        const std::size_t i = index(axis.axis);
        if (i > 2) continue;
        vmax_[i] = axis.max_velocity;
        amax_[i] = axis.max_acceleration;
        jmax_[i] = axis.max_jerk;
        if (i < 2 && axis.backlash > 0) {
            const double steps = std::round(axis.backlash * axis.steps_per_unit);
            reversal_s_[i] = steps / axis.backlash_rate_steps_s;
        }
    }
}

double AirTimer::rapid_s(double dx, double dy, double dz) const {
    const double length = std::sqrt(dx * dx + dy * dy + dz * dz);
    if (length <= 0) return 0;
    // A line's derivative bounds are its direction cosines (no curvature): each axis limits the
    // path's speed, acceleration and jerk to its own limit over its cosine.
    const std::array<double, 3> c{std::abs(dx) / length, std::abs(dy) / length, std::abs(dz) / length};
    ProfileLimits limits{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                         std::numeric_limits<double>::infinity()};
    for (std::size_t i = 0; i < 3; ++i) {
        if (c[i] <= 0) continue;
        limits.max_velocity = std::min(limits.max_velocity, vmax_[i] / c[i]);
        limits.max_acceleration = std::min(limits.max_acceleration, amax_[i] / c[i]);
        limits.max_jerk = std::min(limits.max_jerk, jmax_[i] / c[i]);
    }
    if (machine_->profile == ProfileKind::trapezoid) {
        const double v = limits.max_velocity, a = limits.max_acceleration;
        return length >= v * v / a ? length / v + v / a : 2.0 * std::sqrt(length / a);
    }
    return plan_profile(length, 0, 0, limits, ProfileKind::scurve).duration_s();
}

}  // namespace nckit::pattern
