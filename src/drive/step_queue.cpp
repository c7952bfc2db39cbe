#include "nckit/drive/step_queue.hpp"

#include <stdexcept>

namespace nckit {

StepQueue::StepQueue(std::size_t machine_axes, std::int64_t max_error_ns, std::size_t max_pending_steps)
    : axes_(machine_axes), max_error_ns_(max_error_ns), max_pending_steps_(max_pending_steps) {
    if (max_error_ns < 0 || max_pending_steps == 0) throw std::invalid_argument("StepQueue: bad parameters");
}

void StepQueue::add(const StepEvent& step, std::vector<StepQueueCommand>& out) {
    if (step.axis >= axes_.size()) throw std::out_of_range("StepQueue: step of an unknown axis");
    ++steps_;
    Axis& axis = axes_[step.axis];
    if (step.direction != axis.direction || axis.pending_ns.size() >= max_pending_steps_) {
        flush(step.axis, out);
        if (step.direction != axis.direction) {
            out.push_back(StepQueueCommand{.kind = StepQueueCommand::Kind::set_direction,
                                           .axis = step.axis,
                                           .direction = step.direction,
                                           .run = {}});
            axis.direction = step.direction;
        }
    }
    axis.pending_ns.push_back(step.t_ns);
}

void StepQueue::finish(std::vector<StepQueueCommand>& out) {
    for (std::size_t a = 0; a < axes_.size(); ++a) flush(a, out);
}

void StepQueue::flush(std::size_t axis_index, std::vector<StepQueueCommand>& out) {
    Axis& axis = axes_[axis_index];
    if (axis.pending_ns.empty()) return;
    for (const StepRun& run : compress_steps(axis.pending_ns, axis.t_prev_ns, max_error_ns_)) {
        out.push_back(StepQueueCommand{
            .kind = StepQueueCommand::Kind::queue_step, .axis = axis_index, .direction = 0, .run = run});
        ++runs_;
    }
    axis.pending_ns.clear();
}

}  // namespace nckit
