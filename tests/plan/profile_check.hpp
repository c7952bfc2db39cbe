#pragma once
// Test-side formulas, written again from docs/planner.md rather than taken from the
// library, and the invariant checks every planned profile must pass.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <fmt/format.h>

#include "nckit/plan/profile.hpp"

namespace nckit::plan_test {

inline constexpr double inf = std::numeric_limits<double>::infinity();

//! s, time-optimal speed change by dv >= 0 with a = 0 at both ends.
inline double ref_change_time(double dv, double a, double j) {
    if (j == inf || dv * j >= a * a) return dv / a + a / j;
    return 2.0 * std::sqrt(dv / j);
}

//! mm, distance of that speed change between v_lo and v_hi.
inline double ref_change_distance(double v_lo, double v_hi, double a, double j) {
    return 0.5 * (v_lo + v_hi) * ref_change_time(v_hi - v_lo, a, j);
}

inline double jerk_of(const ProfileLimits& limits, ProfileKind kind) {
    return kind == ProfileKind::trapezoid ? inf : limits.max_jerk;
}

//! Boundary states of each phase, integrated forwards from the start independently of at().
struct PhaseStates {
    double t_s[8]{};
    double position[8]{};
    double velocity[8]{};
    double acceleration_end[8]{};  //!< at the end of phase k-1 (index k)
};

inline PhaseStates integrate_phases(const Profile& profile) {
    PhaseStates s;
    s.velocity[0] = profile.start_velocity;
    for (int k = 0; k < profile.phase_count; ++k) {
        const ProfilePhase& ph = profile.phases[static_cast<std::size_t>(k)];
        const double t = ph.duration_s;
        const double a = ph.acceleration;
        const double j = ph.jerk;
        s.t_s[k + 1] = s.t_s[k] + t;
        s.position[k + 1] = s.position[k] + s.velocity[k] * t + a * t * t / 2 + j * t * t * t / 6;
        s.velocity[k + 1] = s.velocity[k] + a * t + j * t * t / 2;
        s.acceleration_end[k + 1] = a + j * t;
    }
    return s;
}

//! The first broken invariant of a planned profile, or "" when it holds them all: phases in
//! shape, end state exact, limits respected (1e-6 relative) at phase boundaries and 16 samples
//! per phase, velocity never negative, position, velocity (and for S-curves acceleration)
//! continuous, at() agreeing with the phases.
inline std::string check_profile(const Profile& profile, const ProfileLimits& limits, ProfileKind kind) {
    const double vmax = limits.max_velocity;
    const double amax = limits.max_acceleration;
    const double jmax = kind == ProfileKind::trapezoid ? 0.0 : limits.max_jerk;
    const double d = profile.distance;
    const int n = profile.phase_count;
    if (n < 0 || n > (kind == ProfileKind::trapezoid ? 3 : 7)) return fmt::format("phase_count {}", n);
    for (int k = 0; k < n; ++k) {
        const ProfilePhase& ph = profile.phases[static_cast<std::size_t>(k)];
        if (!(ph.duration_s > 0) || !std::isfinite(ph.duration_s))
            return fmt::format("phase {} duration {}", k, ph.duration_s);
        if (std::abs(ph.jerk) > jmax * (1 + 1e-12)) return fmt::format("phase {} jerk {}", k, ph.jerk);
    }
    const PhaseStates s = integrate_phases(profile);
    const double total = profile.duration_s();
    // End state from the phases alone.
    if (std::abs(s.position[n] - d) > 1e-9 * d) {
        return fmt::format("integrated end position {} != {}", s.position[n], d);
    }
    if (std::abs(s.velocity[n] - profile.end_velocity) > 1e-9 * vmax) {
        return fmt::format("integrated end velocity {} != {}", s.velocity[n], profile.end_velocity);
    }
    if (kind == ProfileKind::scurve && n > 0 && std::abs(s.acceleration_end[n]) > 1e-9 * amax) {
        return fmt::format("integrated end acceleration {}", s.acceleration_end[n]);
    }
    // Acceleration continuity of S-curves: each phase starts where the previous one ended.
    if (kind == ProfileKind::scurve && n > 0) {
        if (profile.phases[0].acceleration != 0) return "S-curve starts with a != 0";
        for (int k = 1; k < n; ++k) {
            const double gap = profile.phases[static_cast<std::size_t>(k)].acceleration - s.acceleration_end[k];
            if (std::abs(gap) > 1e-9 * amax) return fmt::format("acceleration jumps by {} at phase {}", gap, k);
        }
    }
    // End state from at(): exact.
    const ProfileState end = profile.at(total);
    if (end.position != profile.start_position + d || end.velocity != profile.end_velocity || end.acceleration != 0) {
        return fmt::format("at(T) = ({}, {}, {})", end.position, end.velocity, end.acceleration);
    }
    const ProfileState start = profile.at(0);
    if (start.position != profile.start_position || start.velocity != profile.start_velocity) return "at(0) != start";
    // Samples: limits, sign of velocity, and at() against the phase polynomials.
    // Tolerances: 1e-9 relative, plus what the rounding of a time (a few ulps of the duration)
    // moves a state by: with jerks up to 1e8 mm/s^3 that is not negligible for acceleration.
    const double time_eps = 8 * std::numeric_limits<double>::epsilon() * total;
    const double pos_tol = 1e-9 * std::max(d, 1e-300) + 1e-12 * vmax * total + vmax * time_eps;
    const double vel_tol = 1e-9 * vmax + amax * time_eps;
    const double acc_tol = 1e-9 * amax + jmax * time_eps;
    for (int k = 0; k < n; ++k) {
        const ProfilePhase& ph = profile.phases[static_cast<std::size_t>(k)];
        for (int i = 0; i <= 16; ++i) {
            const double tau = ph.duration_s * i / 16.0;
            const double t = s.t_s[k] + tau;
            if (t <= 0 || t >= total) continue;  // the ends are the boundary states, checked above
            const ProfileState st = profile.at(t);
            const double a = ph.acceleration + ph.jerk * tau;
            const double v = s.velocity[k] + ph.acceleration * tau + ph.jerk * tau * tau / 2;
            const double p =
                s.position[k] + s.velocity[k] * tau + ph.acceleration * tau * tau / 2 + ph.jerk * tau * tau * tau / 6;
            if (!(st.velocity >= 0)) return fmt::format("negative velocity {} at t={}", st.velocity, t);
            if (st.velocity > vmax * (1 + 1e-6)) return fmt::format("velocity {} > {} at t={}", st.velocity, vmax, t);
            if (std::abs(st.acceleration) > amax * (1 + 1e-6)) {
                return fmt::format("acceleration {} > {} at t={}", st.acceleration, amax, t);
            }
            if (std::abs(st.jerk) > jmax * (1 + 1e-6)) return fmt::format("jerk {} at t={}", st.jerk, t);
            if (std::abs(st.position - profile.start_position - p) > pos_tol) {
                return fmt::format("at({}) position {} vs phases {}", t, st.position, p);
            }
            if (std::abs(st.velocity - v) > vel_tol)
                return fmt::format("at({}) velocity {} vs phases {}", t, st.velocity, v);
            // A trapezoid's acceleration jumps at phase boundaries, where at() gives the value
            // of the phase starting there: within a rounding of the time, either.
            const bool jump = kind == ProfileKind::trapezoid && (i == 0 || i == 16);
            if (!jump && std::abs(st.acceleration - a) > acc_tol) {
                return fmt::format("at({}) acceleration {} vs phases {}", t, st.acceleration, a);
            }
        }
    }
    // Continuity where at() switches from forwards to backwards evaluation, and monotone
    // position across it.
    if (total > 0) {
        const double mid = 0.5 * total;
        const double dt = 1e-12 * total;
        const ProfileState l = profile.at(mid - dt);
        const ProfileState r = profile.at(mid + dt);
        if (std::abs(r.position - l.position) > pos_tol + 3 * vmax * dt) return "position jumps at T/2";
        if (std::abs(r.velocity - l.velocity) > vel_tol + 3 * amax * dt) return "velocity jumps at T/2";
        if (kind == ProfileKind::scurve && std::abs(r.acceleration - l.acceleration) > acc_tol + 3 * jmax * dt) {
            return "acceleration jumps at T/2";
        }
    }
    return "";
}

}  // namespace nckit::plan_test
