#pragma once
// One-dimensional time-optimal motion profiles along a path: the building block the look-ahead
// planner calls for every path segment. A profile goes from (0, v_start, a = 0) to
// (distance, v_end, a = 0) as fast as the limits allow, never moving backwards.
#include <array>

#include "nckit/core/machine.hpp"  // ProfileKind

namespace nckit {

//! Limits along the path. All must be positive and finite, except max_jerk, which may be
//! +infinity (an S-curve with infinite jerk is a trapezoid).
struct ProfileLimits {
    double max_velocity = 0;      //!< mm/s
    double max_acceleration = 0;  //!< mm/s^2
    double max_jerk = 0;          //!< mm/s^3; ignored by ProfileKind::trapezoid
};

//! A piece of constant jerk.
struct ProfilePhase {
    double duration_s = 0;  //!< s, > 0
    double jerk = 0;        //!< mm/s^3 throughout the phase (0 in trapezoids)
    //! mm/s^2 at the phase start. Continuous across S-curve phases; in a trapezoid, where jerk
    //! is infinite, it jumps, which a jerk alone cannot describe.
    double acceleration = 0;
};

//! The motion at one instant.
struct ProfileState {
    double position = 0;      //!< mm along the path
    double velocity = 0;      //!< mm/s, never negative
    double acceleration = 0;  //!< mm/s^2
    double jerk = 0;          //!< mm/s^3
};

//! Rise to a peak speed, cruise at it (only when the peak is max_velocity), fall to the end
//! speed: at most 7 phases for an S-curve (+j, 0, -j, cruise, -j, 0, +j), 3 for a trapezoid.
//! Phases of zero duration are left out.
struct Profile {
    using State = ProfileState;

    double start_position = 0;      //!< mm; at() adds it to every position
    double start_velocity = 0;      //!< mm/s, v_start as planned (clamped into [0, max_velocity])
    double start_acceleration = 0;  //!< mm/s^2, always 0
    double distance = 0;            //!< mm, length of the profile (>= 0)
    double end_velocity = 0;        //!< mm/s, v_end as planned (see plan_profile for clamping)
    std::array<ProfilePhase, 7> phases{};
    int phase_count = 0;

    //! s, the sum of the phase durations.
    [[nodiscard]] double duration_s() const;
    //! The exact (piecewise cubic) state at t_s; t_s <= 0 gives the start state, t_s >= duration
    //! the end state (position start_position + distance, end_velocity, a = 0, jerk 0), both
    //! exactly. Inside, a trapezoid's acceleration is the value of the phase starting at t_s.
    [[nodiscard]] ProfileState at(double t_s) const;
};

//! The time-optimal profile from (0, v_start, a = 0) to (distance, v_end, a = 0) with
//! 0 <= v <= max_velocity, |a| <= max_acceleration, |j| <= max_jerk.
//!
//! The request is feasible when distance >= speed_change_distance(v_start, v_end). Otherwise
//! v_end is replaced by the highest reachable end speed below it, or, when none is (the distance
//! is too short to slow down that far), by min_end_speed(): the end is never faster than asked
//! unless it cannot be helped. Speeds are first clamped into [0, max_velocity], a negative or
//! NaN distance taken as 0. The speeds actually planned are in start_velocity and end_velocity.
//!
//! Shorter distances are treated as infeasible although, with jerk limits, a profile that
//! brakes *below* v_end and speeds up again can sometimes cover them (see min_end_speed).
//! Such a dip is never what a look-ahead wants, and a look-ahead never asks for one: its two
//! passes keep v_end <= max_end_speed(distance, v_start) and v_start <= max_end_speed(distance,
//! v_end), which together are exactly this test.
[[nodiscard]] Profile plan_profile(double distance, double v_start, double v_end, const ProfileLimits& limits,
                                   ProfileKind kind);

//! mm, the distance of the time-optimal monotone speed change between two speeds (a = 0 at both
//! ends), the same in both directions: the shortest distance over which plan_profile can go
//! from one speed to the other.
[[nodiscard]] double speed_change_distance(double v_from, double v_to, const ProfileLimits& limits, ProfileKind kind);

//! mm/s, the highest end speed reachable over distance from v_start (accelerating all the way),
//! at most max_velocity. Every end speed in [v_start, max_end_speed] is reachable.
[[nodiscard]] double max_end_speed(double distance, double v_start, const ProfileLimits& limits, ProfileKind kind);

//! mm/s, the lowest end speed reachable over distance from v_start, at least 0.
//! Jerk-limited braking to nearly a stop covers more distance than braking to a stop (lower
//! speeds take longer to reach but lower the mean speed of the whole braking more), so with an
//! S-curve, when min_end_speed is 0, a band of end speeds between it and v_start can be out of
//! reach: test a request with speed_change_distance, not with this range.
[[nodiscard]] double min_end_speed(double distance, double v_start, const ProfileLimits& limits, ProfileKind kind);

}  // namespace nckit
