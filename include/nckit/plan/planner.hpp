#pragma once
// The look-ahead motion planner: Moves in, an exact time-parameterised Trajectory out.
#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "nckit/core/diagnostic.hpp"
#include "nckit/core/machine.hpp"
#include "nckit/interp/move.hpp"
#include "nckit/plan/trajectory.hpp"

namespace nckit {

struct PlannerOptions {
    std::optional<ProfileKind> profile;        //!< default: the machine's
    double feed_override = 1.0;                //!< factor on programmed feeds, (0, 2]; not on rapids
    std::size_t window_moves = 10000;          //!< most segments held for look-ahead (>= 2)
    double default_blend_tolerance_mm = 0.05;  //!< mm, G64 without P
    //! Jerk-limited plans stop exactly at a sharp corner between lines whose transition would be
    //! slower to cross than a stop (src/plan/corner_stop.hpp); false always passes through it.
    bool stop_sharp_corners = true;
};

//! Streaming planner. push() the interpreter's moves in order, then finish(); pop() hands out
//! pieces in order as soon as their timing can no longer change. Memory is bounded by the
//! window (plus the pieces not yet popped): when the window is full, its oldest half is
//! committed as planned, which is always safe because the window's end is planned as a stop.
//!
//! Rules (details in src/plan/): per-segment limits keep every axis within its machine limits
//! (segment_limits.hpp); junctions pass at speed only when tangent (junction.hpp), straight
//! corners under G64 are rounded by a blend arc within the tolerance, everything else stops,
//! as do G61/G9, dwells and waiting M-codes; I/O that does not wait becomes a zero-duration
//! piece at its place. G95 feeds follow the spindle model's mean speed (spindle_model.hpp);
//! G32/G33 stop, wait for the index pulse (a dwell piece with waits_for_index) and move the
//! lead per turn at that speed, without override; a G32 chained to the previous one goes on.
class Planner {
public:
    //! Throws std::invalid_argument for options out of range (a programming error).
    Planner(MachineConfig machine, PlannerOptions options = {});
    ~Planner();
    Planner(Planner&&) noexcept;
    Planner& operator=(Planner&&) noexcept;

    //! Adds the next move. After an error (see diagnostics) further moves are ignored.
    void push(const Move& move);
    //! No more moves: the trajectory ends at rest and every remaining piece becomes available.
    void finish();
    //! The next piece, if one is ready.
    bool pop(TrajectoryPiece& piece);
    //! Problems with the moves (no usable feed, an axis the machine lacks); empty when fine.
    [[nodiscard]] const Diagnostics& diagnostics() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

//! Plans a whole move list; the diagnostics when the planner reported any.
struct PlanResult {
    Trajectory trajectory;
    Diagnostics diagnostics;
};
[[nodiscard]] PlanResult plan_moves(const std::vector<Move>& moves, const MachineConfig& machine,
                                    const PlannerOptions& options = {});

}  // namespace nckit
