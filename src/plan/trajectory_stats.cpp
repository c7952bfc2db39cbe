#include "nckit/plan/trajectory_stats.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

#include <fmt/format.h>

namespace nckit {

void PeakTracker::take(const TrajectorySample& s) {
    for (std::size_t i = 0; i < axis_count; ++i) {
        peaks_.max_velocity[i] = std::max(peaks_.max_velocity[i], std::abs(s.velocity[i]));
        peaks_.max_acceleration[i] = std::max(peaks_.max_acceleration[i], std::abs(s.acceleration[i]));
        peaks_.max_jerk[i] = std::max(peaks_.max_jerk[i], std::abs(s.jerk[i]));
    }
}

void PeakTracker::add(const TrajectoryPiece& piece) {
    if (piece.kind != PieceKind::motion || piece.duration_s <= 0) return;
    // The piece covers [offset, offset + duration] of its profile (runs of tangent segments
    // share one profile); walk the profile's phases that overlap it.
    const double begin = piece.profile_offset_s;
    const double end = begin + piece.duration_s;
    double phase_start = 0;
    for (int p = 0; p < piece.profile.phase_count; ++p) {
        double phase_end = phase_start + piece.profile.phases[static_cast<std::size_t>(p)].duration_s;
        double from = std::max(phase_start, begin);
        double to = std::min(phase_end, end);
        phase_start = phase_end;
        if (to <= from) continue;
        // Just inside both ends of the phase: jerk and (for trapezoids) acceleration jump there.
        double inside = std::min((to - from) * 1e-9, 1e-12);
        double t0 = piece.start_time_s + (from - begin);
        double span = to - from;
        take(sample(piece, t0 + inside));
        for (int k = 1; k < points_per_phase_; ++k) take(sample(piece, t0 + span * k / points_per_phase_));
        take(sample(piece, t0 + span - inside));
    }
}

TraceWriter::TraceWriter(const MachineConfig& machine, double period_s) : sampler_(period_s, SamplerEnd::within_cycle) {
    for (const AxisConfig& axis : machine.axes) axes_.insert(axis.axis);
}

std::string TraceWriter::header() const {
    std::string out = "t";
    for (const char* prefix : {"", "v", "a", "j"}) {
        for (std::size_t i = 0; i < axis_count; ++i) {
            auto axis = static_cast<Axis>(i);
            if (axes_.contains(axis)) fmt::format_to(std::back_inserter(out), ",{}{}", prefix, letter(axis));
        }
    }
    return out + "\n";
}

void TraceWriter::row(const TrajectorySample& s, std::string& out) const {
    fmt::format_to(std::back_inserter(out), "{}", s.t);
    for (const AxisVector* values : {&s.position, &s.velocity, &s.acceleration, &s.jerk}) {
        for (std::size_t i = 0; i < axis_count; ++i) {
            // + 0.0 turns -0 into 0: a trace read by people and plotting tools.
            if (axes_.contains(static_cast<Axis>(i)))
                fmt::format_to(std::back_inserter(out), ",{}", (*values)[i] + 0.0);
        }
    }
    out += '\n';
}

void TraceWriter::add(const TrajectoryPiece& piece, std::string& out) {
    sampler_.add(piece, [&](const TrajectorySample& s) { row(s, out); });
}

void TraceWriter::finish(std::string& out) {
    sampler_.finish([&](const TrajectorySample& s) { row(s, out); });
}

}  // namespace nckit
