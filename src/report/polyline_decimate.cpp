#include "polyline_decimate.hpp"

#include <algorithm>
#include <cmath>

namespace nckit::report_detail {

namespace {

//! Distance from p to the chord a–b, and the fraction along it of p's foot point.
struct Foot {
    double distance_mm;
    double fraction;
};

Foot foot(const ReportVertex& a, const ReportVertex& b, const ReportVertex& p) {
    const double dx = b.x_mm - a.x_mm, dy = b.y_mm - a.y_mm, dz = b.z_mm - a.z_mm;
    const double px = p.x_mm - a.x_mm, py = p.y_mm - a.y_mm, pz = p.z_mm - a.z_mm;
    const double len2 = dx * dx + dy * dy + dz * dz;
    double f = len2 > 0 ? (px * dx + py * dy + pz * dz) / len2 : 0.0;
    f = std::clamp(f, 0.0, 1.0);
    return {std::hypot(px - f * dx, py - f * dy, pz - f * dz), f};
}

bool chord_holds(const std::vector<ReportVertex>& points, std::size_t from, std::size_t to, double tolerance_mm,
                 double speed_tolerance_mm_s) {
    const ReportVertex& a = points[from];
    const ReportVertex& b = points[to];
    for (std::size_t i = from + 1; i < to; ++i) {
        const Foot f = foot(a, b, points[i]);
        if (f.distance_mm > tolerance_mm) return false;
        const double speed = a.speed_mm_s + f.fraction * (b.speed_mm_s - a.speed_mm_s);
        if (std::abs(speed - points[i].speed_mm_s) > speed_tolerance_mm_s) return false;
    }
    return true;
}

}  // namespace

std::vector<ReportVertex> decimate(const std::vector<ReportVertex>& points, double tolerance_mm,
                                   double speed_tolerance_mm_s, std::size_t window) {
    std::vector<ReportVertex> kept;
    if (points.size() < 2) return kept;
    std::size_t anchor = 0;
    while (anchor + 1 < points.size()) {
        // The farthest point the chord from the anchor can reach with every point between in
        // tolerance; the next point is always reachable.
        std::size_t reach = anchor + 1;
        const std::size_t last = std::min(points.size() - 1, anchor + window);
        for (std::size_t to = anchor + 2; to <= last; ++to) {
            if (!chord_holds(points, anchor, to, tolerance_mm, speed_tolerance_mm_s)) break;
            reach = to;
        }
        kept.push_back(points[reach]);
        anchor = reach;
    }
    return kept;
}

}  // namespace nckit::report_detail
