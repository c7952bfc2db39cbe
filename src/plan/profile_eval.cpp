// Evaluating a Profile: piecewise cubic in time, forwards from the start for the first half of
// the duration and backwards from the end for the second, so both ends come out exactly.
// The time into a phase is clamped to the phase: far from t = 0 a double resolves time more
// coarsely than a short jerk phase lasts (1e-10 s at 1e6 s), and the time computed into the
// phase can overshoot it by that much, which a high jerk would turn into a limit overshoot.
#include "nckit/plan/profile.hpp"

#include <algorithm>

namespace nckit {

namespace {

//! mm/s^2 at the end of phase i. Jerk phases of an S-curve end where the next phase (or the
//! profile, at 0) starts: taking that value rather than a + j t keeps the last phase ending at
//! exactly a = 0, so the speed never dips below end_velocity by a rounding.
double end_acceleration(const Profile& profile, int i) {
    const ProfilePhase& phase = profile.phases[static_cast<std::size_t>(i)];
    if (phase.jerk == 0) return phase.acceleration;
    return i + 1 < profile.phase_count ? profile.phases[static_cast<std::size_t>(i + 1)].acceleration : 0.0;
}

}  // namespace

double Profile::duration_s() const {
    double total = 0;
    for (int i = 0; i < phase_count; ++i) total += phases[static_cast<std::size_t>(i)].duration_s;
    return total;
}

ProfileState Profile::at(double t_s) const {
    const double total = duration_s();
    if (!(t_s > 0)) return {start_position, start_velocity, start_acceleration, 0.0};
    if (t_s >= total) return {start_position + distance, end_velocity, 0.0, 0.0};

    if (t_s <= 0.5 * total) {
        double p = 0;
        double v = start_velocity;
        double phase_start_s = 0;
        for (int i = 0; i < phase_count; ++i) {
            const ProfilePhase& phase = phases[static_cast<std::size_t>(i)];
            const double a = phase.acceleration;
            const double j = phase.jerk;
            if (t_s < phase_start_s + phase.duration_s || i + 1 == phase_count) {
                const double s = std::min(t_s - phase_start_s, phase.duration_s);
                return {start_position + p + s * (v + s * (0.5 * a + s * j / 6.0)), v + s * (a + 0.5 * s * j),
                        a + s * j, j};
            }
            const double tau = phase.duration_s;
            p += tau * (v + tau * (0.5 * a + tau * j / 6.0));
            v += tau * (a + 0.5 * tau * j);
            phase_start_s += tau;
        }
    }

    double p = distance;
    double v = end_velocity;
    double phase_end_s = total;
    for (int i = phase_count - 1; i >= 0; --i) {
        const ProfilePhase& phase = phases[static_cast<std::size_t>(i)];
        const double a = end_acceleration(*this, i);
        const double j = phase.jerk;
        if (t_s >= phase_end_s - phase.duration_s || i == 0) {
            const double s = std::min(phase_end_s - t_s, phase.duration_s);
            return {start_position + p - s * (v - s * (0.5 * a - s * j / 6.0)), v - s * (a - 0.5 * s * j), a - s * j,
                    j};
        }
        const double tau = phase.duration_s;
        p -= tau * (v - tau * (0.5 * a - tau * j / 6.0));
        v -= tau * (a - 0.5 * tau * j);
        phase_end_s -= tau;
    }
    return {start_position + distance, end_velocity, 0.0, 0.0};  // no phases: unreachable
}

}  // namespace nckit
