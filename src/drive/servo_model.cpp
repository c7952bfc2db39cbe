#include "nckit/drive/servo_model.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "servo_step.hpp"

namespace nckit::drive {

namespace {

//! exp(-a h) * c and exp(-a h) * S, where the free response of e'' + 2 a e' + w^2 e = 0 is
//! e(h) = E (c + a S) e0 + E S v0 with E = exp(-a h); a = zeta w, w_d = w sqrt|1 - zeta^2|;
//! c = cos(w_d h), S = sin(w_d h) / w_d (zeta < 1); c = 1, S = h (zeta = 1);
//! c = cosh(w_d h), S = sinh(w_d h) / w_d (zeta > 1).
struct Decay {
    double c = 0;  //!< exp(-a h) c
    double s = 0;  //!< exp(-a h) S
    // zeta > 1 only: the decay rates of the two real modes and their exp(-rate h).
    double slow = 0, fast = 0, e_slow = 0, e_fast = 0;
};

Decay decay(double omega, double zeta, double h) {
    const double a = zeta * omega;
    if (zeta < 1.0) {
        // sin(w_d h) / w_d keeps full relative precision as w_d -> 0, so zeta just below 1
        // needs no special case; it meets the critical branch continuously.
        const double wd = omega * std::sqrt((1.0 - zeta) * (1.0 + zeta));
        const double e = std::exp(-a * h);
        return {e * std::cos(wd * h), e * std::sin(wd * h) / wd};
    }
    if (zeta == 1.0) {
        const double e = std::exp(-omega * h);
        return {e, e * h};
    }
    // Written with the two real roots so neither exp(-a h) nor cosh overflows, and the slow
    // root a - w_d = w^2 / (a + w_d) without cancellation for large zeta.
    const double wd = omega * std::sqrt((zeta - 1.0) * (zeta + 1.0));
    const double slow = omega * omega / (a + wd);
    const double fast = a + wd;
    const double e_slow = std::exp(-slow * h);
    const double e_fast = std::exp(-fast * h);
    // e_slow - e_fast = -e_slow expm1(-(fast - slow) h): no lost digits when w_d h is small.
    const double difference = -e_slow * std::expm1(-(fast - slow) * h);
    return {0.5 * (e_slow + e_fast), difference / (2.0 * wd), slow, fast, e_slow, e_fast};
}

using Matrix2 = std::array<std::array<double, 2>, 2>;

//! exp(A h) for x = (e, v), e' = v, v' = -w^2 e - 2 zeta w v.
Matrix2 transition_matrix(double omega, double zeta, double h) {
    const double a = zeta * omega;
    const Decay d = decay(omega, zeta, h);
    Matrix2 phi{{{d.c + a * d.s, d.s}, {-omega * omega * d.s, d.c - a * d.s}}};
    // Well past critical damping c - a S cancels (a / w_d -> 1); the modal form
    // (fast e_fast - slow e_slow) / (fast - slow) does not, once the rates are apart.
    if (zeta > 1.0 && d.fast > 2.0 * d.slow) {
        const double spread = d.fast - d.slow;
        phi[0][0] = (d.fast * d.e_slow - d.slow * d.e_fast) / spread;
        phi[1][1] = (d.fast * d.e_fast - d.slow * d.e_slow) / spread;
    }
    return phi;
}

}  // namespace

ServoParameters ServoParameters::from_natural_frequency(double gain, double natural_frequency_hz, double damping) {
    if (!(natural_frequency_hz > 0.0) || !std::isfinite(natural_frequency_hz)) {
        throw std::invalid_argument("servo natural frequency must be positive and finite");
    }
    return {gain, 1.0 / (2.0 * std::numbers::pi * natural_frequency_hz), damping};
}

std::complex<double> frequency_response(const ServoParameters& p, double omega_rad_s) {
    const double wt = omega_rad_s * p.time_constant_s;
    return p.gain / std::complex<double>(1.0 - wt * wt, 2.0 * p.damping * wt);
}

ServoDiscretisation discretise(const ServoParameters& parameters, double period_s) {
    const bool finite = std::isfinite(parameters.gain) && std::isfinite(parameters.damping) &&
                        std::isfinite(parameters.time_constant_s) && std::isfinite(period_s);
    if (!finite || parameters.time_constant_s <= 0.0 || parameters.damping < 0.0 || period_s <= 0.0) {
        throw std::invalid_argument("servo model needs finite gain, time constant > 0, damping >= 0 and period > 0");
    }
    ServoDiscretisation d;
    d.period_s = period_s;
    d.transition = transition_matrix(parameters.natural_frequency_rad_s(), parameters.damping, period_s);
    // With u held, e = y - k u obeys the free equation, so x(h) = Phi x0 + (I - Phi) (k u, 0):
    // Gamma = (I - Phi) (k, 0)^T. step() applies Phi to (e, v) rather than adding Gamma u:
    // I - Phi is ill-conditioned for w h << 1, and in the error form a held setpoint settles
    // at k u exactly.
    d.input_gain = {parameters.gain * (1.0 - d.transition[0][0]), -parameters.gain * d.transition[1][0]};
    return d;
}

ServoModel::ServoModel(const ServoParameters& parameters, double period_s, ServoState initial)
    : parameters_(parameters), period_s_(period_s), state_(initial), deviation_(initial.position) {
    const ServoDiscretisation d = discretise(parameters, period_s);
    phi_ = d.transition;
    gamma_ = d.input_gain;
}

ServoState ServoModel::step(double setpoint) {
    drive_detail::step_held(phi_, parameters_.gain * setpoint, target_, deviation_, state_);
    setpoint_ = setpoint;
    return state_;
}

void ServoModel::reset(ServoState state, double setpoint) {
    state_ = state;
    setpoint_ = setpoint;
    target_ = parameters_.gain * setpoint;
    deviation_ = state.position - target_;
}

}  // namespace nckit::drive
