#include "speed_change.hpp"

#include <algorithm>
#include <cmath>

#include "scalar_solve.hpp"

namespace nckit::plan_detail {

namespace {

// Residuals are accepted this far from the distance, relative; far below the 1e-9 the profile
// promises, and within a few roundings of what the formulas can resolve.
constexpr double distance_tolerance = 1e-14;

//! mm, braking from v by dv.
double braking_distance(double v, double dv, const Rates& r) {
    return change_distance(v - dv, dv, r);
}

}  // namespace

double speed_gain(double distance_mm, double v, const Rates& r) {
    // At or beyond the acceleration limit, (2v + dv)(dv/a + a/j) = 2 d is a quadratic in dv:
    // dv^2/a + b dv - c = 0, solved in the form without cancellation (b, c > 0 there).
    if (distance_mm >= change_distance(v, r.ramp_dv, r)) {
        const double b = 2.0 * v / r.a + r.a_over_j;
        const double c = 2.0 * distance_mm - 2.0 * v * r.a_over_j;
        return 2.0 * c / (b + std::sqrt(b * b + 4.0 * c / r.a));
    }
    // Below it, (2v + s^2) s / sqrt(j) = d with s = sqrt(dv): a cubic with one real root.
    const double s = cubic_root(2.0 * v, distance_mm * r.sqrt_j);
    return s * s;
}

double braking_peak_loss(double v, const Rates& r) {
    // d/d(dv) of the braking distance: (v - dv)/a - a/(2j) at the acceleration limit, and
    // (v - 1.5 dv)/sqrt(j dv) below it; the two agree at dv = a^2/j.
    if (v >= 1.5 * r.ramp_dv) return v - 0.5 * r.ramp_dv;
    return v * (2.0 / 3.0);
}

double speed_loss(double distance_mm, double v, BrakingSide side, const Rates& r) {
    const double peak = braking_peak_loss(v, r);
    const double tolerance = distance_tolerance * distance_mm;
    // At the acceleration limit: (2v - dv)(dv/a + a/j) = 2 d, i.e. dv^2/a - b dv + c = 0 with
    // the vertex at the peak loss; the rising side is the smaller root, written without
    // cancellation, the falling side the larger.
    const double b = (2.0 * v - r.ramp_dv) / r.a;
    const double c = 2.0 * distance_mm - 2.0 * v * r.a_over_j;
    const double root_disc = std::sqrt(std::max(0.0, b * b - 4.0 * c / r.a));
    // Below it: g(s) = (2v - s^2) s / sqrt(j) = d with s = sqrt(dv), rising up to s^2 = 2v/3.
    // Newton on g is safe from the left on the rising side (g is concave) and bracketed anyway.
    auto braking_at_root = [&](double s) {
        const double value = (2.0 * v - s * s) * s / r.sqrt_j - distance_mm;
        const double slope = (2.0 * v - 3.0 * s * s) / r.sqrt_j;
        return ValueSlope{value, slope};
    };
    if (side == BrakingSide::rising) {
        if (peak > r.ramp_dv && distance_mm >= braking_distance(v, r.ramp_dv, r)) {
            return std::min(peak, 2.0 * c / (b + root_disc));
        }
        const double hi = std::sqrt(std::min(peak, r.ramp_dv));
        const double guess = std::min(hi, distance_mm * r.sqrt_j / (2.0 * v));
        const double s = solve_increasing(braking_at_root, 0.0, hi, guess, tolerance);
        return s * s;
    }
    const double limited_from = std::max(peak, r.ramp_dv);
    if (limited_from < v && distance_mm <= braking_distance(v, limited_from, r)) {
        return std::clamp(0.5 * (b + root_disc) * r.a, limited_from, v);
    }
    // The falling side below the acceleration limit: solve -g, increasing there.
    auto falling = [&](double s) {
        const ValueSlope g = braking_at_root(s);
        return ValueSlope{-g.value, -g.slope};
    };
    const double lo = std::sqrt(peak);
    const double hi = std::sqrt(std::min(v, r.ramp_dv));
    const double s = solve_increasing(falling, lo, hi, 0.5 * (lo + hi), tolerance);
    return s * s;
}

}  // namespace nckit::plan_detail
