#include <cmath>
#include <numbers>
#include <stdexcept>

#include "nckit/process/fts/fts_spindle.hpp"
#include "nckit/plan/spindle_model.hpp"

namespace nckit {

SpindleClock::SpindleClock(double rpm, int counts_per_turn, const SpindleRipple& ripple)
    : counts_(counts_per_turn), ripple_(ripple) {
    const bool ripple_ok = ripple.fraction >= 0.0 && ripple.slow_fraction >= 0.0 &&
                           ripple.fraction + ripple.slow_fraction < 1.0 && std::isfinite(ripple.phase_deg) &&
                           std::isfinite(ripple.slow_hz);
    if (!(rpm > 0.0) || !std::isfinite(rpm) || counts_per_turn < 1 || !ripple_ok) {
        throw std::invalid_argument("spindle clock needs rpm > 0, counts >= 1, ripple below 100 %");
    }
    nominal_period_s_ = 60.0 / (rpm * counts_per_turn);
    synchronous_speed_.assign(static_cast<std::size_t>(counts_per_turn), 1.0);
    if (ripple.fraction == 0.0) return;
    // The synchronous ripple is the spindle model's (plan/spindle_model.hpp): each count takes
    // exactly the time the model turns through it, expressed as a mean speed over the count.
    SpindleConfig config;
    config.ripple_fraction = ripple.fraction;
    config.ripple_per_turn = ripple.per_turn;
    config.ripple_phase_deg = ripple.phase_deg;
    SpindleModel spindle(config);
    spindle.set_speed(0.0, rpm);
    for (int count = 0; count < counts_per_turn; ++count) {
        const double period_s = spindle.travel_time_s(angle_deg(count), angle_deg(count + 1));
        synchronous_speed_[static_cast<std::size_t>(count)] = nominal_period_s_ / period_s;
    }
}

double SpindleClock::tick_period_s(int count, double t_s) const {
    double speed = synchronous_speed_[static_cast<std::size_t>(count)];
    if (ripple_.slow_fraction != 0.0) {
        // At the count's start time: the slow component hardly moves within one count.
        speed += ripple_.slow_fraction * std::sin(2.0 * std::numbers::pi * ripple_.slow_hz * t_s);
    }
    return nominal_period_s_ / speed;
}

double SpindleClock::angle_deg(int count) const {
    return 360.0 * count / counts_;
}

}  // namespace nckit
