#pragma once
// Private to the drive stage: the one held-setpoint step ServoModel and VariablePeriodServo
// share, so a fixed period gives them identical bits.
#include <array>

#include "nckit/drive/servo_model.hpp"

namespace nckit::drive_detail {

//! Holds gain × setpoint = `target` for one period with transition `phi`. The state is kept as
//! the deviation from the held target, re-referenced only when the target moves: between
//! changes the deviation keeps its own exponent and decays to 0, where an absolute position would
//! stall once v·h fell below half an ulp.
inline void step_held(const std::array<std::array<double, 2>, 2>& phi, double target, double& held_target,
                      double& deviation, drive::ServoState& state) {
    const double e = deviation + (held_target - target);
    const double v = state.velocity;
    deviation = phi[0][0] * e + phi[0][1] * v;
    held_target = target;
    state.position = target + deviation;
    state.velocity = phi[1][0] * e + phi[1][1] * v;
}

}  // namespace nckit::drive_detail
