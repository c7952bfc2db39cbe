#include "notch_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "nckit/plan/path_segment.hpp"
#include "notch_index.hpp"

namespace nckit::notch_detail {

double dot(const AxisVector& a, const AxisVector& b) {
    double sum = 0;
    for (std::size_t i = 0; i < axis_count; ++i) sum += a[i] * b[i];
    return sum;
}

AxisVector scaled(const AxisVector& a, double k) {
    AxisVector out = a;
    for (double& x : out.value) x *= k;
    return out;
}

std::optional<Ends> motion_ends(const Move& move) {
    if (const auto* line = std::get_if<Line>(&move.what)) return Ends{line->from, line->to};
    if (const auto* arc = std::get_if<Arc>(&move.what)) return Ends{arc->from, arc->to};
    if (const auto* sync = std::get_if<SyncMove>(&move.what)) return Ends{sync->from, sync->to};
    return std::nullopt;
}

std::vector<AxisVector> path_polyline(const Move& move, double tolerance_mm) {
    if (const auto* arc = std::get_if<Arc>(&move.what)) {
        const PathSegment segment = make_arc(*arc);
        const double sweep = std::abs(segment.sweep_rad());
        // A chord of angle θ strays r(1 - cos(θ/2)) from its arc.
        const double r = std::max(segment.radius_mm, tolerance_mm);
        const double chord_angle = 2.0 * std::acos(std::max(-1.0, 1.0 - tolerance_mm / r));
        const auto chords =
            static_cast<std::size_t>(std::clamp(std::ceil(sweep / std::max(chord_angle, 1e-9)), 1.0, 100000.0));
        std::vector<AxisVector> points;
        points.reserve(chords + 1);
        for (std::size_t k = 0; k <= chords; ++k) {
            points.push_back(
                position_at(segment, segment.length * static_cast<double>(k) / static_cast<double>(chords)));
        }
        return points;
    }
    if (auto ends = motion_ends(move)) return {ends->from, ends->to};
    return {};
}

double segment_distance(const AxisVector& p0, const AxisVector& p1, const AxisVector& q0, const AxisVector& q1) {
    // Closest points of two segments (Ericson, Real-Time Collision Detection, 5.1.9), any dimension.
    const AxisVector d1 = p1 - p0;
    const AxisVector d2 = q1 - q0;
    const AxisVector r = p0 - q0;
    const double a = dot(d1, d1);
    const double e = dot(d2, d2);
    const double f = dot(d2, r);
    constexpr double tiny = 1e-18;
    double s = 0;
    double t = 0;
    if (a <= tiny && e <= tiny) {
        s = t = 0;
    } else if (a <= tiny) {
        t = std::clamp(f / e, 0.0, 1.0);
    } else {
        const double c = dot(d1, r);
        if (e <= tiny) {
            s = std::clamp(-c / a, 0.0, 1.0);
        } else {
            const double b = dot(d1, d2);
            const double denom = a * e - b * b;
            s = denom > tiny * a * e ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
            t = (b * s + f) / e;
            if (t < 0) {
                t = 0;
                s = std::clamp(-c / a, 0.0, 1.0);
            } else if (t > 1) {
                t = 1;
                s = std::clamp((b - c) / a, 0.0, 1.0);
            }
        }
    }
    const AxisVector gap = (p0 + scaled(d1, s)) - (q0 + scaled(d2, t));
    return std::sqrt(dot(gap, gap));
}

}  // namespace nckit::notch_detail

namespace nckit::notch_detail {

SweepIndex::SweepIndex(const std::vector<Segment>& segments) {
    // The axis along which the segments' starts spread most separates them best.
    double best_spread = -1;
    for (std::size_t a = 0; a < axis_count && !segments.empty(); ++a) {
        double lo = segments.front().from[a];
        double hi = lo;
        for (const Segment& s : segments) {
            lo = std::min(lo, s.from[a]);
            hi = std::max(hi, s.from[a]);
        }
        if (hi - lo > best_spread) {
            best_spread = hi - lo;
            axis_ = a;
        }
    }
    entries_.reserve(segments.size());
    for (std::size_t i = 0; i < segments.size(); ++i) {
        const double a = segments[i].from[axis_];
        const double b = segments[i].to[axis_];
        entries_.push_back({std::min(a, b), std::max(a, b), static_cast<std::uint32_t>(i)});
        max_extent_ = std::max(max_extent_, std::abs(b - a));
    }
    std::sort(entries_.begin(), entries_.end(), [](const Entry& x, const Entry& y) { return x.lo < y.lo; });
}

void SweepIndex::query(const AxisVector& from, const AxisVector& to, double pad_mm,
                       const std::function<void(std::size_t)>& visit) const {
    const double lo = std::min(from[axis_], to[axis_]) - pad_mm;
    const double hi = std::max(from[axis_], to[axis_]) + pad_mm;
    // An entry overlaps when entry.lo <= hi and entry.hi >= lo; entry.hi <= entry.lo + max_extent_.
    auto first = std::lower_bound(entries_.begin(), entries_.end(), lo - max_extent_,
                                  [](const Entry& e, double v) { return e.lo < v; });
    for (auto it = first; it != entries_.end() && it->lo <= hi; ++it) {
        if (it->hi >= lo) visit(it->id);
    }
}

}  // namespace nckit::notch_detail
