#include "chain_smoother.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "chord_distance.hpp"

namespace nckit::plan_detail {

namespace {

constexpr long half = chain_half_width;
// Vertices no longer needed are dropped from the stores once there are this many.
constexpr long compact_after = 1024;

double norm3(const std::array<double, 3>& v) {
    return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

}  // namespace

ChainSmoother::ChainSmoother() {
    // C(2n, k) / 4^n, built row by row of Pascal's triangle.
    std::array<double, 2 * chain_half_width + 1> row{};
    row[0] = 1;
    for (std::size_t r = 1; r < row.size(); ++r) {
        for (std::size_t k = r; k > 0; --k) row[k] += row[k - 1];
    }
    double sum = 0;
    for (const double w : row) sum += w;
    for (std::size_t k = 0; k < row.size(); ++k) weights_[k] = row[k] / sum;
}

ChainSmoother::Vec3 ChainSmoother::convolve(const Vec3* first) const {
    Vec3 s{};
    for (std::size_t k = 0; k < weights_.size(); ++k) {
        for (std::size_t i = 0; i < 3; ++i) s[i] += weights_[k] * first[k][i];
    }
    return s;
}

template <class At>
ChainSmoother::Vec3 ChainSmoother::convolve_at(At at) const {
    Vec3 s{};
    for (long k = -half; k <= half; ++k) {
        const Vec3 p = at(k);
        const double w = weights_[static_cast<std::size_t>(k + half)];
        for (std::size_t i = 0; i < 3; ++i) s[i] += w * p[i];
    }
    return s;
}

// The chain is extended beyond its fixed ends by odd reflection, P(−j) = 2·P(0) − P(j) and
// P(n + j) = 2·P(n) − P(n − j): the filter then keeps both ends in place and a straight or
// evenly curving chain runs on into them without a bend.
ChainSmoother::Vec3 ChainSmoother::original(long j) const {
    Vec3 offset{};
    double sign = 1;
    const Vec3& first = points_.front();  // vertex 0 is kept while any reflection can reach it
    // Each reflection brings j at least one chain length closer to [0, n_]: bounded by the kernel.
    for (long guard = 0; guard < 4 * half + 4 && (j < 0 || (ended_ && j > n_)); ++guard) {
        const bool low = j < 0;
        const Vec3& about = low ? first : points_.back();
        for (std::size_t i = 0; i < 3; ++i) offset[i] += sign * 2 * about[i];
        sign = -sign;
        j = low ? -j : 2 * n_ - j;
    }
    const Vec3& p = points_[static_cast<std::size_t>(j - points_base_)];
    return {offset[0] + sign * p[0], offset[1] + sign * p[1], offset[2] + sign * p[2]};
}

// The residual P − K·P of an odd-reflected chain is odd about both ends (and 0 there).
ChainSmoother::Vec3 ChainSmoother::residual(long j) const {
    double sign = 1;
    for (long guard = 0; guard < 4 * half + 4 && (j < 0 || (ended_ && j > n_)); ++guard) {
        sign = -sign;
        j = j < 0 ? -j : 2 * n_ - j;
    }
    const Vec3& r = residuals_[static_cast<std::size_t>(j - residuals_base_)];
    return {sign * r[0], sign * r[1], sign * r[2]};
}

void ChainSmoother::start(const Line& line, double tolerance_mm) {
    points_.clear();
    residuals_.clear();
    points_base_ = 0;
    residuals_base_ = 0;
    points_.push_back({line.from[0], line.from[1], line.from[2]});
    n_ = 0;
    ended_ = false;
    next_residual_ = 0;
    next_vertex_ = 0;
    tolerance_mm_ = tolerance_mm;
}

bool ChainSmoother::push(const Move& move, double tolerance_mm) {
    const auto* line = std::get_if<Line>(&move.what);
    if (line == nullptr || line->rapid || line->path.exact_stop || !(tolerance_mm > 0)) return false;
    for (std::size_t i = 3; i < axis_count; ++i) {
        if (line->from[i] != line->to[i]) return false;
    }
    const Vec3 d{line->to[0] - line->from[0], line->to[1] - line->from[1], line->to[2] - line->from[2]};
    const double length = norm3(d);
    if (!(length > 1e-9) || length > chain_max_line_tolerances * tolerance_mm) return false;
    const Vec3 direction{d[0] / length, d[1] / length, d[2] / length};
    bool continues = n_ >= 0 && !ended_ && tolerance_mm == tolerance_mm_;
    if (continues) {
        for (std::size_t i = 0; i < axis_count; ++i) continues = continues && line->from[i] == last_to_[i];
    }
    if (continues) {
        const double cos_turn =
            direction[0] * last_direction_[0] + direction[1] * last_direction_[1] + direction[2] * last_direction_[2];
        continues = cos_turn >= std::cos(chain_max_turn_rad);
    }
    if (!continues) {
        flush();
        start(*line, tolerance_mm);
    }
    held_.push_back(move);
    points_.push_back({line->to[0], line->to[1], line->to[2]});
    ++n_;
    last_to_ = line->to;
    last_direction_ = direction;
    advance();
    return true;
}

void ChainSmoother::flush() {
    if (n_ < 0 || ended_) return;
    ended_ = true;
    advance();
}

// Twicing: T = S + K·(P − S) with S = K·P. Where K passes a curve almost unchanged (its
// response 1 − ε at low frequencies), twicing passes it as 1 − ε²: a circle keeps its radius
// (K alone pulls every vertex in by about n·h²/(4r)), while the noise of the decimals, at the
// highest frequencies of the chain, is removed as by K.
void ChainSmoother::advance() {
    // A chain of at most three lines is handed out as written: its residuals' reflections over so
    // short a chain, and the vertex loop, would cost most of the time of a program of corners.
    if (ended_ && n_ <= 3 && next_vertex_ == 0) {
        release_as_written();
        return;
    }
    while (next_residual_ <= n_ && (ended_ || next_residual_ + half <= n_)) {
        const long j = next_residual_;
        // Inside the chain the taps read the stored vertices directly; near its ends through
        // the reflections.
        const Vec3 s = j - half >= points_base_ && j + half <= n_
                           ? convolve(&points_[static_cast<std::size_t>(j - half - points_base_)])
                           : convolve_at([&](long k) { return original(j + k); });
        const Vec3 p = original(j);
        residuals_.push_back({p[0] - s[0], p[1] - s[1], p[2] - s[2]});
        ++next_residual_;
    }
    const double budget = chain_budget_share * tolerance_mm_;
    while (next_vertex_ <= n_ && (ended_ || next_vertex_ + half < next_residual_)) {
        const long v = next_vertex_;
        const Vec3 p = original(v);
        Vec3 t = p;
        // The first and last two vertices stay: the lines at the chain's ends are as written,
        // so the joins with the moves before and after keep the whole tolerance.
        const bool fixed = v <= 1 || (ended_ && v >= n_ - 1);
        if (!fixed) {
            const Vec3 r = residual(v);
            const Vec3 kr = v - half >= residuals_base_ && v + half < next_residual_
                                ? convolve(&residuals_[static_cast<std::size_t>(v - half - residuals_base_)])
                                : convolve_at([&](long k) { return residual(v + k); });
            const Vec3 moved{kr[0] - r[0], kr[1] - r[1], kr[2] - r[2]};
            const double shift = norm3(moved);
            const double scale = shift > budget ? budget / shift : 1.0;
            for (std::size_t i = 0; i < 3; ++i) t[i] = p[i] + scale * moved[i];
        }
        if (v > 0) {
            emit(v, t);
        } else {
            last_smoothed_ = t;
        }
        ++next_vertex_;
    }
    // Keep what the next residual (P from next_residual_ − n) and vertex (R from next_vertex_ − n)
    // still need; reflections reach back only while those are near vertex 0.
    // Dropped in blocks, so the stores stay contiguous and each vertex is moved about once.
    const long points_unused = std::min(next_residual_ - half, next_vertex_) - 1 - points_base_;
    if (points_unused > compact_after && points_unused < static_cast<long>(points_.size())) {
        points_.erase(points_.begin(), points_.begin() + points_unused);
        points_base_ += points_unused;
    }
    const long residuals_unused = next_vertex_ - half - 1 - residuals_base_;
    if (residuals_unused > compact_after && residuals_unused < static_cast<long>(residuals_.size())) {
        residuals_.erase(residuals_.begin(), residuals_.begin() + residuals_unused);
        residuals_base_ += residuals_unused;
    }
    if (ended_ && next_vertex_ > n_) n_ = -1;
}

// A chain of at most three lines has only fixed vertices (the first and last two), and no line
// of it is merged with another (a merge needs an inner vertex that is not fixed): each line
// leaves as it came, with the tolerance of an exact join (release_merged). A program of corners
// (every line a chain of its own) passes here with every line.
void ChainSmoother::release_as_written() {
    while (!held_.empty()) {
        std::get<Line>(held_.front().what).path.tolerance_mm = tolerance_mm_;
        out_.push_back(std::move(held_.front()));
        held_.pop_front();
    }
    next_vertex_ = n_ + 1;
    n_ = -1;
}

bool ChainSmoother::is_fixed(long v) const {
    return v <= 1 || (ended_ && v >= n_ - 1);
}

// Vertex v, smoothed to `at`, ends the line held_.front(). The line being grown (from the
// anchor) takes it in while every vertex it passes lies within the merge share of the tolerance
// from its chord: the chord is then within that share of the smoothed lines (a point of the
// chord and the place where the smoothed lines cross its normal plane lie that close).
void ChainSmoother::emit(long v, const Vec3& at) {
    Move move = std::move(held_.front());
    held_.pop_front();
    const Line& line = std::get<Line>(move.what);
    if (v > 1) {
        const Line& growing = std::get<Line>(merged_.what);
        const long end = v - 1;
        const double length = std::sqrt((line.to[0] - line.from[0]) * (line.to[0] - line.from[0]) +
                                        (line.to[1] - line.from[1]) * (line.to[1] - line.from[1]) +
                                        (line.to[2] - line.from[2]) * (line.to[2] - line.from[2]));
        bool extends = !is_fixed(end) && merged_count_ < chain_max_merged &&
                       length < chain_merge_max_line_tolerances * tolerance_mm_ &&
                       line.feed.mode == growing.feed.mode && line.feed.mm_per_min == growing.feed.mm_per_min &&
                       line.feed.mm_per_rev == growing.feed.mm_per_rev;
        if (extends) {
            passed_.push_back(last_smoothed_);
            const double limit = chain_merge_share * tolerance_mm_;
            for (const Vec3& p : passed_) extends = extends && distance2_to_chord(p, anchor_, at) <= limit * limit;
            if (!extends) passed_.pop_back();
        }
        if (extends) {
            ++merged_count_;
            std::get<Line>(merged_.what).to = line.to;
            for (std::size_t i = 0; i < 3; ++i) std::get<Line>(merged_.what).to[i] = at[i];
            last_smoothed_ = at;
            if (ended_ && v == n_) release_merged(v + 1);
            return;
        }
        release_merged(v);
    }
    anchor_index_ = v - 1;
    anchor_ = last_smoothed_;
    merged_ = std::move(move);
    merged_count_ = 1;
    passed_.clear();
    Line& first = std::get<Line>(merged_.what);
    for (std::size_t i = 0; i < 3; ++i) {
        first.from[i] = anchor_[i];
        first.to[i] = at[i];
    }
    last_smoothed_ = at;
    if (ended_ && v == n_) release_merged(v + 1);
}

// The grown line, from the anchor to vertex next − 1. Its tolerance governs the join at its end,
// whose transition runs from the anchor to the line after: where any of these lines is not as
// written (a vertex moved, lines merged), the programmed path lies up to the smoothing and
// merging shares away from the lines the transition is measured against.
void ChainSmoother::release_merged(long next) {
    Line& line = std::get<Line>(merged_.what);
    const bool exact = is_fixed(anchor_index_) && is_fixed(next - 1) && is_fixed(next);
    line.path.tolerance_mm = exact ? tolerance_mm_ : (1 - chain_budget_share - chain_merge_share) * tolerance_mm_;
    out_.push_back(std::move(merged_));
}

}  // namespace nckit::plan_detail
