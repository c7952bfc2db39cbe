#pragma once
#include <array>
#include <complex>

namespace nckit::drive {

//! y(s)/u(s) = gain / (T^2 s^2 + 2 zeta T s + 1): the seed's axis model (docs/processes/piston.md).
struct ServoParameters {
    double gain = 1.0;             //!< k, position out per setpoint in (DC gain), dimensionless
    double time_constant_s = 0.0;  //!< T = 1 / omega_n, s
    double damping = 1.0;          //!< zeta, dimensionless, >= 0

    //! T from the natural frequency f_n: T = 1 / (2 pi f_n).
    [[nodiscard]] static ServoParameters from_natural_frequency(double gain, double natural_frequency_hz,
                                                                double damping);
    [[nodiscard]] double natural_frequency_rad_s() const { return 1.0 / time_constant_s; }
};

//! G(j omega) of the continuous model.
[[nodiscard]] std::complex<double> frequency_response(const ServoParameters& parameters, double omega_rad_s);

struct ServoState {
    double position = 0.0;  //!< mm (deg): the model's output y
    double velocity = 0.0;  //!< mm/s (deg/s): dy/dt
};

//! The exact zero-order-hold map over one period h: x(h) = Phi x(0) + Gamma u.
struct ServoDiscretisation {
    double period_s = 0.0;                              //!< h, s
    std::array<std::array<double, 2>, 2> transition{};  //!< Phi = exp(A h), (position, velocity)
    std::array<double, 2> input_gain{};                 //!< Gamma = (I - Phi) (k, 0)^T
};

//! Phi and Gamma for any period, closed form (the same numbers ServoModel uses). Throws
//! std::invalid_argument for the parameters ServoModel rejects.
[[nodiscard]] ServoDiscretisation discretise(const ServoParameters& parameters, double period_s);

//! The model discretised exactly for a setpoint held constant over each servo period (zero-order
//! hold): x[n+1] = Phi x[n] + Gamma u[n] (computed as Phi applied to the deviation from the
//! settled state (k u, 0), which is the same map), with Phi = exp(A h) in closed form for zeta < 1,
//! zeta = 1 and zeta > 1. The sample values equal the continuous response to the held setpoint
//! up to rounding, for any period; there is no integration error to tune away.
class ServoModel {
public:
    //! Throws std::invalid_argument for T <= 0, zeta < 0, period <= 0 or non-finite values:
    //! configs are validated before a model is built, so a bad value here is a program error.
    ServoModel(const ServoParameters& parameters, double period_s, ServoState initial = {});

    //! Holds `setpoint` for one period; returns the state at the end of it.
    ServoState step(double setpoint);

    [[nodiscard]] const ServoState& state() const { return state_; }
    //! Setpoint held during the last step (0 before the first) minus the position now.
    [[nodiscard]] double following_error() const { return setpoint_ - state_.position; }
    [[nodiscard]] double period_s() const { return period_s_; }
    [[nodiscard]] const ServoParameters& parameters() const { return parameters_; }
    //! Phi = exp(A h), state (position, velocity) order, row-major.
    [[nodiscard]] const std::array<std::array<double, 2>, 2>& transition() const { return phi_; }
    //! Gamma = integral_0^h exp(A s) B ds: the state change per unit of held setpoint.
    [[nodiscard]] const std::array<double, 2>& input_gain() const { return gamma_; }
    //! Restarts from `state` as if `setpoint` had been held during the last step.
    void reset(ServoState state, double setpoint = 0.0);

private:
    ServoParameters parameters_;
    double period_s_;
    std::array<std::array<double, 2>, 2> phi_{};
    std::array<double, 2> gamma_{};
    ServoState state_;
    double setpoint_ = 0.0;
    double target_ = 0.0;     //!< gain * setpoint_: where the held setpoint settles
    double deviation_ = 0.0;  //!< position - target_, kept apart so it decays below an ulp
};

}  // namespace nckit::drive
