#include "pending_motion.hpp"

#include <algorithm>
#include <array>

namespace nckit::plan_detail {

bool join_by_transition(PendingMotion& p, PendingMotion& next, double tolerance, const TurningLimits* turning) {
    // Built in place: a transition is a large value, and this runs once per move of a chain.
    auto xyz = [](const AxisVector& v) { return std::array<double, 3>{v[0], v[1], v[2]}; };
    ChainStart chain;
    // A chain starts only after a single quintic (a ramp transition's end is not rebuilt).
    const bool chained_entry = p.entry && p.entry->more.empty();
    if (chained_entry) {
        chain.entry_length = p.entry->curve.length;
        chain.entry_start_d1 = xyz(p.entry->start.d1);
    }
    const double before_room = 0.5 * p.full_length;
    const double after_room = 0.5 * next.path.length;
    auto& t = next.entry.emplace();
    if (!make_transition(p.path, before_room, next.path, after_room, tolerance, t, chained_entry ? &chain : nullptr,
                         turning)) {
        next.entry.reset();
        return false;
    }
    // When t is chained, p is eaten by its two transitions: they meet at its middle, in its
    // direction, with the curvature of the turn between their outer ends (transition.hpp). The
    // one into p is rebuilt to end there; failing the tolerance, both stay as built (no curvature).
    if (t.chained &&
        !rebuild_with_end_state(*p.entry, xyz(p.entry->end.position), xyz(t.start.d1), xyz(t.start.d2), tolerance) &&
        !make_transition(p.path, before_room, next.path, after_room, tolerance, t, nullptr, turning)) {
        next.entry.reset();
        return false;
    }
    p.path.length -= t.trim_before;
    trim_start_into(next.path, next.path, t.trim_after);
    next.entry_feed_mm_s = std::min(p.feed_mm_s, next.feed_mm_s);
    next.entry_where = p.where;
    next.entry_number = p.sequence_number;
    return true;
}

}  // namespace nckit::plan_detail
