#pragma once
// The time at which a profile reaches given positions: where one run's profile crosses the
// junctions between its segments.
#include "nckit/plan/profile.hpp"

namespace nckit::plan_detail {

//! Walks a profile forwards; queries must come with non-decreasing positions.
class ProfileWalker {
public:
    explicit ProfileWalker(const Profile& profile) : profile_(profile) {}

    //! s, the first time the profile is at position_mm (clamped into the profile), found by
    //! a bracketed Newton search on the phase's cubic (monotone, since v >= 0).
    [[nodiscard]] double time_at(double position_mm);

private:
    const Profile& profile_;
    int phase_ = 0;
    double phase_start_s_ = 0;
    double p_ = 0;  //!< mm at the phase start (relative to start_position)
    double v_ = 0;  //!< mm/s at the phase start
    bool started_ = false;
};

}  // namespace nckit::plan_detail
