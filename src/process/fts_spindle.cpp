#include <cmath>
#include <numbers>
#include <stdexcept>

#include "nckit/process/fts_spindle.hpp"

namespace nckit {

SpindleClock::SpindleClock(double rpm, int counts_per_turn, const SpindleRipple& ripple)
    : counts_(counts_per_turn), ripple_(ripple) {
    const bool ripple_ok = ripple.fraction >= 0.0 && ripple.slow_fraction >= 0.0 &&
                           ripple.fraction + ripple.slow_fraction < 1.0 &&
                           std::isfinite(ripple.phase_deg) && std::isfinite(ripple.slow_hz);
    if (!(rpm > 0.0) || !std::isfinite(rpm) || counts_per_turn < 1 || !ripple_ok) {
        throw std::invalid_argument("spindle clock needs rpm > 0, counts >= 1, ripple below 100 %");
    }
    nominal_period_s_ = 60.0 / (rpm * counts_per_turn);
    synchronous_speed_.resize(static_cast<std::size_t>(counts_per_turn));
    const double phase = ripple.phase_deg * std::numbers::pi / 180.0;
    for (int count = 0; count < counts_per_turn; ++count) {
        const double middle = 2.0 * std::numbers::pi * (count + 0.5) / counts_per_turn;
        synchronous_speed_[static_cast<std::size_t>(count)] =
            1.0 + ripple.fraction * std::sin(ripple.per_turn * middle + phase);
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

double SpindleClock::angle_deg(int count) const { return 360.0 * count / counts_; }

}  // namespace nckit
