#include "nckit/drive/servo_follow.hpp"

#include <algorithm>
#include <cmath>

namespace nckit::drive {

ServoParameters servo_parameters(const AxisServoConfig& config) {
    return ServoParameters::from_natural_frequency(config.gain, config.natural_frequency_hz, config.damping);
}

ServoFollower::ServoFollower(const MachineConfig& machine)
    : period_s_(machine.servo_period_s), sampler_(machine.servo_period_s, SamplerEnd::through_first_after_end) {
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
    sampler_.add(piece, [&](const TrajectorySample& s) { take(s, s.t, sink); });
}

void ServoFollower::finish(const Sink& sink) {
    sampler_.finish([&](const TrajectorySample& s) { take(s, s.t, sink); });
}

ServoFollowReport ServoFollower::report() const {
    ServoFollowReport out;
    out.duration_s = sampler_.end_s();
    out.samples = sampler_.samples();
    for (const AxisLoop& loop : axes_) {
        FollowingError axis;
        axis.axis = loop.axis;
        axis.max_following_error_mm = loop.max_abs;
        axis.t_max_s = loop.t_max_s;
        axis.rms_following_error_mm =
            sampler_.samples() > 0 ? std::sqrt(loop.sum_squares / static_cast<double>(sampler_.samples())) : 0.0;
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
