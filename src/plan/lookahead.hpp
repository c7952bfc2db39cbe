#pragma once
// The look-ahead window: segments whose junction speeds may still change, the backward and
// forward passes over them, and the commit of pieces whose timing is final.
#include <cstddef>
#include <cstdint>
#include <deque>
#include <vector>

#include "nckit/plan/trajectory.hpp"

namespace nckit::plan_detail {

//! A dwell or I/O event that follows a segment (or the start, at rest).
struct WindowEvent {
    PieceKind kind = PieceKind::io;
    Io io;
    double dwell_s = 0;  //!< s, dwell only
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
    std::vector<WindowEvent> after;  //!< events between its end and the next segment
};

//! Consecutive segments joined at speed with limits within run_spread of each other share one
//! profile: a junction inside a run keeps its acceleration, so chains of tiny segments reach
//! the feed (per-segment profiles start and end at a = 0, and a jerk-limited profile gains
//! almost no speed over a few µm). The run plans with limits no higher than any of its
//! segments' (see run_margin in lookahead.cpp).
struct WindowRun {
    std::size_t count = 0;    //!< segments
    double length = 0;        //!< mm
    ProfileLimits limits;
    double junction_max = 0;  //!< mm/s at its end
    double bound = 0;         //!< mm/s, from the backward pass: the end speed it can still stop from
};

//! Runs merge segments whose speed, acceleration and jerk limits are within this factor.
inline constexpr double run_spread = 1.05;

class Lookahead {
public:
    Lookahead(ProfileKind kind, std::size_t window_moves) : kind_(kind), window_(window_moves) {}

    //! Appends a segment (length > 0). Its junction_max is the caller's limit at its end; the
    //! next add() lowers it to the next segment's speed limit.
    void add(WindowSegment segment);
    //! Appends an event after everything added so far, at `position`.
    void add_event(WindowEvent event, const AxisVector& position);
    //! The stream is over: the window end is a real stop, everything is final.
    void finish();

    [[nodiscard]] std::deque<TrajectoryPiece>& output() { return output_; }

private:
    void plan(std::size_t keep_at_most);
    void commit_front(double v_end);
    [[nodiscard]] bool joins_last_run(const WindowSegment& segment) const;
    void emit_event(const WindowEvent& event, const AxisVector& position);

    ProfileKind kind_;
    std::size_t window_;
    std::deque<WindowSegment> segments_;
    std::deque<WindowRun> runs_;
    std::deque<TrajectoryPiece> output_;
    double start_speed_ = 0;  //!< mm/s at the start of segments_.front() (final)
    double clock_s_ = 0;      //!< s, end of the last committed piece
    bool finished_ = false;
    std::size_t added_since_plan_ = 0;
    std::size_t left_after_plan_ = 0;
};

}  // namespace nckit::plan_detail
