#include "pending_motion.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "chain_state.hpp"

namespace nckit::plan_detail {

namespace {

//! p, a short line from rest, is taken whole into the transition to `next` (a line), which then
//! leaves p's start with the curvature of the turn it makes: at rest the curvature is free (the
//! axes' acceleration q'·s̈ + q''·ṡ² and jerk do not see it), and a chain of CAM lines starting
//! there has no curvature to ramp up from zero at the first line's middle (docs/planner.md,
//! "CAM polylines"). False, with t undefined, when that transition does not keep the tolerance.
bool start_from_rest(const PendingMotion& p, const PendingMotion& next, double tolerance, Transition& t) {
    if (!make_transition(p.path, p.full_length, next.path, 0.5 * next.path.length, tolerance, t)) return false;
    if (t.trim_before != p.path.length) return false;
    // The chords' directions turn by (after − p) between their middles, (trims_before + L)/2
    // apart on the curve they sample; at p's start the curve's direction is p's turned back by
    // half of p's share of that turn.
    const double h = t.trim_before;
    const double spacing = t.curve.length - 0.5 * h;
    std::array<double, 3> turn{};
    for (std::size_t i = 0; i < 3; ++i) turn[i] = (t.end.d1[i] - t.start.d1[i]) / spacing;
    std::array<double, 3> start_d1{};
    for (std::size_t i = 0; i < 3; ++i) start_d1[i] = t.start.d1[i];
    const DirectionState start = turned_state(start_d1, turn, -0.5 * h);
    std::array<double, 3> end_d1{};
    std::array<double, 3> end_d2{};
    for (std::size_t i = 0; i < 3; ++i) {
        end_d1[i] = t.end.d1[i];
        end_d2[i] = t.end.d2[i];
    }
    if (const auto curved = with_end_states(t, start.d1, start.d2, end_d1, end_d2, tolerance)) apply(t, *curved);
    return true;
}

}  // namespace

bool join_by_transition(PendingMotion& p, PendingMotion& next, double tolerance, const TurningLimits* turning,
                        bool starts_at_rest) {
    // A short line from rest before a line of a chain (jerk-limited plans only).
    if (starts_at_rest && turning != nullptr && !p.entry && p.path.shape == SegmentShape::line &&
        next.path.shape == SegmentShape::line && p.path.length == p.full_length && p.full_length <= next.path.length) {
        auto& t = next.entry.emplace();
        if (start_from_rest(p, next, tolerance, t)) {
            p.path.length = 0;
            next.path = trim_start(next.path, t.trim_after);
            next.entry_feed_mm_s = std::min(p.feed_mm_s, next.feed_mm_s);
            next.entry_tolerance_mm = tolerance;
            next.entry_where = p.where;
            next.entry_number = p.sequence_number;
            return true;
        }
        next.entry.reset();
    }
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
    // The meeting point lies on the curve the chain samples (chain_state.hpp), not on p.
    // The entry keeps the tolerance it was built within (p's may be wider).
    if (t.chained &&
        !rebuild_with_end_state(*p.entry, xyz(t.start.position), xyz(t.start.d1), xyz(t.start.d2),
                                std::min(tolerance, p.entry_tolerance_mm)) &&
        !make_transition(p.path, before_room, next.path, after_room, tolerance, t, nullptr, turning)) {
        next.entry.reset();
        return false;
    }
    p.path.length -= t.trim_before;
    trim_start_into(next.path, next.path, t.trim_after);
    next.entry_feed_mm_s = std::min(p.feed_mm_s, next.feed_mm_s);
    next.entry_tolerance_mm = tolerance;
    next.entry_where = p.where;
    next.entry_number = p.sequence_number;
    return true;
}

bool end_at_rest(PendingMotion& p) {
    // Only the last line of a CAM chain (its entry chained): a short line after a single corner
    // keeps its own piece, at the programmed point where the program stops.
    if (!p.entry || !p.entry->chained || !p.entry->more.empty() || p.path.shape != SegmentShape::line ||
        p.entry->replaced_after.shape != SegmentShape::line || p.entry->replaced_before.shape != SegmentShape::line ||
        !(p.path.length > 0) || p.full_length > p.entry->curve.length + p.entry->trim_after) {
        return false;
    }
    Transition t = *p.entry;
    // The curve's direction at p's end: p's turned on by half of p's share of the turn the
    // entry starts with (its start lies on the curve the chain samples, chain_state.hpp).
    const double h = p.full_length;
    std::array<double, 3> start_d1{};
    std::array<double, 3> start_d2{};
    std::array<double, 3> rate{};
    for (std::size_t i = 0; i < 3; ++i) {
        start_d1[i] = t.start.d1[i];
        start_d2[i] = t.start.d2[i];
        rate[i] = p.path.rate[i];
    }
    const DirectionState end = turned_state(rate, start_d2, 0.5 * h);
    t.trim_after += p.path.length;
    t.replaced_after.length = t.trim_after;
    t.end.position = end_point(p.path);
    const auto rebuilt = with_end_states(t, start_d1, start_d2, end.d1, end.d2, p.entry_tolerance_mm);
    if (!rebuilt) return false;
    apply(t, *rebuilt);
    *p.entry = std::move(t);
    p.path.length = 0;
    return true;
}

}  // namespace nckit::plan_detail
