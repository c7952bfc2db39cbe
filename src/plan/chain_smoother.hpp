#pragma once
// CAM polylines under a jerk limit: the written end points of a chain of short G1 lines carry the
// rounding noise of their decimals (4 decimals on 0.06 mm chords turn the chord directions by up
// to 25 % of the true turning). Transitions that follow the written chords turn that noise into
// curvature noise, and the jerk terms q'''·ṡ³ cap the speed. The chain smoother moves each inner
// vertex of a chain of gently turning lines towards a low-pass filtered copy of the chain, by at
// most a share of the G64 P tolerance, before the planner sees the lines; the transitions then
// follow the smooth curve the points sample (docs/planner.md, "CAM polylines").
#include <array>
#include <cstddef>
#include <vector>

#include "nckit/interp/move.hpp"
#include "ring_queue.hpp"

namespace nckit::plan_detail {

//! Half-width n of the binomial kernel C(2n, k)/4^n (standard deviation sqrt(n/2) vertices); the
//! filter is applied twice ("twicing": S + K·(P − S)), so a vertex depends on 2n neighbours each
//! side. Chosen by measurement on the 2,000-chord circle at j 5,000 (BENCHMARKS.md): n = 8 gave
//! 4.476 s, n = 16 3.080 s (one G2: 2.807 s); the filter costs 4n + 2 multiply-adds per axis and line.
inline constexpr int chain_half_width = 16;
//! A vertex turning more than this is a corner of the part, not a sample of a curve: the chain
//! ends there and the vertex stays where it was written.
inline constexpr double chain_max_turn_rad = 0.25;
//! Share of the path tolerance a vertex may move; the transitions get the rest.
inline constexpr double chain_budget_share = 0.2;
//! Consecutive smoothed lines are merged into one while the vertices they pass lie within this
//! share of the tolerance from its chord (at most chain_max_merged lines): longer chords make
//! the transitions' curvature follow the curve over a longer stretch, and there are fewer.
inline constexpr double chain_merge_share = 0.2;
inline constexpr long chain_max_merged = 16;
//! Only lines shorter than this many tolerances are merged: where the written decimals are a
//! large part of a line's length (longer lines of a smooth surface keep their own vertices).
inline constexpr double chain_merge_max_line_tolerances = 10;
//! Lines longer than this many tolerances are not samples of a curve (a part's own edges).
inline constexpr double chain_max_line_tolerances = 100;

class ChainSmoother {
public:
    ChainSmoother();

    //! Takes the next move when it is a G1 line that may belong to a chain (XYZ only, blendable
    //! under `tolerance_mm`): the line is held, and the lines that can no longer change become
    //! available through ready(). A line that does not continue the chain (another tolerance, a corner,
    //! not joined) ends it first. False for any other move: the caller ends the chain (flush) and
    //! plans the move itself.
    bool push(const Move& move, double tolerance_mm);
    //! The chain ends here: every held line becomes available.
    void flush();
    //! The next line, with its end points smoothed, in place (null when none is ready): valid
    //! until drop_ready() or the next push() or flush(). In place saves copying a move per line.
    [[nodiscard]] const Move* ready() { return out_.empty() ? nullptr : &out_.front(); }
    void drop_ready() { out_.pop_front(); }
    [[nodiscard]] bool holding() const { return !held_.empty() || !out_.empty(); }

private:
    using Vec3 = std::array<double, 3>;

    [[nodiscard]] Vec3 original(long j) const;
    [[nodiscard]] Vec3 residual(long j) const;
    //! K at the vertex whose 2n + 1 neighbours start at `first` (stored contiguously), or read by `at(k)`, k in [−n,
    //! n].
    [[nodiscard]] Vec3 convolve(const Vec3* first) const;
    template <class At>
    [[nodiscard]] Vec3 convolve_at(At at) const;
    void start(const Line& line, double tolerance_mm);
    void advance();
    void emit(long vertex, const Vec3& at);
    void release_as_written();
    void release_merged(long next);
    [[nodiscard]] bool is_fixed(long vertex) const;

    std::array<double, 2 * chain_half_width + 1> weights_{};  //!< the kernel K
    // The current chain: vertices 0..n_ (the lines' end points), the first at chain index 0.
    RingQueue<Move> held_;      //!< lines not yet handed out; held_.front() ends at vertex emitted_ + 1
    std::vector<Vec3> points_;  //!< written vertices from points_base_
    long points_base_ = 0;
    std::vector<Vec3> residuals_;  //!< P − K·P from residuals_base_ (filled up to next_residual_)
    long residuals_base_ = 0;
    long n_ = -1;  //!< index of the last vertex; -1: no chain
    bool ended_ = false;
    long next_residual_ = 0;
    long next_vertex_ = 0;  //!< next smoothed vertex to compute
    Vec3 last_smoothed_{};
    Vec3 last_direction_{};
    AxisVector last_to_;  //!< where the chain's last line ends, every axis
    double tolerance_mm_ = 0;
    RingQueue<Move> out_;
    // The merged line being grown: from the anchor (vertex anchor_index_) over merged_count_ lines.
    Move merged_;
    long anchor_index_ = 0;
    Vec3 anchor_{};
    long merged_count_ = 0;
    std::vector<Vec3> passed_;  //!< smoothed vertices inside it
};

}  // namespace nckit::plan_detail
