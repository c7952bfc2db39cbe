// The planned path speed over a programmed cut, sampled from the planner's exact trajectory.
//
// The cut is measured once, in time order: from the first piece that runs along the cut line
// towards the programmed end and overlaps the cut, over every following piece while they keep
// doing so, up to the first piece that does not (the return after the overrun). A later move on
// the cut line (a short G1 after the laser-off code) is another move, not the cut. Statistics
// are streamed: memory stays bounded however slow the feed (F0.01 takes hours of samples).
#include <algorithm>
#include <cmath>

#include "nckit/process/notch/notch.hpp"
#include "notch_geometry.hpp"
#include "notch_passes.hpp"

namespace nckit {

namespace {

using notch_detail::dot;
using notch_detail::scaled;

constexpr double on_line_mm = 1e-6;
//! However slow the cut, a piece is sampled at most this often: speed within a piece follows
//! a cubic, which a few thousand samples resolve far below the report's precision.
constexpr double max_samples_per_piece = 20000;

//! Streams (s, speed) samples in path order into min, max, mean over s and an evenly spaced
//! profile along the programmed cut.
class SpeedStats {
public:
    SpeedStats(const NotchCut& cut, std::size_t points)
        : cut_(&cut),
          rate_(scaled(cut.end - cut.start, 1.0 / cut.length_mm)),
          points_(std::max<std::size_t>(points, 2)) {}

    void add(double s, double speed) {
        if (count_ == 0) {
            first_s_ = s;
            out_.min_mm_min = out_.max_mm_min = speed;
        } else {
            if (s < last_s_) return;  // never backwards along the cut
            integral_ += 0.5 * (speed + last_speed_) * (s - last_s_);
            while (next_point_ < points_ && point_s(next_point_) <= s) {
                const double at = point_s(next_point_);
                const double w = s > last_s_ ? std::clamp((at - last_s_) / (s - last_s_), 0.0, 1.0) : 1.0;
                if (at >= first_s_) push_point(at, last_speed_ + w * (speed - last_speed_));
                ++next_point_;
            }
        }
        if (count_ == 0) {
            while (next_point_ < points_ && point_s(next_point_) < s) ++next_point_;  // not covered
            if (next_point_ < points_ && point_s(next_point_) == s) {
                push_point(s, speed);
                ++next_point_;
            }
        }
        out_.min_mm_min = std::min(out_.min_mm_min, speed);
        out_.max_mm_min = std::max(out_.max_mm_min, speed);
        last_s_ = s;
        last_speed_ = speed;
        ++count_;
    }

    CutSpeed finish() {
        if (count_ == 0) return out_;
        out_.covered_mm = last_s_ - first_s_;
        out_.mean_mm_min = out_.covered_mm > 0 ? integral_ / out_.covered_mm : last_speed_;
        return std::move(out_);
    }

private:
    [[nodiscard]] double point_s(std::size_t k) const {
        return cut_->length_mm * static_cast<double>(k) / static_cast<double>(points_ - 1);
    }
    void push_point(double s, double speed) {
        const double coordinate =
            cut_->profile_axis ? cut_->start[*cut_->profile_axis] + s * rate_[*cut_->profile_axis] : s;
        out_.profile.push_back({coordinate, speed});
    }

