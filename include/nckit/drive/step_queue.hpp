#pragma once
// The step events of all axes turned into the command stream of step-compressing firmware
// (Klipper's set_next_step_dir and queue_step, in ns): per axis, in time order, the steps of one
// direction compressed into runs (step_compress.hpp), every step within a given error.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "nckit/drive/step_compress.hpp"
#include "nckit/drive/step_generator.hpp"

namespace nckit {

//! One command for the firmware of one axis.
struct StepQueueCommand {
    enum class Kind {
        set_direction,  //!< the axis's next steps go in `direction`
        queue_step      //!< `run` of steps in the current direction
    };
    Kind kind = Kind::queue_step;
    std::size_t axis = 0;  //!< index into MachineConfig::axes
    int direction = 0;     //!< set_direction: +1 or -1
    StepRun run;           //!< queue_step: the run, timed from the axis's previous step
};

//! Collects step events (in time order, as StepGenerator gives them) and hands out the commands
//! as they become final: an axis's runs when its direction changes, when it has gathered
//! `max_pending_steps` steps (memory stays bounded), and at finish().
class StepQueue {
public:
    //! `max_error_ns` >= 0: how far a reproduced step may be from its exact time.
    StepQueue(std::size_t machine_axes, std::int64_t max_error_ns,
              std::size_t max_pending_steps = std::size_t{1} << 20);

    //! Adds one step; the commands it makes final are appended to `out`.
    void add(const StepEvent& step, std::vector<StepQueueCommand>& out);
    //! Compresses every axis's remaining steps into `out`.
    void finish(std::vector<StepQueueCommand>& out);

    [[nodiscard]] std::int64_t steps() const { return steps_; }  //!< steps added
    [[nodiscard]] std::int64_t runs() const { return runs_; }    //!< queue_step commands given
    //! steps / runs: how many steps one command carries on average (0 before any run).
    [[nodiscard]] double compression_ratio() const {
        return runs_ > 0 ? static_cast<double>(steps_) / static_cast<double>(runs_) : 0.0;
    }

private:
    struct Axis {
        int direction = 0;
        std::int64_t t_prev_ns = 0;  // the last reproduced step time
        std::vector<std::int64_t> pending_ns;
    };
    void flush(std::size_t axis, std::vector<StepQueueCommand>& out);

    std::vector<Axis> axes_;
    std::int64_t max_error_ns_;
    std::size_t max_pending_steps_;
    std::int64_t steps_ = 0;
    std::int64_t runs_ = 0;
};

}  // namespace nckit
