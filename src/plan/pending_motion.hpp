#pragma once
// The motion the planner holds back until the next one is known (its end may still be trimmed
// by a blend), and the join of two such motions by a quintic transition.
#include <cstdint>
#include <optional>

#include "transition.hpp"
#include "nckit/core/source_location.hpp"
#include "nckit/interp/move.hpp"
#include "nckit/plan/path_segment.hpp"
#include "nckit/plan/profile.hpp"

namespace nckit::plan_detail {

//! A transition that may be absent, like std::optional, but whose storage outlives reset():
//! a transition is about 1.6 kB, and constructing a fresh (zeroed) one for every move of a CAM
//! chain cost more than building the curve in it. emplace() hands back the storage as the last
//! transition left it; make_transition sets every field of it.
class TransitionSlot {
public:
    [[nodiscard]] explicit operator bool() const { return engaged_; }
    [[nodiscard]] Transition& operator*() { return value_; }
    [[nodiscard]] const Transition& operator*() const { return value_; }
    [[nodiscard]] Transition* operator->() { return &value_; }
    [[nodiscard]] const Transition* operator->() const { return &value_; }
    Transition& emplace() {
        engaged_ = true;
        return value_;
    }
    void reset() { engaged_ = false; }

private:
    Transition value_;
    bool engaged_ = false;
};

//! The last motion, whose end may still be trimmed by a blend with the next one.
struct PendingMotion {
    PathSegment path;
    double full_length = 0;  //!< programmed length, for the half-line rule
    //! Computed when first needed: a short line of a CAM chain is usually eaten whole by the
    //! transitions at its ends, and then its own limits never matter.
    std::optional<ProfileLimits> limits;
    double normal_share = 0.5;    //!< of the acceleration, for the curvature term
    double feed_mm_s = 0;         //!< +inf for rapids
    bool blendable = false;       //!< a G1 line or a G2/G3 arc: its ends may be rounded
    bool spindle_locked = false;  //!< G32/G33: moves at the spindle's speed
    PathControl control;
    SourceLocation where;
    std::int64_t sequence_number = -1;
    //! The transition into this motion, held back until the next join is known: when that
    //! join's transition eats the whole of this motion, both meet with a common curvature.
    TransitionSlot entry;
    double entry_feed_mm_s = 0;
    double entry_tolerance_mm = 0;  //!< mm, the tolerance it was built within
    SourceLocation entry_where;
    std::int64_t entry_number = -1;
};

//! Joins `p` (the pending motion) and `next` by a quintic transition within `tolerance`, each
//! side giving at most half its programmed length: on success p's end and next's start are
//! trimmed and the transition becomes next.entry (fed at the lower of the two feeds, located at
//! p); p is then ready to be released. False, with both untouched, when no transition keeps the
//! tolerance. With `turning` (jerk-limited plans) a tangent join of an arc may get a ramp
//! transition (make_transition). When `starts_at_rest` (p follows a stop), a short line p before a
//! line may be taken whole into the transition, which then leaves p's start already turning.
[[nodiscard]] bool join_by_transition(PendingMotion& p, PendingMotion& next, double tolerance,
                                      const TurningLimits* turning = nullptr, bool starts_at_rest = false);

//! Before a stop, the rest of a line p that its chained entry transition trimmed (p is the last
//! line of a CAM chain, the line before it eaten) is taken into that transition, which then ends
//! at p's end with the curvature it started with: at rest
//! the curvature is free, so a chain of CAM lines ending there does not ramp its curvature down
//! to zero at the last line's middle. Within the tolerance the transition was built with; false,
//! with p untouched, when that keeps no tolerance.
[[nodiscard]] bool end_at_rest(PendingMotion& p);

}  // namespace nckit::plan_detail
