#pragma once
// The look-ahead window: segments whose junction speeds may still change, the backward and
// forward passes over them, and the commit of pieces whose timing is final.
#include <cstddef>
#include <cstdint>
#include <algorithm>
#include <utility>
#include <vector>

#include "bell_search.hpp"
#include "cruise_raise.hpp"
#include "ring_queue.hpp"
#include "run_merge.hpp"
#include "nckit/plan/spindle_model.hpp"
#include "nckit/plan/trajectory.hpp"

namespace nckit::plan_detail {

//! A dwell or I/O event that follows a segment (or the start, at rest).
struct WindowEvent {
    PieceKind kind = PieceKind::io;
    Io io;
    double dwell_s = 0;          //!< s, dwell only
    bool wait_index = false;     //!< dwell until the spindle's next index pulse (G32/G33), not dwell_s
    double index_angle_deg = 0;  //!< wait_index: until this angle past the pulse (a thread's start)
    SourceLocation where;
    std::int64_t sequence_number = -1;
};

struct WindowSegment {
    PathSegment path;
    ProfileLimits limits;
    double junction_max = 0;  //!< mm/s, the highest speed allowed at its end; 0 = stop
    SourceLocation where;
    std::int64_t sequence_number = -1;
    bool blend = false;
    bool continues_move = false;     //!< TrajectoryPiece::continues_move
    bool spindle_locked = false;     //!< G32/G33 (SegmentOrigin::spindle_locked)
    std::vector<WindowEvent> after;  //!< events between its end and the next segment
    //! A curved piece's axes, so a run of such pieces may go faster where its profile holds the
    //! speed (cruise_raise.hpp); cruise_velocity 0 when unknown.
    PieceCheck check;
};

//! Consecutive segments joined at speed with limits within run_spread of each other share one
//! profile: a junction inside a run keeps its acceleration, so chains of tiny segments reach
//! the feed (per-segment profiles start and end at a = 0, and a jerk-limited profile gains
//! almost no speed over a few µm). The run plans with limits no higher than any of its
//! segments' (see run_margin in lookahead.cpp).
struct WindowRun {
    std::size_t count = 0;  //!< segments
    double length = 0;      //!< mm
    ProfileLimits limits;
    ProfileLimits first_limits;  //!< its first segment's (times run_margin); limits never drift far below
    double junction_max = 0;     //!< mm/s at its end
    //! mm/s, the lowest cruise_velocity of its segments when every one has a PieceCheck, else 0.
    double cruise_velocity = 0;
    //! Only lines and transitions between lines (no arc, no curved piece): its segments may
    //! share the run with wider acceleration and jerk limits (straight_run_rate_spread).
    bool straight = true;
    double bound = 0;  //!< mm/s, from the backward pass: the end speed it can still stop from
    //! The bound no longer depends on the window's provisional stop at its end (see plan()).
    bool bound_final = false;
    //! mm/s, max_end_speed(length, 0, limits) once computed, < 0 until then; reset whenever
    //! length or limits change.
    mutable double stop_speed = -1;
};

//! Runs merge segments whose speed, acceleration and jerk limits are within this factor.
inline constexpr double run_spread = 1.05;
//! S-curve runs of lines and transitions between lines (no arc, no curved piece) merge segments
//! whose acceleration and jerk limits are within this factor (the speed limits still within
//! run_spread): a run ends with zero path acceleration, and on a CAM chain speeding up from
//! rest the line and transition limits differ by more than run_spread at every vertex, so the
//! acceleration had to return to 0 every few tenths of a millimetre. Measured at j 5,000
//! (BENCHMARKS.md): the 2,000-line circle 3.080 -> 2.917 s, the raster 37.001 -> 36.782 s (1.3
//! gave 2.997 s on the circle; 2 and 3 the same as 1.5). Among arcs and their pieces it cost
//! time (semicircles at j 50,000 27.764 -> 27.883 s), so there the spread stays run_spread.
inline constexpr double straight_run_rate_spread = 1.5;

class Lookahead {
public:
    Lookahead(ProfileKind kind, std::size_t window_moves, const SpindleConfig& spindle = {})
        : kind_(kind), window_(window_moves), spindle_(spindle) {}

    //! Appends a segment (length > 0). Its junction_max is the caller's limit at its end; the
    //! next add() lowers it to the next segment's speed limit.
    void add(WindowSegment segment);
    //! Appends an event after everything added so far, at `position`.
    void add_event(WindowEvent event, const AxisVector& position);
    //! The stream is over: the window end is a real stop, everything is final.
    void finish();

    [[nodiscard]] RingQueue<TrajectoryPiece>& output() { return output_; }

