// plan_profile and the feasibility queries: clamping, the peak, and the phases.
#include <algorithm>
#include <cmath>

#include "nckit/plan/profile.hpp"
#include "peak_speed.hpp"
#include "rates.hpp"
#include "speed_change.hpp"

namespace nckit {

using plan_detail::BrakingSide;
using plan_detail::change_distance;
using plan_detail::Rates;

namespace {

//! Speeds outside [0, v_max] (or NaN) are outside every profile; the nearest allowed value.
double clean_speed(double v, const Rates& r) {
    return v > 0 ? std::min(v, r.v_max) : 0.0;
}
double clean_distance(double d) {
    return d > 0 ? d : 0.0;
}

bool fits(double d, double v0, double v1, const Rates& r) {
    return change_distance(std::min(v0, v1), std::abs(v1 - v0), r) <= d;
}

//! An end speed from one of the inverses, moved by growing steps of an ulp toward a speed known
//! to fit until the speed change fits in d as change_distance computes it. The inverses are
//! right to rounding, but rounding the end speed to a double can miss d by far more when the
//! speed change is tiny (the distance grows like its square root); plan_profile must then
//! still cover d exactly, which a peak can do only from a speed that fits.
double fit(double d, double v0, double v1, double fitting_v, const Rates& r) {
    double step = std::abs(v1) * 0x1p-52 + 0x1p-1074;
    while (!fits(d, v0, v1, r)) {
        if (std::abs(fitting_v - v1) <= step) return fitting_v;
        v1 += fitting_v > v1 ? step : -step;
        step *= 2;
    }
    return v1;
}

double max_end(double d, double v0, const Rates& r) {
    if (v0 >= r.v_max || fits(d, v0, r.v_max, r)) return r.v_max;
    return fit(d, v0, std::min(r.v_max, v0 + plan_detail::speed_gain(d, v0, r)), v0, r);
}

double min_end(double d, double v0, const Rates& r) {
    if (fits(d, v0, 0.0, r)) return 0.0;
    return fit(d, v0, std::max(0.0, v0 - plan_detail::speed_loss(d, v0, BrakingSide::rising, r)), v0, r);
}

//! The end speed plan_profile plans for a request of v1: v1 itself when reachable, otherwise
//! the highest reachable speed below it, otherwise the lowest reachable speed (above it).
double reachable_end(double d, double v0, double v1, const Rates& r) {
    if (fits(d, v0, v1, r)) return v1;
    if (v1 > v0) return std::min(v1, max_end(d, v0, r));
    // Too short to brake to v1. When braking to a stop fits, the speeds that fit below v0 are
    // [0, v_a] and [v_b, v0] with v1 between: v_a is on the falling side of the braking
    // distance (see speed_change.hpp). Otherwise only [v_b, v0] fits, and v_b = min_end.
    if (fits(d, v0, 0.0, r)) {
        const double v_a = std::max(0.0, v0 - plan_detail::speed_loss(d, v0, BrakingSide::falling, r));
        return std::min(v1, fit(d, v0, v_a, 0.0, r));
    }
    return min_end(d, v0, r);
}

void append_phase(Profile& profile, double duration_s, double jerk, double acceleration) {
    if (!(duration_s > 0)) return;  // also drops the zero-length jerk phases of trapezoids
    profile.phases[static_cast<std::size_t>(profile.phase_count++)] = {duration_s, jerk, acceleration};
}

//! The phases of a time-optimal speed change by dv >= 0, up (sign +1) or down (-1).
void append_speed_change(Profile& profile, double dv, double sign, const Rates& r) {
    if (!(dv > 0)) return;
    double ramp_s = r.a_over_j;  // jerk phases, each
    double hold_s = 0;           // constant acceleration between them
    double peak_a = r.a;
    if (dv >= r.ramp_dv) {
        hold_s = std::max(0.0, dv / r.a - r.a_over_j);
    } else {
        const double root = std::sqrt(dv);
        ramp_s = root / r.sqrt_j;
        peak_a = std::min(r.a, root * r.sqrt_j);
    }
    append_phase(profile, ramp_s, sign * r.j, 0.0);
    append_phase(profile, hold_s, 0.0, sign * peak_a);
    append_phase(profile, ramp_s, -sign * r.j, sign * peak_a);
}

}  // namespace

Profile plan_profile(double distance, double v_start, double v_end, const ProfileLimits& limits, ProfileKind kind) {
    const Rates r = plan_detail::make_rates(limits, kind);
    const double d = clean_distance(distance);
    const double v0 = clean_speed(v_start, r);
    const double v1 = reachable_end(d, v0, clean_speed(v_end, r), r);

    Profile profile;
    profile.start_velocity = v0;
    profile.distance = d;
    profile.end_velocity = v1;
    const double v_low = std::min(v0, v1);
    const double v_high = std::max(v0, v1);
    const plan_detail::Peak peak = plan_detail::solve_peak(d, v_low, v_high, r);
    // The rise of the lower half is the boundary gap plus the rise above v_high, kept as such
    // (not as peak - v_low) so both halves see the same peak to the last bit.
    const double gap = v_high - v_low;
    append_speed_change(profile, (v0 <= v1 ? gap : 0.0) + peak.rise_mm_s, 1.0, r);
    append_phase(profile, peak.cruise_s, 0.0, 0.0);
    append_speed_change(profile, (v0 <= v1 ? 0.0 : gap) + peak.rise_mm_s, -1.0, r);
    return profile;
}

double speed_change_distance(double v_from, double v_to, const ProfileLimits& limits, ProfileKind kind) {
    const Rates r = plan_detail::make_rates(limits, kind);
    const double a = clean_speed(v_from, r);
    const double b = clean_speed(v_to, r);
    return change_distance(std::min(a, b), std::abs(b - a), r);
}

double max_end_speed(double distance, double v_start, const ProfileLimits& limits, ProfileKind kind) {
    const Rates r = plan_detail::make_rates(limits, kind);
    return max_end(clean_distance(distance), clean_speed(v_start, r), r);
}

double min_end_speed(double distance, double v_start, const ProfileLimits& limits, ProfileKind kind) {
    const Rates r = plan_detail::make_rates(limits, kind);
    return min_end(clean_distance(distance), clean_speed(v_start, r), r);
}

}  // namespace nckit
