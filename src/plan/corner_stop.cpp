#include "corner_stop.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "nckit/plan/profile.hpp"
#include "ramp_transition.hpp"
#include "rates.hpp"

namespace nckit::plan_detail {
namespace {

//! A line's path limits from the axes' (the axis that moves most against its limit sets them).
ProfileLimits line_limits(const PathSegment& line, double feed_mm_s, const TurningLimits& limits) {
    ProfileLimits out{feed_mm_s, std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    for (std::size_t i = 0; i < 3; ++i) {
        const double share = std::abs(line.rate[i]);
        if (!(share > 0)) continue;
        out.max_acceleration = std::min(out.max_acceleration, limits.max_acceleration[i] / share);
        out.max_jerk = std::min(out.max_jerk, limits.max_jerk[i] / share);
    }
    return out;
}

//! s, what changing between v and cruise costs against cruising the same distance: its time
//! less the distance it covers (at the mean of its end speeds) over cruise.
double change_cost_s(double v_mm_s, double cruise_mm_s, const Rates& rates) {
    if (!(cruise_mm_s > v_mm_s)) return 0;
    const double t = change_time(cruise_mm_s - v_mm_s, rates);
    return t * (cruise_mm_s - v_mm_s) / (2.0 * cruise_mm_s);
}

}  // namespace

bool stop_is_faster(const Transition& transition, const PathSegment& before, const PathSegment& after, double feed_mm_s,
                    const TurningLimits& limits) {
    if (before.shape != SegmentShape::line || after.shape != SegmentShape::line || !transition.more.empty()) {
        return false;
    }
    const double corner_mm_s = std::min(turning_speed(transition, limits), feed_mm_s);
    if (!(corner_mm_s > 0)) return true;
    double cost_s = 0;  // stopping against passing
    double slowest_cruise = feed_mm_s;
    for (const PathSegment* line : {&before, &after}) {
        const ProfileLimits path = line_limits(*line, feed_mm_s, limits);
        // The speed a line reaches from the corner: over half its length (its other end may be
        // a corner as well).
        const double cruise = max_end_speed(0.5 * line->length, 0.0, path, ProfileKind::scurve);
        slowest_cruise = std::min(slowest_cruise, cruise);
        const Rates rates = make_rates(path, ProfileKind::scurve);
        cost_s += change_cost_s(0.0, cruise, rates) - change_cost_s(corner_mm_s, cruise, rates);
    }
    if (!(slowest_cruise > corner_mm_s)) return false;
    const double crossing_s =
        transition.curve.length / corner_mm_s - (transition.trim_before + transition.trim_after) / slowest_cruise;
    return crossing_s > cost_s;
}

bool unjoin_for_a_stop(PendingMotion& p, PendingMotion& next, const TurningLimits& limits) {
    if (!next.entry) return false;
    const Transition& t = *next.entry;
    if (t.chained || !(p.path.length > 0) || p.path.shape != SegmentShape::line ||
        next.path.shape != SegmentShape::line) {
        return false;
    }
    // The lines as they were before the transition's trims (replaced_after is the whole of
    // next's path, cut to the trim's length).
    PathSegment after = t.replaced_after;
    after.length = next.path.length + t.trim_after;
    const double trimmed_mm = p.path.length;
    p.path.length += t.trim_before;
    if (stop_is_faster(t, p.path, after, next.entry_feed_mm_s, limits)) {
        next.path = after;
        next.entry.reset();
        return true;
    }
    p.path.length = trimmed_mm;  // exactly as joined
    return false;
}

}  // namespace nckit::plan_detail
