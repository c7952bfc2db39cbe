#pragma once
// Consecutive S-curve runs planned as one profile. A run starts and ends with zero path
// acceleration, so a speed change that crosses several runs (braking from a line through the
// pieces of a transition whose speed limits fall towards an arc) used to be a staircase of
// S-curves, each bringing the acceleration back to 0. One profile over the runs carries its
// acceleration across their boundaries; it is kept only where every segment's axes keep their
// limits along it (docs/planner.md, "Speed changes across runs").
#include <vector>

#include "cruise_raise.hpp"
#include "nckit/plan/profile.hpp"

namespace nckit::plan_detail {

//! Whether a segment may lie inside a merged profile: its limits hold for any motion within
//! them (lines, whole segments) or its curved axes are known (PieceCheck), not a piece whose
//! limits count the knee and whose axes are unknown.
[[nodiscard]] inline bool mergeable(const PieceCheck& check) {
    return check.count > 0 || !check.limits_need_knee;
}

//! +1 when `profile` ends speeding up (its last phase brings a > 0 back to 0), -1 braking, 0
//! holding its speed (or no phase).
[[nodiscard]] int end_direction(const Profile& profile);
//! +1 when `profile` starts by speeding up, -1 by braking, 0 by holding its speed (or no phase).
[[nodiscard]] int start_direction(const Profile& profile);

//! The rates a merged profile tries: from the fastest segment's acceleration and jerk down to
//! the slowest one's.
struct MergeRates {
    ProfileLimits widest;    //!< the highest speed, acceleration and jerk of the runs
    ProfileLimits tightest;  //!< the lowest acceleration and jerk of the runs
    //! Every span is a curved piece with its axes known: rates above the widest are tried too.
    bool curved = false;
};

//! The fastest profile over `distance` from v_start to v_end (both kept exactly) among S-curves
//! with an acceleration and jerk between rates.tightest's and rates.widest's and a top speed up
//! to rates.widest.max_velocity that profile_keeps_pieces accepts on `spans`; false when none
//! is. The search is bounded: six rate levels, seven top speeds each.
[[nodiscard]] bool merged_profile(double distance, double v_start, double v_end, const MergeRates& rates,
                                  const std::vector<CheckedSpan>& spans, Profile& out);

}  // namespace nckit::plan_detail
