#include "nckit/plan/spindle_model.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "nckit/core/bracketed_newton.hpp"

namespace nckit {

namespace {

constexpr double two_pi = 2.0 * std::numbers::pi;
constexpr double rad_per_deg = std::numbers::pi / 180.0;

//! ∫_0^u du / (1 + r sin u) for any u >= 0 (and by oddness below): whole periods of
//! 2π / sqrt(1 − r²) plus the closed form within one, which is continuous at u = π.
double ripple_integral(double u, double r) {
    if (r == 0.0) return u;
    const double s = std::sqrt(1.0 - r * r);
    const double period = two_pi / s;
    const double turns = std::floor(u / two_pi);
    double rest = u - turns * two_pi;  // [0, 2π)
    auto antiderivative = [&](double v) { return 2.0 / s * std::atan((std::tan(v / 2.0) + r) / s); };
    double within = 0;
    if (rest < std::numbers::pi) {
        within = antiderivative(rest) - antiderivative(0.0);
    } else {
        within = period + antiderivative(rest - two_pi) - antiderivative(0.0);
    }
    return turns * period + within;
}

}  // namespace

SpindleModel::SpindleModel(const SpindleConfig& config) : config_(config) {
    if (!(config.ripple_fraction >= 0 && config.ripple_fraction < 1) || config.ripple_per_turn < 1) {
        throw std::invalid_argument("spindle ripple out of range");
    }
}

void SpindleModel::set_speed(double t_s, double rpm) {
    angle_since_deg_ = angle_deg(t_s);
    since_s_ = t_s;
    rpm_ = rpm;
}

double mean_rpm(double rpm, const SpindleConfig& config) {
    const double r = config.ripple_fraction;
    return std::abs(rpm) * std::sqrt(1.0 - r * r);
}

double SpindleModel::mean_rpm() const {
    return nckit::mean_rpm(rpm_, config_);
}

// In the turning sense ψ (ψ = θ forward, −θ backward) the ripple reads r'·sin(kψ + φ') with
// r' = r, φ' = φ forward and r' = −r, φ' = −φ backward.
double SpindleModel::travel_time_s(double from_deg, double to_deg) const {
    const double omega_rad_s = std::abs(rpm_) * two_pi / 60.0;
    const double k = config_.ripple_per_turn;
    const bool forward = rpm_ > 0;
    const double r = forward ? config_.ripple_fraction : -config_.ripple_fraction;
    const double phase = (forward ? 1.0 : -1.0) * config_.ripple_phase_deg * rad_per_deg;
    const double u0 = k * from_deg * rad_per_deg + phase;
    const double u1 = k * to_deg * rad_per_deg + phase;
    return (ripple_integral(u1, r) - ripple_integral(u0, r)) / (k * omega_rad_s);
}

double SpindleModel::angle_deg(double t_s) const {
    const double dt = t_s - since_s_;
    if (rpm_ == 0.0 || dt <= 0) return angle_since_deg_;
    const double sense = rpm_ > 0 ? 1.0 : -1.0;
    const double start = sense * angle_since_deg_;  // ψ at the speed change
    const double omega_deg_s = std::abs(rpm_) * 6.0;
    const double r = config_.ripple_fraction;
    // ψ − ψ0 lies within ωΔt·(1 ± r): the speed never leaves that band.
    const double low = start + omega_deg_s * dt * (1.0 - r);
    const double high = start + omega_deg_s * dt * (1.0 + r);
    const double guess = start + omega_deg_s * dt;
    const double phase_rad = sense * config_.ripple_phase_deg * rad_per_deg;
    // travel_time_s(start, ψ) − Δt is increasing in ψ with slope 1 / speed.
    const auto residual = [&](double psi) {
        const double u = config_.ripple_per_turn * psi * rad_per_deg + phase_rad;
        const double speed_deg_s = omega_deg_s * (1.0 + sense * r * std::sin(u));
        return ValueSlope{travel_time_s(start, psi) - dt, 1.0 / speed_deg_s};
    };
    const double bracket_deg = 1e-12 * std::max(1.0, std::abs(guess));
    const double psi = bracketed_newton(residual, low, high, guess,
                                        NewtonStop{.bracket_tolerance = bracket_deg, .max_iterations = 100})
                           .x;
    return sense * psi;
}

long long SpindleModel::count_at(double t_s) const {
    return static_cast<long long>(std::floor(angle_deg(t_s) / 360.0 * config_.encoder_counts));
}

std::optional<double> SpindleModel::next_index_s(double t_s, double past_index_deg) const {
    if (rpm_ == 0.0) return std::nullopt;
    const double sense = rpm_ > 0 ? 1.0 : -1.0;
    const double now_deg = angle_deg(t_s);
    // An angle within a nano-degree of the target counts as on it: the moment is now.
    const double psi_now = sense * now_deg;
    const double psi_index = std::ceil((psi_now - past_index_deg) / 360.0 - 1e-12) * 360.0 + past_index_deg;
    const double start = sense * angle_since_deg_;
    return std::max(t_s, since_s_ + travel_time_s(start, psi_index));
}

bool SpindleCommand::apply(const Io& io) {
    const double old_rpm = rpm;
    const int old_direction = direction;
    if (io.kind == IoKind::spindle_speed && !io.constant_surface_speed) {
        rpm = io.value;
    } else if (io.kind == IoKind::mcode) {
        if (io.number == 3 || io.number == 4) {
            direction = io.number == 3 ? 1 : -1;
            if (!io.constant_surface_speed) rpm = io.value;
        } else if (io.number == 5 || io.number == 2 || io.number == 30) {
            direction = 0;
        }
    }
    return rpm != old_rpm || direction != old_direction;
}

double SpindleCommand::signed_rpm(const SpindleConfig& config) const {
    const double limited = config.max_rpm > 0 ? std::min(rpm, config.max_rpm) : rpm;
    return direction * limited;
}

double SpindleCommand::mean_rpm(const SpindleConfig& config) const {
    return nckit::mean_rpm(signed_rpm(config), config);
}

}  // namespace nckit
