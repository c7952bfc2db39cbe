#pragma once
// Under a jerk limit, whether a sharp corner between two lines is passed faster by stopping at
// it than through its transition. Within a tight G64 P a sharp corner's quintic is tiny and so
// tightly curved that its speed limit is a few mm/s: crossing it takes longer than the speed
// it keeps saves on either side (docs/planner.md, "Sharp corners: stop or pass").
#include "pending_motion.hpp"
#include "transition.hpp"

namespace nckit::plan_detail {

//! True when stopping exactly at the corner is faster than passing through `transition` (built
//! between the lines `before` and `after`, not yet trimmed) at its turning speed, fed at
//! feed_mm_s. The comparison covers the same stretch of path both ways: on each side the speed
//! change between the line's speed and the corner's (from rest when stopping), and the
//! transition's length at its speed against the lines' corner at theirs.
[[nodiscard]] bool stop_is_faster(const Transition& transition, const PathSegment& before, const PathSegment& after,
                                  double feed_mm_s, const TurningLimits& limits);

//! After join_by_transition joined the lines p and next by a plain corner transition (not a
//! chained one, p not eaten): when stopping at the corner is faster, undoes the join (both lines
//! as programmed, next without its entry) and returns true; otherwise leaves both as joined.
[[nodiscard]] bool unjoin_for_a_stop(PendingMotion& p, PendingMotion& next, const TurningLimits& limits);

}  // namespace nckit::plan_detail
