#include "profile_inverse.hpp"

#include <algorithm>
#include <cmath>

#include "nckit/core/bracketed_newton.hpp"

namespace nckit::plan_detail {

double ProfileWalker::time_at(double position_mm) {
    if (!started_) {
        v_ = profile_.start_velocity;
        started_ = true;
    }
    const double target = position_mm - profile_.start_position;
    if (!(target > 0)) return 0.0;
    if (target >= profile_.distance) return profile_.duration_s();
    while (phase_ < profile_.phase_count) {
        const ProfilePhase& ph = profile_.phases[static_cast<std::size_t>(phase_)];
        const double tau = ph.duration_s;
        const double a = ph.acceleration;
        const double j = ph.jerk;
        auto pos = [&](double x) { return p_ + x * (v_ + x * (0.5 * a + x * j / 6.0)); };
        const double end_p = pos(tau);
        if (target < end_p || phase_ + 1 == profile_.phase_count) {
            // Bracketed Newton on pos(x) = target over [0, tau], to a bracket of 1e-16 of the
            // profile time (the resolution of a double there).
            const double x0 =
                v_ + 0.5 * a * tau > 0 ? std::clamp((target - p_) / std::max(v_, 1e-300), 0.0, tau) : 0.5 * tau;
            const auto residual = [&](double x) { return ValueSlope{pos(x) - target, v_ + x * (a + 0.5 * x * j)}; };
            const double x =
                bracketed_newton(residual, 0.0, tau, x0,
                                 NewtonStop{.bracket_tolerance = 1e-16 * (phase_start_s_ + tau), .max_iterations = 100})
                    .x;
            return phase_start_s_ + x;
        }
        p_ = end_p;
        v_ += tau * (a + 0.5 * tau * j);
        phase_start_s_ += tau;
        ++phase_;
    }
    return profile_.duration_s();
}

}  // namespace nckit::plan_detail
