// The planned path speed over a programmed cut, sampled from the planner's exact trajectory.
#include <algorithm>
#include <cmath>

#include "nckit/process/notch.hpp"
#include "notch_geometry.hpp"

namespace nckit {

namespace {

using notch_detail::dot;
using notch_detail::scaled;

struct SpeedSample {
    double s = 0;        // mm from the programmed start along the cut
    double speed = 0;    // mm/min
};

}  // namespace

CutSpeed measure_cut_speed(const Trajectory& trajectory, const NotchCut& cut, const NotchOptions& options) {
    const double length = cut.length_mm;
    const AxisVector rate = scaled(cut.end - cut.start, 1.0 / length);
    const double rate_sq = dot(rate, rate);
    constexpr double on_line_mm = 1e-6;
    std::vector<SpeedSample> samples;
    for (const TrajectoryPiece& piece : trajectory.pieces) {
        if (piece.kind != PieceKind::motion || piece.segment.shape != SegmentShape::line) continue;
        // Only path running along the cut line towards the programmed end.
        const AxisVector along = piece.segment.rate - rate;
        if (std::sqrt(dot(along, along)) > 1e-9) continue;
        const AxisVector offset = piece.segment.origin - cut.start;
        const double s0 = dot(offset, rate) / rate_sq;
        const AxisVector off_line = offset - scaled(rate, s0);
        if (std::sqrt(dot(off_line, off_line)) > on_line_mm) continue;
        const double s1 = s0 + piece.segment.length;
        if (s1 < -on_line_mm || s0 > length + on_line_mm) continue;
        const auto steps = static_cast<std::size_t>(std::ceil(piece.duration_s / options.sample_period_s));
        for (std::size_t k = 0; k <= steps; ++k) {
            const double t = piece.start_time_s +
                             (steps == 0 ? 0.0 : piece.duration_s * static_cast<double>(k) / static_cast<double>(steps));
            const TrajectorySample state = sample(piece, t);
            const double s = dot(state.position - cut.start, rate) / rate_sq;
            if (s < -on_line_mm || s > length + on_line_mm) continue;
            samples.push_back({std::clamp(s, 0.0, length), state.path_velocity * 60.0});
        }
    }
    CutSpeed out;
    if (samples.empty()) return out;
    std::stable_sort(samples.begin(), samples.end(), [](const SpeedSample& a, const SpeedSample& b) { return a.s < b.s; });
    out.min_mm_min = samples.front().speed;
    out.max_mm_min = samples.front().speed;
    double integral = 0;
    for (std::size_t i = 0; i < samples.size(); ++i) {
        out.min_mm_min = std::min(out.min_mm_min, samples[i].speed);
        out.max_mm_min = std::max(out.max_mm_min, samples[i].speed);
        if (i > 0) integral += 0.5 * (samples[i].speed + samples[i - 1].speed) * (samples[i].s - samples[i - 1].s);
    }
    out.covered_mm = samples.back().s - samples.front().s;
    out.mean_mm_min = out.covered_mm > 0 ? integral / out.covered_mm : samples.front().speed;

    // Evenly spaced in s, the speed interpolated between the neighbouring samples.
    const std::size_t points = std::max<std::size_t>(options.profile_points, 2);
    std::size_t i = 0;
    for (std::size_t k = 0; k < points; ++k) {
        const double s = samples.front().s + out.covered_mm * static_cast<double>(k) / static_cast<double>(points - 1);
        while (i + 1 < samples.size() && samples[i + 1].s < s) ++i;
        double speed = samples[i].speed;
        if (i + 1 < samples.size() && samples[i + 1].s > samples[i].s) {
            const double w = std::clamp((s - samples[i].s) / (samples[i + 1].s - samples[i].s), 0.0, 1.0);
            speed = samples[i].speed + w * (samples[i + 1].speed - samples[i].speed);
        }
        const double coordinate = cut.profile_axis ? cut.start[*cut.profile_axis] + s * rate[*cut.profile_axis] : s;
        out.profile.push_back({coordinate, speed});
    }
    return out;
}

}  // namespace nckit
