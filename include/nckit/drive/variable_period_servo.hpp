#pragma once
#include <cstddef>
#include <unordered_map>

#include "nckit/drive/servo_model.hpp"

namespace nckit::drive {

//! The second-order servo model of servo_model.hpp stepped over periods that change from step to
//! step: a servo updated at every encoder count of a spindle whose speed ripples. Each step is
//! the exact zero-order-hold response for its own period, as ServoModel's is for its fixed one
//! (same closed form, same arithmetic: at a fixed period the two agree bit for bit).
class VariablePeriodServo {
public:
    //! Throws std::invalid_argument for the parameters ServoModel rejects.
    explicit VariablePeriodServo(const ServoParameters& parameters, ServoState initial = {});

    //! Holds `setpoint` for `period_s` (> 0, finite; else std::invalid_argument); returns the
    //! state at the end of it.
    ServoState step(double setpoint, double period_s);

    [[nodiscard]] const ServoState& state() const { return state_; }
    [[nodiscard]] const ServoParameters& parameters() const { return parameters_; }
    //! Restarts from `state` as if `setpoint` had been held during the last step.
    void reset(ServoState state, double setpoint = 0.0);
    //! Periods whose Phi and Gamma are kept (a spindle-synchronous ripple repeats its periods
    //! every turn, so a turn's worth of them are computed once).
    [[nodiscard]] std::size_t cached_periods() const { return cache_.size(); }

    //! Distinct periods kept at most; past it the cache starts again (a ripple that never
    //! repeats would otherwise grow it without bound).
    static constexpr std::size_t max_cached_periods = 1u << 16;

private:
    const ServoDiscretisation& discretisation(double period_s);

    ServoParameters parameters_;
    std::unordered_map<double, ServoDiscretisation> cache_;
    ServoDiscretisation last_;  //!< the latest period's (period 0 before the first step): the common hit
    ServoState state_;
    double target_ = 0.0;     //!< gain * the setpoint held in the last step
    double deviation_ = 0.0;  //!< position - target_, kept apart as ServoModel keeps it
};

}  // namespace nckit::drive
