#include "peak_speed.hpp"

#include <algorithm>
#include <cmath>

#include "scalar_solve.hpp"

namespace nckit::plan_detail {

namespace {

// Residuals are accepted this far from the distance, relative (see speed_change.cpp).
constexpr double distance_tolerance = 1e-14;

//! Distance of the speed change from v by dv0 + u^2, and its derivative in u. Solving in
//! u = sqrt(peak - v_high) rather than in the peak speed keeps the derivative finite where the
//! peak meets v_high: the jerk-limited distance grows like sqrt(peak - v_high) there, and Newton
//! in the peak speed would crawl.
ValueSlope half_distance(double v, double dv0, double u, const Rates& r) {
    const double dv = dv0 + u * u;
    const double mean_v = v + 0.5 * dv;
    if (dv >= r.ramp_dv) {
        const double time = dv / r.a + r.a_over_j;
        return {mean_v * time, 2.0 * u * (0.5 * time + mean_v / r.a)};
    }
    const double root = std::sqrt(dv);
    const double u_over_root = dv > 0 ? u / root : 1.0;  // the limit when dv0 = 0 and u -> 0
    return {2.0 * mean_v * root / r.sqrt_j, 2.0 * (u * root + mean_v * u_over_root) / r.sqrt_j};
}

}  // namespace

Peak solve_peak(double distance_mm, double v_low, double v_high, const Rates& r) {
    const double gap = v_high - v_low;
    // Distance of the whole profile for a rise w above v_high; strictly increasing in w.
    auto distance_at = [&](double w) { return change_distance(v_low, gap + w, r) + change_distance(v_high, w, r); };

    const double w_max = std::max(0.0, r.v_max - v_high);
    const double at_max = distance_at(w_max);
    if (at_max <= distance_mm) return {w_max, (distance_mm - at_max) / r.v_max};
    const double at_zero = distance_at(0.0);
    if (at_zero >= distance_mm) return {0.0, 0.0};

    // Both halves reach the acceleration limit (w >= a^2/j): the distance is a quadratic in w,
    // w^2/a + b w + c0 = d, c0 being both halves' at-the-limit formulas taken at w = 0. Closed
    // form without cancellation; this is every trapezoid, where a^2/j = 0.
    const double w_both_limited = r.ramp_dv;
    if (w_both_limited < w_max && distance_at(w_both_limited) <= distance_mm) {
        const double b = 2.0 * v_high / r.a + r.a_over_j;
        const double c0 = (v_low + 0.5 * gap) * (gap / r.a + r.a_over_j) + v_high * r.a_over_j;
        const double rest = distance_mm - c0;
        const double w = 2.0 * rest / (b + std::sqrt(b * b + 4.0 * rest / r.a));
        return {std::clamp(w, w_both_limited, w_max), 0.0};
    }

    // Equal boundary speeds, neither half at the limit: 2 (2v + u^2) u / sqrt(j) = d, a cubic in
    // u with one real root (the rest-to-rest case 4 of the reference when v = 0).
    if (gap == 0) {
        const double u = cubic_root(2.0 * v_high, 0.5 * distance_mm * r.sqrt_j);
        return {std::min(u * u, w_max), 0.0};
    }

    // Different boundary speeds with at least the higher half below the limit: the distance is a
    // sum of square roots (and a quadratic) in the peak with no usable closed form. It is
    // strictly increasing in u, so a bracketed Newton search on the regime interval that holds
    // the root converges from any start; the lower half reaches the limit beyond w_low_limited.
    double lo = 0.0;
    double at_lo = at_zero;
    double hi = std::min(w_both_limited, w_max);
    double at_hi = hi == w_max ? at_max : distance_at(hi);
    const double w_low_limited = r.ramp_dv - gap;
    if (w_low_limited > lo && w_low_limited < hi) {
        const double at_split = distance_at(w_low_limited);
        if (at_split <= distance_mm) {
            lo = w_low_limited;
            at_lo = at_split;
        } else {
            hi = w_low_limited;
            at_hi = at_split;
        }
    }
    auto residual = [&](double u) {
        const ValueSlope low = half_distance(v_low, gap, u, r);
        const ValueSlope high = half_distance(v_high, 0.0, u, r);
        return ValueSlope{low.value + high.value - distance_mm, low.slope + high.slope};
    };
    const double u_lo = std::sqrt(lo);
    const double u_hi = std::sqrt(hi);
    // Start where the chord through the interval's ends meets the distance.
    const double u_start = u_lo + (u_hi - u_lo) * (distance_mm - at_lo) / (at_hi - at_lo);
    const double u =
        solve_increasing(residual, u_lo, u_hi, std::clamp(u_start, u_lo, u_hi), distance_tolerance * distance_mm);
    return {std::min(u * u, w_max), 0.0};
}

}  // namespace nckit::plan_detail
