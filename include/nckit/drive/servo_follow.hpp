#pragma once
// Following error of servo axes: the trajectory sampled at the machine's servo period is the
// setpoint stream of each servo axis's second-order model (servo_model.hpp); the following
// error is the setpoint minus the model's position at each sample.
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "nckit/core/machine.hpp"
#include "nckit/drive/servo_model.hpp"
#include "nckit/plan/setpoint_sampler.hpp"
#include "nckit/plan/trajectory.hpp"

namespace nckit::drive {

//! The model a configured servo axis stands for.
[[nodiscard]] ServoParameters servo_parameters(const AxisServoConfig& config);

//! One servo axis at one sample time.
struct ServoSample {
    double t_s = 0;  //!< s, n × servo period
    Axis axis = Axis::X;
    double setpoint_mm = 0;         //!< mm (deg): the trajectory's position at t_s
    double actual_mm = 0;           //!< mm (deg): the model's position at t_s
    double following_error_mm = 0;  //!< mm (deg): setpoint_mm − actual_mm
};

//! One servo axis over a whole run.
struct FollowingError {
    Axis axis = Axis::X;
    double max_following_error_mm = 0;  //!< mm (deg), the largest |setpoint − actual|
    double rms_following_error_mm = 0;  //!< mm (deg), root mean square over every sample
    double t_max_s = 0;                 //!< s, the first sample time with the largest error
};

struct ServoFollowReport {
    std::vector<FollowingError> axes;  //!< the servo axes, in the machine file's order
    double duration_s = 0;             //!< s, the trajectory's cycle time
    std::int64_t samples = 0;          //!< sample times, t = 0 to the first at or after the end
};

//! Streams a trajectory through the machine's servo axes (those with [axis.servo]).
//!
//! Sample n is at t_n = n h (h = servo_period_s, computed from n so it never drifts): the
//! setpoint u_n = q(t_n) is compared with the model's position y_n, then held for one period
//! (zero-order hold, as a servo loop holds its command), which gives y_{n+1}. The model starts
//! settled at the first setpoint (y_0 = gain × u_0, at rest). After the last piece the setpoint
//! stays at the end position up to the first sample at or after the cycle time. For gain 1 a
//! ramp of speed v settles at a lag of 2 zeta T v, plus about v h / 2 from the hold.
class ServoFollower {
public:
    using Sink = std::function<void(const ServoSample&)>;

    explicit ServoFollower(const MachineConfig& machine);

    //! Whether the machine has any servo axis; without one there is nothing to follow.
    [[nodiscard]] bool has_servo_axes() const { return !axes_.empty(); }

    //! The samples in this piece, every servo axis each; pieces come in order. `sink`, when
    //! set, receives every sample (a trace).
    void add(const TrajectoryPiece& piece, const Sink& sink = {});
    //! The samples after the last piece, up to the first at or after its end.
    void finish(const Sink& sink = {});

    [[nodiscard]] ServoFollowReport report() const;

private:
    struct AxisLoop {
        Axis axis = Axis::X;
        ServoParameters parameters;
        std::optional<ServoModel> model;  //!< made at the first setpoint, settled there
        double max_abs = 0;
        double t_max_s = 0;
        double sum_squares = 0;
    };
    void take(const TrajectorySample& sample, double t_s, const Sink& sink);

    double period_s_;
    std::vector<AxisLoop> axes_;
    SetpointSampler sampler_;  //!< SamplerEnd::through_first_after_end
};

//! The whole trajectory at once.
[[nodiscard]] ServoFollowReport follow_trajectory(const Trajectory& trajectory, const MachineConfig& machine,
                                                  const ServoFollower::Sink& sink = {});

}  // namespace nckit::drive