    const NotchCut* cut_;
    AxisVector rate_;
    std::size_t points_;
    std::size_t next_point_ = 0;
    std::int64_t count_ = 0;
    double first_s_ = 0;
    double last_s_ = 0;
    double last_speed_ = 0;
    double integral_ = 0;
    CutSpeed out_;
};

//! Whether a motion piece runs along the cut's line towards its end and overlaps it.
bool on_cut(const TrajectoryPiece& piece, const NotchCut& cut) {
    if (piece.segment.shape != SegmentShape::line || !(piece.duration_s > 0)) return false;
    const AxisVector rate = scaled(cut.end - cut.start, 1.0 / cut.length_mm);
    const AxisVector along = piece.segment.rate - rate;
    const AxisVector offset = piece.segment.origin - cut.start;
    const double s0 = dot(offset, rate) / dot(rate, rate);
    const AxisVector off_line = offset - scaled(rate, s0);
    const double s1 = s0 + piece.segment.length;
    return std::sqrt(dot(along, along)) <= 1e-9 && std::sqrt(dot(off_line, off_line)) <= on_line_mm &&
           s1 >= -on_line_mm && s0 <= cut.length_mm + on_line_mm;
}

//! The samples of a piece on the cut, in time order.
void sample_piece(const TrajectoryPiece& piece, const NotchCut& cut, const NotchOptions& options, SpeedStats& stats) {
    const double length = cut.length_mm;
    const AxisVector rate = scaled(cut.end - cut.start, 1.0 / length);
    const double rate_sq = dot(rate, rate);
    const double period_s = std::max(options.sample_period_s, piece.duration_s / max_samples_per_piece);
    const auto steps = static_cast<std::int64_t>(std::ceil(piece.duration_s / period_s));
    for (std::int64_t k = 0; k <= steps; ++k) {
        const double t = piece.start_time_s + piece.duration_s * static_cast<double>(k) / static_cast<double>(steps);
        const TrajectorySample state = sample(piece, t);
        const double s = dot(state.position - cut.start, rate) / rate_sq;
        if (s < -on_line_mm || s > length + on_line_mm) continue;
        stats.add(std::clamp(s, 0.0, length), state.path_velocity * 60.0);
    }
}

}  // namespace

CutSpeed measure_cut_speed(const Trajectory& trajectory, const NotchCut& cut, const NotchOptions& options) {
    SpeedStats stats(cut, options.profile_points);
    bool started = false;
    for (const TrajectoryPiece& piece : trajectory.pieces) {
        // Dwells, I/O and waits between the pieces of the cut take no path; a motion piece that
        // is not on the cut ends it once it has started.
        if (piece.kind != PieceKind::motion) continue;
        if (!on_cut(piece, cut)) {
            if (started) break;
            continue;
        }
        started = true;
        sample_piece(piece, cut, options, stats);
    }
    return stats.finish();
}

namespace notch_detail {

struct CutMeter::Active {
    std::size_t cut;
    SpeedStats stats;
};

void CutWindow::reindex() {
    std::vector<SweepIndex::Segment> segments;
    segments.reserve(records.size());
    margin_mm = 0;
    for (const CutRecord& cut : records) {
        segments.push_back({cut.info.start, cut.info.end});
        for (std::size_t a = 0; a < axis_count; ++a) {
            margin_mm = std::max(
                margin_mm, on_line_mm * (2.0 + std::abs(cut.info.end[a] - cut.info.start[a]) / cut.info.length_mm));
        }
    }
    lines = SweepIndex(segments);
}

CutMeter::CutMeter(const CutWindow& window, const NotchOptions& options) : window_(window), options_(options) {}

CutMeter::~CutMeter() = default;

void CutMeter::add(const TrajectoryPiece& piece) {
    if (piece.kind != PieceKind::motion) return;
    // Measurements under way: this piece goes on, or ends, each of them.
    for (std::size_t i = 0; i < active_.size();) {
        Active& active = active_[i];
        const NotchCut& cut = window_.at(active.cut).info;
        if (on_cut(piece, cut)) {
            sample_piece(piece, cut, options_, active.stats);
            ++i;
            continue;
        }
        finished_.emplace(active.cut, active.stats.finish());
        active_.erase(active_.begin() + static_cast<std::ptrdiff_t>(i));
    }
    if (piece.segment.shape != SegmentShape::line) return;
    const AxisVector end = piece.segment.origin + scaled(piece.segment.rate, piece.segment.length);
    window_.lines.query(piece.segment.origin, end, window_.margin_mm, [&](std::size_t i) {
        const std::size_t c = window_.base + i;
        const CutRecord& record = window_.records[i];
        if (c < next_take_ || started_.count(c) != 0 || record.local_error || !on_cut(piece, record.info)) return;
        started_.insert(c);
        active_.push_back({c, SpeedStats(record.info, options_.profile_points)});
        sample_piece(piece, record.info, options_, active_.back().stats);
    });
}

void CutMeter::finish() {
    for (Active& active : active_) finished_.emplace(active.cut, active.stats.finish());
    active_.clear();
    ended_ = true;
}

CutSpeed CutMeter::take(std::size_t cut) {
    next_take_ = cut + 1;
    started_.erase(cut);
    auto it = finished_.find(cut);
    // Never on the trajectory: what measure_cut_speed gives for a cut it does not find.
    if (it == finished_.end()) return SpeedStats(window_.at(cut).info, options_.profile_points).finish();
    CutSpeed out = std::move(it->second);
    finished_.erase(it);
    return out;
}

}  // namespace notch_detail
}  // namespace nckit
