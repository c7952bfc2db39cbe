#include "profile_clock.hpp"

#include "nckit/core/bracketed_newton.hpp"

namespace nckit::drive_detail {

ProfileClock::ProfileClock(const Profile& profile, PhaseSolver solver) : profile_(profile), solver_(solver) {
    enter(0, 0, 0, profile.start_velocity);
}

void ProfileClock::advance(double p) {
    while (phase_ + 1 < profile_.phase_count && p > end_p_) {
        const double tau = duration_;
        enter(phase_ + 1, start_s_ + tau, end_p_, v_ + tau * (a_ + 0.5 * tau * j_));
    }
}

void ProfileClock::enter(int phase, double start_s, double p, double v) {
    phase_ = phase;
    start_s_ = start_s;
    p_ = p;
    v_ = v;
    guess_ = 0;
    last_gap_ = 0;
    have_root_ = false;
    if (phase >= profile_.phase_count) return;
    const ProfilePhase& ph = profile_.phases[static_cast<std::size_t>(phase)];
    a_ = ph.acceleration;
    j_ = ph.jerk;
    duration_ = ph.duration_s;
    inv_v_ = v > 0 ? 1.0 / v : 0.0;
    half_a_ = 0.5 * a_;
    sixth_j_ = j_ / 6.0;
    end_p_ = phase + 1 == profile_.phase_count ? profile_.distance
                                               : p + duration_ * (v + duration_ * (0.5 * a_ + duration_ * j_ / 6.0));
    if (j_ == 0 && a_ == 0) {
        shape_ = Shape::cruise;
    } else if (j_ == 0 && solver_ == PhaseSolver::closed_form) {
        shape_ = Shape::quadratic;
    } else {
        shape_ = Shape::cubic;
    }
}

// Newton on the monotone cubic, kept inside a shrinking bracket (bisection fallback), from a
// second-order Taylor step off the last root (steps come close together, so the first Newton
// step is usually already below the tolerance).
double ProfileClock::newton(double p) {
    double x = guess_ + last_gap_;
    if (have_root_) {
        const double v = v_ + guess_ * (a_ + 0.5 * guess_ * j_);
        if (v > 0) {
            const double a = a_ + guess_ * j_;
            const double inv_v = 1.0 / v;
            const double d = (p - last_p_) * inv_v;
            x = guess_ + d - 0.5 * a * d * d * inv_v;
        }
    }
    const auto residual = [&](double t) {
        return ValueSlope{p_ + t * (v_ + t * (half_a_ + t * sixth_j_)) - p, v_ + t * (a_ + 0.5 * t * j_)};
    };
    // A Newton step below 1e-10 s leaves an error of the order of its square: done.
    x = bracketed_newton(residual, 0.0, duration_, x,
                         NewtonStop{.step_tolerance = 1e-10, .bracket_tolerance = 1e-12, .max_iterations = 100})
            .x;
    last_gap_ = x - guess_;
    guess_ = x;
    have_root_ = true;
    last_p_ = p;
    return x;
}

}  // namespace nckit::drive_detail
