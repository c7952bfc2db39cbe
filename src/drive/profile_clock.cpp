#include "profile_clock.hpp"

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
    end_p_ = phase + 1 == profile_.phase_count
                 ? profile_.distance
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
    double lo = 0;
    double hi = duration_;
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
    x = std::clamp(x, lo, hi);
    for (int iteration = 0; iteration < 100; ++iteration) {
        const double f = p_ + x * (v_ + x * (half_a_ + x * sixth_j_)) - p;
        if (f < 0) {
            lo = x;
        } else if (f > 0) {
            hi = x;
        } else {
            break;
        }
        const double slope = v_ + x * (a_ + 0.5 * x * j_);
        double next = slope > 0 ? x - f / slope : lo + 0.5 * (hi - lo);
        if (!(next >= lo && next <= hi)) next = lo + 0.5 * (hi - lo);
        const double step = std::abs(next - x);
        x = next;
        // A Newton step this small leaves an error of the order of its square: done.
        if (step < 1e-10 || hi - lo < 1e-12) break;
    }
    last_gap_ = x - guess_;
    guess_ = x;
    have_root_ = true;
    last_p_ = p;
    return x;
}

}  // namespace nckit::drive_detail
