#include "nckit/drive/variable_period_servo.hpp"

#include <cmath>
#include <stdexcept>

#include "servo_step.hpp"

namespace nckit::drive {

VariablePeriodServo::VariablePeriodServo(const ServoParameters& parameters, ServoState initial)
    : parameters_(parameters), state_(initial), deviation_(initial.position) {
    // Validates the parameters now rather than at the first step: a period of 1 s is always legal.
    (void)discretise(parameters, 1.0);
}

const ServoDiscretisation& VariablePeriodServo::discretisation(double period_s) {
    if (!(period_s > 0.0) || !std::isfinite(period_s)) {
        throw std::invalid_argument("servo step needs a finite period > 0");
    }
    if (last_.period_s == period_s) return last_;
    auto found = cache_.find(period_s);
    if (found == cache_.end()) {
        if (cache_.size() >= max_cached_periods) cache_.clear();
        found = cache_.emplace(period_s, discretise(parameters_, period_s)).first;
    }
    last_ = found->second;
    return last_;
}

ServoState VariablePeriodServo::step(double setpoint, double period_s) {
    drive_detail::step_held(discretisation(period_s).transition, parameters_.gain * setpoint, target_, deviation_,
                            state_);
    return state_;
}

void VariablePeriodServo::reset(ServoState state, double setpoint) {
    state_ = state;
    target_ = parameters_.gain * setpoint;
    deviation_ = state.position - target_;
}

}  // namespace nckit::drive