    //! Tests only: every backward pass recomputes every bound, and no stop speed is taken from
    //! the cache, as a reference for the incremental passes (whose results must be identical).
    void set_full_passes(bool full) { full_passes_ = full; }
    //! Tests only: commit a run only when its own junction limit or its speed-up holds its end
    //! speed (or the window overflows), not as soon as a junction limit further on does.
    void set_final_bound_commits(bool on) { final_bound_commits_ = on; }
    //! Tests only: plan every run on its own, with zero acceleration at each boundary.
    void set_merge_runs(bool on) { merge_runs_ = on; }
    //! Segments in the window now (tests: how far planning lags behind the input).
    [[nodiscard]] std::size_t window_segments() const { return segments_.size(); }

private:
    void plan(std::size_t keep_at_most);
    void commit_front(double v_end);
    //! The end speed the forward pass gives run `r` entered at v_start (in v_end), and whether
    //! it is final: no later segment can change it.
    [[nodiscard]] bool end_speed(const WindowRun& r, double v_start, double& v_end) const;
    //! Whether `segment`, a piece of the same transition as the run's last, must start a run of
    //! its own because the run holds transition_run_pieces of them already.
    [[nodiscard]] bool ends_transition_run(const WindowRun& run, const WindowSegment& segment) const;
    //! Whether the end speeds of the runs after the front one (entered at v_front_end) are
    //! final as well, curved_commit_ahead of them.
    [[nodiscard]] bool following_runs_final(double v_front_end) const;
    //! The profile of `r` alone, its segments from index `first` on: planned, then raised where
    //! its pieces allow (cruise_raise.hpp).
    [[nodiscard]] Profile run_profile(const WindowRun& r, std::size_t first, double v_start, double v_end);
    //! S-curve: how many runs from the front to commit as one profile (`profile`, on entry the
    //! front run's own; replaced by a merged one where that is faster, run_merge.hpp).
    [[nodiscard]] std::size_t merge_following(Profile& profile);
    //! Appends the checks of `count` segments from index `first` to merge_spans_; false when
    //! one of them may not lie inside a merged profile.
    [[nodiscard]] bool append_merge_spans(std::size_t first, std::size_t count);
    //! A stretch of runs merge_following looked at: how many, their length, the end speed the
    //! passes gave it, how many of merge_spans_ it holds and the best plan found for it.
    struct BellExtent {
        std::size_t runs = 0;
        double length = 0;           //!< mm
        double v_end = 0;            //!< mm/s
        std::size_t span_count = 0;  //!< of merge_spans_
        double plan_s = 0;           //!< s
    };
    //! Replaces `profile` by a bell (bell_search.hpp) over the taken or the widest extent where
    //! one is faster; the number of runs it covers, 0 when none is faster.
    [[nodiscard]] std::size_t bell_curved_runs(Profile& profile, const BellExtent& taken, const BellExtent& widest,
                                               const MergeRates& rates);
    [[nodiscard]] bool joins_last_run(const WindowSegment& segment) const;
    //! S-curve only: whether the last run can take a segment whose limits are slightly below
    //! its own by lowering its limits to the segment's (`lowered`) without lowering any bound.
    [[nodiscard]] bool lowers_last_run(const WindowSegment& segment, ProfileLimits& lowered) const;
    void emit_event(const WindowEvent& event, const AxisVector& position);
    [[nodiscard]] std::size_t max_run_segments() const;
    //! max_end_speed(run.length, 0, run.limits), cached in the run.
    [[nodiscard]] double stop_speed(const WindowRun& run) const;
    //! Run k (from the front) or a later one changed (length, limits or junction_max) since
    //! the last backward pass.
    void touch(std::size_t k) { dirty_from_ = std::min(dirty_from_, k); }

    ProfileKind kind_;
    std::size_t window_;
    std::vector<CheckedSpan> spans_;        //!< commit_front's, reused
    std::vector<CheckedSpan> merge_spans_;  //!< merge_following's, reused
    RecentBellRates recent_bell_rates_{};   //!< bell_search.hpp
    RingQueue<WindowSegment> segments_;
    RingQueue<WindowRun> runs_;
    RingQueue<TrajectoryPiece> output_;
    double start_speed_ = 0;  //!< mm/s at the start of segments_.front() (final)
    double clock_s_ = 0;      //!< s, end of the last committed piece
    //! The spindle on the committed pieces' clock: I/O events set its speed, index waits read it.
    SpindleModel spindle_;
    SpindleCommand spindle_command_;
    bool finished_ = false;
    std::size_t added_since_plan_ = 0;
    std::size_t left_after_plan_ = 0;
    //! Runs before this index (from the front) kept their length, limits and junction_max since
    //! the last backward pass: a bound there changes only when the next run's bound does.
    std::size_t dirty_from_ = 0;
    bool full_passes_ = false;
    bool final_bound_commits_ = true;
    bool merge_runs_ = true;
};

}  // namespace nckit::plan_detail
