// Pass 2a of the notch job: a run-up or overrun must keep clear of every other move's path.
// The moves stream by once; the run-ups and overruns (two short segments per cut) sit in a
// SweepIndex, so each move is tested against the few that lie near it.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "notch_geometry.hpp"
#include "notch_passes.hpp"

namespace nckit::notch_detail {

namespace {

std::string block_name(const Crossing& crossing) {
    if (crossing.sequence_number >= 0) return fmt::format("N{} (line {})", crossing.sequence_number, crossing.line);
    return fmt::format("line {}", crossing.line);
}

AxisVector rate_of(const AxisVector& from, const AxisVector& to) {
    return scaled(to - from, 1.0 / measured_length(from, to));
}

struct Span {
    AxisVector from;
    AxisVector to;
};

Span span_of(const CutRecord& cut, bool run_up) {
    return run_up ? Span{cut.run_up_point, cut.info.start} : Span{cut.info.end, cut.overrun_point};
}

}  // namespace

ClearanceCheck::ClearanceCheck(CutRecords& cuts, std::size_t count, const NotchOptions& options)
    : cuts_(cuts), options_(options) {
    std::vector<SweepIndex::Segment> segments;
    for (std::size_t c = 0; c < count; ++c) {
        if (cuts_[c].local_error) continue;  // refused already: its crossings are not looked for
        for (bool run_up : {true, false}) {
            const Span span = span_of(cuts_[c], run_up);
            pieces_.push_back({c, run_up});
            segments.push_back({span.from, span.to});
        }
    }
    index_ = SweepIndex(segments);
}

void ClearanceCheck::add(const Move& move) {
    const std::uint64_t k = index_k_++;
    if (pieces_.empty()) return;
    const std::vector<AxisVector> polyline = path_polyline(move, options_.clearance_mm);
    if (polyline.empty()) return;
    // A piece near several chords of an arc is checked once, against every chord.
    std::vector<std::size_t> near;
    for (std::size_t c = 0; c + 1 < polyline.size(); ++c) {
        index_.query(polyline[c], polyline[c + 1], options_.clearance_mm, [&](std::size_t i) { near.push_back(i); });
    }
    std::sort(near.begin(), near.end());
    near.erase(std::unique(near.begin(), near.end()), near.end());
    for (std::size_t i : near) check(k, move, pieces_[i], polyline);
}

void ClearanceCheck::check(std::uint64_t k, const Move& move, const Piece& piece,
                           const std::vector<AxisVector>& polyline) {
    CutRecord& cut = cuts_[piece.cut];
    std::optional<Crossing>& crossing = piece.run_up ? cut.run_up_crossing : cut.overrun_crossing;
    if (crossing || k == cut.line) return;  // the first crossing (in program order) is the one reported
    const Span span = span_of(cut, piece.run_up);
    const std::optional<std::uint64_t> adjacent = piece.run_up ? cut.approach : cut.next;
    if (adjacent && k == *adjacent) {
        // The adjacent move shares a point with the segment: a straight one crosses only when it
        // runs along the same line over part of the segment.
        if (piece.run_up && cut.info.approach_shortened) return;
        const auto* line = std::get_if<Line>(&move.what);
        if (line == nullptr) return;  // an arc meeting the segment at its end: not checked
        const double length = measured_length(line->from, line->to);
        if (!(length > 0)) return;
        const AxisVector dir = rate_of(span.from, span.to);
        const AxisVector w = rate_of(line->from, line->to);
        const double cosine = dot(w, dir) / std::sqrt(dot(w, w) * dot(dir, dir));
        if (std::abs(cosine) < 1.0 - 1e-12) return;  // two lines meet once: at the shared point
        const double s0 = dot(line->from - span.from, dir);
        const double s1 = dot(line->to - span.from, dir);
        const double seg = measured_length(span.from, span.to);
        const double overlap = std::min(std::max(s0, s1), seg) - std::max(std::min(s0, s1), 0.0);
        if (overlap > options_.clearance_mm) crossing = Crossing{move.sequence_number, move.where.line};
        return;
    }
    for (std::size_t c = 0; c + 1 < polyline.size(); ++c) {
        if (segment_distance(span.from, span.to, polyline[c], polyline[c + 1]) < options_.clearance_mm) {
            crossing = Crossing{move.sequence_number, move.where.line};
            return;
        }
    }
}

Diagnostics cut_errors(const CutRecords& cuts, std::size_t count) {
    Diagnostics errors;
    for (std::size_t c = 0; c < count; ++c) {
        const CutRecord& cut = cuts[c];
        if (cut.local_error) {
            errors.push_back(*cut.local_error);
            continue;
        }
        for (bool run_up : {true, false}) {
            const std::optional<Crossing>& crossing = run_up ? cut.run_up_crossing : cut.overrun_crossing;
            if (!crossing) continue;
            const Span span = span_of(cut, run_up);
            errors.push_back(error_at(
                cut.info.where, "notch-crossing",
                fmt::format("the {} of {:.4f} mm for this notch crosses the path of {}", run_up ? "run-up" : "overrun",
                            measured_length(span.from, span.to), block_name(*crossing))));
            break;
        }
    }
    return errors;
}

}  // namespace nckit::notch_detail
