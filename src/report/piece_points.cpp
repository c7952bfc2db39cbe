#include "piece_points.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace nckit::report_detail {

namespace {

// The most points one arc is drawn with (a helix of many turns stays drawable).
constexpr int max_arc_points = 4096;

//! Piece-local time at which the profile reaches arc length s of the segment (the profile's
//! position never decreases, so bisection finds it).
double time_at(const TrajectoryPiece& piece, double s) {
    double lo = 0, hi = piece.duration_s;
    for (int i = 0; i < 60 && hi - lo > 1e-12; ++i) {
        const double mid = 0.5 * (lo + hi);
        const double at = piece.profile.at(piece.profile_offset_s + mid).position - piece.profile_offset_mm;
        (at < s ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

}  // namespace

PiecePoints piece_points(const TrajectoryPiece& piece, double arc_step_deg) {
    std::vector<double> times{0.0, piece.duration_s};
    double boundary = 0;
    for (int i = 0; i < piece.profile.phase_count; ++i) {
        boundary += piece.profile.phases[i].duration_s;
        const double local = boundary - piece.profile_offset_s;
        if (local > 0 && local < piece.duration_s) times.push_back(local);
    }
    if (piece.segment.shape == SegmentShape::arc && piece.segment.length > 0) {
        const double sweep_deg = std::abs(piece.segment.sweep_rad()) * 180.0 / std::numbers::pi;
        const int n = std::clamp(static_cast<int>(std::ceil(sweep_deg / arc_step_deg)), 1, max_arc_points);
        for (int k = 1; k < n; ++k) times.push_back(time_at(piece, piece.segment.length * k / n));
    }
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end()), times.end());
    PiecePoints out;
    out.points.reserve(times.size());
    for (std::size_t i = 0; i < times.size(); ++i) {
        const TrajectorySample s = sample(piece, piece.start_time_s + times[i]);
        const double xyz = std::hypot(s.velocity[Axis::X], s.velocity[Axis::Y], s.velocity[Axis::Z]);
        const double speed = xyz > 0 ? xyz : std::abs(s.path_velocity);
        out.points.push_back({s.position[Axis::X], s.position[Axis::Y], s.position[Axis::Z], speed});
        out.peak_mm_s = std::max(out.peak_mm_s, s.path_velocity);
        if (i == 0) out.start_mm_s = s.path_velocity;
        out.end_mm_s = s.path_velocity;
    }
    return out;
}

}  // namespace nckit::report_detail
