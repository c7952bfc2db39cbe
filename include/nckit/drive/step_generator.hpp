#pragma once
// Exact step generation: the step/direction events that keep every axis's motor count equal to
// round(position × steps_per_unit) of the Trajectory at every instant, plus backlash take-up.
#include <cstdint>
#include <vector>

#include "nckit/core/machine.hpp"
#include "nckit/plan/trajectory.hpp"

namespace nckit {

//! How step crossings and their times are solved. Both give the same steps; their times agree
//! to the ns except where an exact time lies within a rounding of a half ns.
enum class StepSolver {
    //! Closed forms: arcs by acos on each interval where the axis moves one way (Newton where a
    //! radius-mismatch rate is too large for it), constant-acceleration phases by the quadratic
    //! formula. No step waits for the one before it, so the processor overlaps them.
    fast,
    //! Bracketed Newton on the exact functions, the library's sine and cosine at every iterate:
    //! the definition the fast forms are tested against.
    reference
};

//! One motor step.
struct StepEvent {
    std::int64_t t_ns = 0;      //!< ns from the trajectory start (the exact crossing time, rounded)
    std::uint8_t axis = 0;      //!< index into MachineConfig::axes (the machine file's axis order)
    std::int8_t direction = 0;  //!< +1 or -1
    bool backlash = false;      //!< an extra step taking up backlash after a reversal
};

//! Streaming step generator: add() the planner's pieces in order, finish(), and pop() events in
//! time order (ties: axis order) as soon as no later piece can put an event before them.
//!
//! Exactness: the commanded count of an axis is round(q × steps_per_unit), rounding half up,
//! i.e. the count changes where q × spu crosses k + 0.5. Each piece is walked in its path
//! parameter s (the profile is monotone in time): s is split where the axis's dq/ds changes sign
//! (arcs: solved in closed form), each crossing s is found exactly (lines: closed form; arcs:
//! closed form on each monotone interval, see StepSolver), then mapped to time by inverting the
//! piecewise-cubic profile (closed form in cruise and at constant acceleration; in jerk phases
//! Newton/bisection from a second-order Taylor guess, accepted once a Newton correction is below
//! 0.1 ns, which leaves an error of the order of its square). Times are then rounded to whole
//! ns. The count emitted so far is carried from piece to piece and every interval ends at the
//! count its end position implies, so nothing accumulates: after every piece the count is
//! exactly round(end position × spu).
//!
//! Backlash: on a reversal of an axis, round(backlash × spu) extra steps in the new direction go
//! out first, starting at the time of the first commanded step in that direction, one every
//! 1 / backlash_rate_steps_s; that step and the ones after it are delayed as needed to keep that
//! spacing, until the commanded steps fall behind their own times again. Motor count = commanded
//! count ± backlash steps; commanded positions are unchanged. The first motion of an axis is
//! taken as having its play already taken up.
class StepGenerator {
public:
    explicit StepGenerator(const MachineConfig& machine, StepSolver solver = StepSolver::fast);

    void add(const TrajectoryPiece& piece);
    //! No more pieces: every remaining event becomes available.
    void finish();
    //! The next event in time order, if one is ready.
    bool pop(StepEvent& event) {
        if (ready_head_ == ready_.size() && !refill()) return false;
        event = ready_[ready_head_++];
        return true;
    }

    //! Commanded count of machine axis `axis` (index into machine.axes) after the pieces added.
    [[nodiscard]] std::int64_t commanded_count(std::size_t axis) const { return axes_[axis].count; }
    //! Motor count (commanded count plus the backlash steps issued).
    [[nodiscard]] std::int64_t motor_count(std::size_t axis) const { return axes_[axis].motor_count; }
    //! Count axis `axis` started from, round(first position × spu) (0 before the first piece):
    //! with the events popped so far, the motor count at any event (a phase table's beat).
    [[nodiscard]] std::int64_t start_count(std::size_t axis) const { return axes_[axis].start_count; }

private:
    struct AxisState {
        Axis axis = Axis::X;
        double spu = 1;                   //!< steps per mm (deg)
        std::int64_t backlash_steps = 0;  //!< steps added on each reversal
        std::int64_t backlash_interval_ns = 50000;
        std::int64_t count = 0;  //!< commanded count
        std::int64_t motor_count = 0;
        std::int64_t start_count = 0;    //!< count at the first position
        int last_direction = 0;          //!< of the last commanded step, 0 before any
        std::int64_t motor_last_ns = 0;  //!< time of the last motor step
        bool catching_up = false;        //!< steps delayed behind a backlash take-up
        bool started = false;            //!< count initialised from the first position
        std::vector<StepEvent> queue;    //!< events not yet popped, in time order
        std::size_t head = 0;
    };
    struct Interval;
    template <class Crossing, class Clock>
    void walk(AxisState& axis, std::uint8_t index, const Interval& interval, Crossing&& crossing, Clock&& time_ns);
    void emit(AxisState& axis, std::uint8_t index, std::int64_t t_ns, int direction);
    bool refill();  //!< releases what the horizon allows; false when nothing is ready
    void release();

    StepSolver solver_;
    std::vector<AxisState> axes_;
    std::int64_t horizon_ns_ = 0;  //!< events before this are final
    bool finished_ = false;
    bool dirty_ = false;            //!< pieces added since the last release()
    std::vector<StepEvent> ready_;  //!< merged events ready to pop
    std::size_t ready_head_ = 0;
    std::vector<StepEvent> merged_;  //!< scratch for merging
};

//! All the steps of a whole trajectory.
[[nodiscard]] std::vector<StepEvent> generate_steps(const Trajectory& trajectory, const MachineConfig& machine,
                                                    StepSolver solver = StepSolver::fast);

//! The commanded count for a position: round(position × spu), halves rounded up.
[[nodiscard]] std::int64_t commanded_count(double position, double steps_per_unit);

}  // namespace nckit
