#pragma once
// Setpoints: the trajectory sampled at a fixed period, as a servo loop or a trace reads it.
// Sample n is at t_n = n·period_s, computed from n so that the times never drift, and each
// time is evaluated in the piece that holds it, so pieces may stream past one at a time.
#include <cstdint>
#include <functional>

#include "nckit/plan/trajectory.hpp"

namespace nckit {

//! Which samples follow the last piece.
enum class SamplerEnd {
    //! Those at or before the cycle time (1 ps of rounding allowed): a trace ends with the
    //! cycle, its last row is at the end only when the period divides it.
    within_cycle,
    //! Up to the first at or after the cycle time, the setpoint held at the end position: a
    //! servo loop keeps running until the command has stopped changing.
    through_first_after_end,
};

class SetpointSampler {
public:
    using Sink = std::function<void(const TrajectorySample&)>;

    //! `period_s` > 0.
    SetpointSampler(double period_s, SamplerEnd end_rule);

    //! Gives `sink` the samples whose times fall in this piece (start <= t_n < end); pieces come
    //! in time order.
    void add(const TrajectoryPiece& piece, const Sink& sink);
    //! Gives `sink` the samples after the last piece, as the end rule says (none without a piece).
    void finish(const Sink& sink);

    [[nodiscard]] std::int64_t samples() const { return next_index_; }  //!< samples given so far
    [[nodiscard]] double period_s() const { return period_s_; }
    [[nodiscard]] double end_s() const { return end_s_; }  //!< s, the end of the last piece

private:
    [[nodiscard]] double time_of(std::int64_t index) const { return static_cast<double>(index) * period_s_; }

    double period_s_;
    SamplerEnd end_rule_;
    std::int64_t next_index_ = 0;
    double end_s_ = 0;
    TrajectoryPiece last_;
    bool any_ = false;
};

}  // namespace nckit
