#include "nckit/drive/servo_follow.hpp"

#include <algorithm>
#include <cmath>

namespace nckit::drive {

ServoParameters servo_parameters(const AxisServoConfig& config) {
    return ServoParameters::from_natural_frequency(config.gain, config.natural_frequency_hz, config.damping);
}

ServoFollower::ServoFollower(const MachineConfig& machine) : period_s_(machine.servo_period_s) {
    for (const AxisConfig& axis : machine.axes) {
        if (!axis.servo) continue;
        AxisLoop loop;
        loop.axis = axis.axis;
        loop.parameters = servo_parameters(*axis.servo);
        axes_.push_back(std::move(loop));
    }
}

void ServoFollower::take(const TrajectorySample& sample, double t_s, const Sink& sink) {
    for (AxisLoop& loop : axes_) {
        const double setpoint = sample.position[loop.axis];
        if (!loop.model) {
            // Settled at the first setpoint: a machine at rest before the program starts.
            const double settled = loop.parameters.gain * setpoint;
            loop.model.emplace(loop.parameters, period_s_, ServoState{settled, 0.0});
            loop.model->reset(ServoState{settled, 0.0}, setpoint);
        }
        const double actual = loop.model->state().position;
        const double error = setpoint - actual;
        if (std::abs(error) > loop.max_abs) {
            loop.max_abs = std::abs(error);
            loop.t_max_s = t_s;
        }
        loop.sum_squares += error * error;
        if (sink) sink(ServoSample{t_s, loop.axis, setpoint, actual, error});
        // The setpoint is held until the next sample.
        loop.model->step(setpoint);
    }
}

void ServoFollower::add(const TrajectoryPiece& piece, const Sink& sink) {
    const double end = piece.start_time_s + piece.duration_s;
    // Sample times are n·period, computed from n so that they never drift.
    for (;;) {
        const double t = static_cast<double>(next_index_) * period_s_;
        if (t >= end) break;
        take(sample(piece, t), t, sink);
        ++next_index_;
    }
    last_ = piece;
    end_s_ = std::max(end_s_, end);
    any_ = true;
}

void ServoFollower::finish(const Sink& sink) {
    if (!any_) return;
    for (;;) {
        const double t = static_cast<double>(next_index_) * period_s_;
        // sample() clamps into the last piece: past the end the setpoint is the end position.
        take(sample(last_, t), t, sink);
        ++next_index_;
        if (t >= end_s_) break;
    }
}

ServoFollowReport ServoFollower::report() const {
    ServoFollowReport out;
    out.duration_s = end_s_;
    out.samples = next_index_;
    for (const AxisLoop& loop : axes_) {
        FollowingError axis;
        axis.axis = loop.axis;
        axis.max_following_error_mm = loop.max_abs;
        axis.t_max_s = loop.t_max_s;
        axis.rms_following_error_mm =
            next_index_ > 0 ? std::sqrt(loop.sum_squares / static_cast<double>(next_index_)) : 0.0;
        out.axes.push_back(axis);
    }
    return out;
}

ServoFollowReport follow_trajectory(const Trajectory& trajectory, const MachineConfig& machine,
                                    const ServoFollower::Sink& sink) {
    ServoFollower follower(machine);
    for (const TrajectoryPiece& piece : trajectory.pieces) follower.add(piece, sink);
    follower.finish(sink);
    return follower.report();
}

}  // namespace nckit::drive
