#pragma once
// A run of curved pieces planned faster than the pieces' own speed limits where the profile
// really keeps their axes within limits: a piece's speed limit pays for the path acceleration
// it might see, but where the run's profile holds its speed there, the turning may take the
// whole acceleration (docs/planner.md, "Speed along an arc (S-curve)").
#include <array>
#include <cstddef>
#include <limits>
#include <vector>

#include "nckit/plan/profile.hpp"

namespace nckit::plan_detail {

//! The values a derivative takes over a piece, with their signs.
struct SignedRange {
    double lo = 0;
    double hi = 0;
};

//! One axis of a curved piece: bounds of |q'|, |q''|, |q'''| over the piece, the ranges of
//! q', q'', q''' with their signs (within ±d1, ±d2, ±d3) and the axis's acceleration and jerk
//! limits. The signs let the check see where the path's own jerk q'·s⃛ works against the
//! turning's q'''·ṡ³ (speeding up out of a curve, braking into one).
struct CurvedAxis {
    double d1 = 0;
    double d2 = 0;
    double d3 = 0;
    double max_acceleration = 0;  //!< mm/s²
    double max_jerk = 0;          //!< mm/s³
    //! Set when q1, q2, q3 are known; otherwise the check takes ±d1, ±d2, ±d3.
    bool signs_known = false;
    SignedRange q1{};
    SignedRange q2{};
    SignedRange q3{};
};

//! What a piece allows beyond its rectangular (v, a, j) limits: its curved axes (count 0: none
//! known, the piece is held to its limits) and the speed it allows with no path acceleration or
//! jerk (d2·v² <= amax, d3·v³ <= jmax, the feed and the axes' speeds).
struct PieceCheck {
    std::array<CurvedAxis, 3> axes{};
    int count = 0;
    double cruise_velocity = 0;  //!< mm/s
    //! mm/s, the feed and the axes' speeds alone: the check's speed limit. Above cruise_velocity
    //! the curved axes' terms decide, with their signs: a path jerk that works against the
    //! turning (speeding up out of a curve) lets a profile pass faster than it could cruise.
    double speed_limit = 0;
    //! mm/s², mm/s³: the path acceleration and jerk the axes that move but do not curve allow
    //! (min of amax/d1, jmax/d1; a helix's axis), infinite when none does.
    double straight_acceleration = std::numeric_limits<double>::infinity();
    double straight_jerk = std::numeric_limits<double>::infinity();
    //! The piece's (v, a, j) limits count the S-curve's knee (arc_pieces.cpp): they hold only for
    //! a profile that reaches a = 0 before its speed tops out, so a profile that carries its
    //! acceleration into the piece may not be checked against them (run_merge.hpp).
    bool limits_need_knee = false;
};

//! One piece of a run as the check sees it: its length along the run and its check, or, where
//! the check knows no curved axis and `limits` is set, its rectangular (v, a, j) limits.
struct CheckedSpan {
    double length = 0;  //!< mm
    const PieceCheck* check = nullptr;
    const ProfileLimits* limits = nullptr;
};

//! Where profile_keeps_pieces found a span out of its limits: its index and its start along
//! the spans (mm). Passed to the next call, that span is checked first.
struct FailedSpan {
    std::size_t index = static_cast<std::size_t>(-1);
    double offset_mm = 0;
};

//! Whether `profile` keeps every axis of every span within its limits: each span's time in the
//! profile is cut at phase boundaries and halved, and on each part the speeds, path accelerations
//! and jerk there must keep q''·ṡ² + q'·s̈ within amax and q'''·ṡ³ + 3·q''·ṡ·s̈ + q'·s⃛ within jmax
//! on every curved axis, in interval arithmetic over the ranges of q', q'', q''' (±d1, ±d2, ±d3
//! where their signs are unknown; the bounds are taken together, so the test errs on the safe
//! side), |s̈| and |s⃛| within the straight axes' limits, and v <= speed_limit; a span with
//! `limits` and no curved axis keeps v, |s̈| and |s⃛| within them instead. `failed`, when given,
//! is checked first and set to the span that fails.
[[nodiscard]] bool profile_keeps_pieces(const Profile& profile, const std::vector<CheckedSpan>& spans,
                                        FailedSpan* failed = nullptr);

//! The fastest profile over `distance` from v_start to v_end with the acceleration and jerk of
//! `limits` and a top speed between limits.max_velocity and `cruise_velocity` that
//! profile_keeps_pieces accepts; `planned` (with limits.max_velocity) when none is faster.
[[nodiscard]] Profile raised_profile(const Profile& planned, double distance, const ProfileLimits& limits,
                                     double cruise_velocity, const std::vector<CheckedSpan>& spans);

}  // namespace nckit::plan_detail
