#pragma once
// The limits in the form the profile formulas use, and the two formulas everything else builds
// on: time and distance of one monotone speed change with a = 0 at both ends.
#include <cmath>
#include <limits>

#include "nckit/plan/profile.hpp"

namespace nckit::plan_detail {

//! A trapezoid is an S-curve with infinite jerk: every jerk ramp takes 0 s, so one set of
//! formulas serves both kinds.
struct Rates {
    double v_max = 0;     //!< mm/s
    double a = 0;         //!< mm/s^2, acceleration limit
    double j = 0;         //!< mm/s^3, jerk limit (+inf for trapezoids)
    double sqrt_j = 0;    //!< sqrt(mm/s^3)
    double a_over_j = 0;  //!< s, a jerk ramp from 0 to a (0 for trapezoids)
    double ramp_dv = 0;   //!< mm/s, a^2/j: smaller speed changes never reach a (0 for trapezoids)
};

inline Rates make_rates(const ProfileLimits& limits, ProfileKind kind) {
    Rates r;
    r.v_max = limits.max_velocity;
    r.a = limits.max_acceleration;
    r.j = kind == ProfileKind::trapezoid ? std::numeric_limits<double>::infinity() : limits.max_jerk;
    r.sqrt_j = std::sqrt(r.j);
    r.a_over_j = r.a / r.j;
    r.ramp_dv = r.a * r.a_over_j;
    return r;
}

//! s, time of a speed change by dv >= 0: a trapezoid in acceleration when dv >= a^2/j,
//! otherwise a triangle that peaks at sqrt(j dv) < a.
inline double change_time(double dv, const Rates& r) {
    return dv >= r.ramp_dv ? dv / r.a + r.a_over_j : 2.0 * std::sqrt(dv) / r.sqrt_j;
}

//! mm, distance of the speed change between v and v + dv (either way): the acceleration is symmetric in
//! time, so the mean speed is the mean of the end speeds.
inline double change_distance(double v, double dv, const Rates& r) {
    return (v + 0.5 * dv) * change_time(dv, r);
}

}  // namespace nckit::plan_detail
