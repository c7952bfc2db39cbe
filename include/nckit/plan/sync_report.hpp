#pragma once
// Where each spindle-synchronised run (G32/G33) of a trajectory starts: the planner's index
// waits checked from outside, by replaying the trajectory's spindle commands through a fresh
// SpindleModel. Every start should lie on its start angle past the index (angle ≡ 0 without Q,
// ≡ Q/1000 degrees with it; its negative under M4), pass after pass.
#include <cstdint>
#include <vector>

#include "nckit/plan/spindle_model.hpp"
#include "nckit/plan/trajectory.hpp"

namespace nckit {

struct SyncStart {
    SourceLocation where;          //!< the G32/G33 block
    double t_s = 0;                //!< s, when the axes start
    double wait_s = 0;             //!< s spent waiting for the index pulse
    double spindle_angle_deg = 0;  //!< spindle angle then, continuous
    double start_angle_deg = 0;    //!< the programmed start angle past the index (Q), [0, 360)
    long long encoder_count = 0;   //!< encoder count then
};

class SyncReport {
public:
    explicit SyncReport(const SpindleConfig& spindle) : spindle_(spindle) {}
    //! Pieces in trajectory order.
    void add(const TrajectoryPiece& piece);

    //! The first `max_kept` starts (a long program may thread thousands of times).
    [[nodiscard]] const std::vector<SyncStart>& starts() const { return starts_; }
    [[nodiscard]] std::int64_t count() const { return count_; }
    //! deg: the largest distance of any start from its programmed angle past the index, taken
    //! over whole turns (all starts, not only kept).
    [[nodiscard]] double max_index_error_deg() const { return max_error_deg_; }

    static constexpr std::size_t max_kept = 1000;

private:
    SpindleModel spindle_;
    SpindleCommand command_;
    std::vector<SyncStart> starts_;
    std::int64_t count_ = 0;
    double max_error_deg_ = 0;
    bool after_wait_ = false;
    double wait_s_ = 0;
    double wait_angle_deg_ = 0;
};

}  // namespace nckit
