#include "nckit/interp/move_summary.hpp"

#include <algorithm>
#include <cmath>

#include "nckit/interp/arc_geometry.hpp"

namespace nckit {

namespace {

double xyz_distance(const AxisVector& a, const AxisVector& b) {
    return std::hypot(b[Axis::X] - a[Axis::X], b[Axis::Y] - a[Axis::Y], b[Axis::Z] - a[Axis::Z]);
}

double minutes_to_seconds(double length_mm, const Feed& feed) {
    return feed.mm_per_min > 0 ? length_mm / feed.mm_per_min * 60.0 : 0.0;
}

}  // namespace

double arc_length_mm(const Arc& arc) {
    PlaneAxes p = plane_axes(arc.plane);
    double radius = 0.5 * (arc_start_radius(arc) + arc_end_radius(arc));
    double in_plane = radius * arc_sweep_rad(arc);
    double along_normal = arc.to[p.normal] - arc.from[p.normal];
    return std::hypot(in_plane, along_normal);
}

void MoveSummary::add(const Move& move) {
    auto extend = [&](const AxisVector& lo, const AxisVector& hi) {
        if (!any_motion) {
            low = lo;
            high = hi;
            any_motion = true;
            return;
        }
        for (std::size_t i = 0; i < axis_count; ++i) {
            low[i] = std::min(low[i], lo[i]);
            high[i] = std::max(high[i], hi[i]);
        }
    };
    auto extend_line = [&](const AxisVector& from, const AxisVector& to) {
        AxisVector lo;
        AxisVector hi;
        for (std::size_t i = 0; i < axis_count; ++i) {
            lo[i] = std::min(from[i], to[i]);
            hi[i] = std::max(from[i], to[i]);
        }
        extend(lo, hi);
    };
    if (const auto* line = std::get_if<Line>(&move.what)) {
        double length = xyz_distance(line->from, line->to);
        if (line->rapid) {
            ++rapids;
            rapid_length_mm += length;
        } else {
            ++lines;
            cutting_length_mm += length;
            feed_time_s += minutes_to_seconds(length, line->feed);
        }
        extend_line(line->from, line->to);
    } else if (const auto* arc = std::get_if<Arc>(&move.what)) {
        ++arcs;
        double length = arc_length_mm(*arc);
        cutting_length_mm += length;
        feed_time_s += minutes_to_seconds(length, arc->feed);
        AxisBox box = arc_bounds(*arc);
        extend(box.low, box.high);
    } else if (const auto* sync = std::get_if<SyncMove>(&move.what)) {
        ++syncs;
        double length = xyz_distance(sync->from, sync->to);
        cutting_length_mm += length;
        feed_time_s += minutes_to_seconds(length, sync->feed);
        extend_line(sync->from, sync->to);
    } else if (const auto* dwell = std::get_if<Dwell>(&move.what)) {
        ++dwells;
        dwell_s += dwell->seconds;
    } else {
        ++ios;
    }
}

}  // namespace nckit
