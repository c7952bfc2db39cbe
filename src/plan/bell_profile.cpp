#include "bell_profile.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace nckit::plan_detail {

namespace {

//! Steps of the search for the peak speed when the bell has no room to cruise, and their
//! relative resolution: what the search leaves is cruised at the peak, so the distance stays
//! exact.
constexpr int peak_steps = 60;
constexpr double peak_resolution = 1e-9;

//! Up to three phases changing the speed from v_from to v_to: jerk `first` until the
//! acceleration reaches its peak, held there, jerk `second` back to 0.
struct Change {
    std::array<ProfilePhase, 3> phases{};
    int count = 0;
    double distance = 0;  //!< mm
};

Change speed_change(double v_from, double v_to, double max_acceleration, double first_jerk, double second_jerk) {
    Change c;
    const double dv = std::abs(v_to - v_from);
    if (!(dv > 0)) return c;
    const double sign = v_to > v_from ? 1.0 : -1.0;
    // The speed gained while the acceleration rises to A and falls back: A²·(1/(2·j1) + 1/(2·j2)).
    const double per_a2 = 0.5 / first_jerk + 0.5 / second_jerk;
    const double peak = std::min(max_acceleration, std::sqrt(dv / per_a2));
    const double hold_s = std::max(0.0, (dv - peak * peak * per_a2) / peak);
    const std::array<double, 3> durations = {peak / first_jerk, hold_s, peak / second_jerk};
    const std::array<double, 3> jerks = {sign * first_jerk, 0.0, -sign * second_jerk};
    double v = v_from;
    double a = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        const double t = durations[i];
        const double j = jerks[i];
        if (!(t > 0)) continue;
        c.phases[static_cast<std::size_t>(c.count++)] = {t, j, a};
        c.distance += t * (v + t * (0.5 * a + t * j / 6.0));
        v += t * (a + 0.5 * t * j);
        a += t * j;
    }
    return c;
}

Change rise_to(double v_start, double v_peak, const BellRates& r) {
    return speed_change(v_start, v_peak, r.rise.max_acceleration, r.rise.end_jerk, r.rise.top_jerk);
}
Change fall_from(double v_peak, double v_end, const BellRates& r) {
    return speed_change(v_peak, v_end, r.fall.max_acceleration, r.fall.top_jerk, r.fall.end_jerk);
}

bool positive(const BellSide& side) {
    return side.max_acceleration > 0 && side.end_jerk > 0 && side.top_jerk > 0;
}

double bell_distance(double v_start, double v_end, double v_peak, const BellRates& r) {
    return rise_to(v_start, v_peak, r).distance + fall_from(v_peak, v_end, r).distance;
}

}  // namespace

bool bell_profile(double distance, double v_start, double v_end, double v_top, const BellRates& rates, Profile& out) {
    const double floor_speed = std::max(v_start, v_end);
    if (!(v_top >= floor_speed) || !positive(rates.rise) || !positive(rates.fall) || !(distance >= 0)) return false;
    const double excess_at_floor = bell_distance(v_start, v_end, floor_speed, rates) - distance;
    if (excess_at_floor > 0) return false;
    double peak = v_top;
    const double excess_at_top = bell_distance(v_start, v_end, v_top, rates) - distance;
    if (excess_at_top > 0) {
        // The distance grows with the peak: false position with the Illinois rule (the end
        // kept twice in a row has its value halved), the bracket [lo, hi] always kept, lo the
        // side that fits.
        double lo = floor_speed;
        double hi = v_top;
        double f_lo = excess_at_floor;
        double f_hi = excess_at_top;
        int kept = 0;
        for (int k = 0; k < peak_steps && hi > lo * (1.0 + peak_resolution); ++k) {
            double mid = lo - f_lo * (hi - lo) / (f_hi - f_lo);
            if (!(mid > lo && mid < hi)) mid = 0.5 * (lo + hi);
            const double f_mid = bell_distance(v_start, v_end, mid, rates) - distance;
            if (f_mid <= 0) {
                lo = mid;
                f_lo = f_mid;
                if (kept == -1) f_hi *= 0.5;
                kept = -1;
            } else {
                hi = mid;
                f_hi = f_mid;
                if (kept == 1) f_lo *= 0.5;
                kept = 1;
            }
        }
        peak = lo;
    }
    // The distance the speed changes leave is cruised at the peak (a sliver after the search);
    // with no speed to cruise at, there is no bell.
    const Change rise = rise_to(v_start, peak, rates);
    const Change fall = fall_from(peak, v_end, rates);
    const double cruise_mm = std::max(0.0, distance - (rise.distance + fall.distance));
    if (cruise_mm > 1e-12 * std::max(1.0, distance) && !(peak > 0)) return false;
    Profile p;
    p.start_velocity = v_start;
    p.end_velocity = v_end;
    p.distance = distance;
    const auto append = [&p](const ProfilePhase& phase) {
        p.phases[static_cast<std::size_t>(p.phase_count++)] = phase;
    };
    for (int i = 0; i < rise.count; ++i) append(rise.phases[static_cast<std::size_t>(i)]);
    if (cruise_mm > 0 && peak > 0) append({cruise_mm / peak, 0.0, 0.0});
    for (int i = 0; i < fall.count; ++i) append(fall.phases[static_cast<std::size_t>(i)]);
    out = p;
    return true;
}

}  // namespace nckit::plan_detail
