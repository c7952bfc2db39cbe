#include "nckit/drive/interval_timer.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace nckit::drive {

TimerSetting IntervalTimer::setting_for(double wanted_hz) const {
    TimerSetting setting;
    setting.wanted_hz = wanted_hz;
    setting.min_rate_hz = min_rate_hz();
    setting.max_rate_hz = max_rate_hz();
    if (!std::isfinite(wanted_hz) || wanted_hz <= 0) {
        setting.status = TimerStatus::invalid_rate;
        return setting;
    }
    // Compared as divisors (clock / rate) so the range ends are exact, not re-rounded rates.
    const double exact_divisor = clock_hz / wanted_hz;
    if (exact_divisor < min_divisor) {
        setting.status = TimerStatus::too_fast;
        return setting;
    }
    if (exact_divisor > max_divisor) {
        setting.status = TimerStatus::too_slow;
        return setting;
    }
    // Of the two neighbouring divisors, the one with the nearer *rate*: the rates meet at the
    // harmonic mean of the divisors, slightly below their midpoint, so plain round() would
    // pick the farther rate for fractions just under one half.
    const double lower = std::floor(exact_divisor);
    const double upper = std::min(lower + 1.0, static_cast<double>(max_divisor));
    const double rate_lower = clock_hz / lower;
    const double rate_upper = clock_hz / upper;
    const double chosen = (rate_lower - wanted_hz) <= (wanted_hz - rate_upper) ? lower : upper;
    setting.divisor = static_cast<std::uint32_t>(chosen);
    setting.rate_hz = clock_hz / chosen;
    setting.speed_error = setting.rate_hz / wanted_hz - 1.0;
    return setting;
}

std::string TimerSetting::message() const {
    switch (status) {
        case TimerStatus::ok:
            return fmt::format("{} steps/s: divisor {} gives {} steps/s ({:+.6g} %)", wanted_hz, divisor, rate_hz,
                               speed_error * 100.0);
        case TimerStatus::too_fast:
            return fmt::format(
                "{} steps/s is faster than the timer can step: it makes {} to {} "
                "steps/s",
                wanted_hz, min_rate_hz, max_rate_hz);
        case TimerStatus::too_slow:
            return fmt::format(
                "{} steps/s is slower than the timer can step: it makes {} to {} "
                "steps/s (a slower rate needs a prescaler or a slower clock)",
                wanted_hz, min_rate_hz, max_rate_hz);
        case TimerStatus::invalid_rate:
            break;
    }
    return fmt::format("{} steps/s is not a step rate: the timer makes {} to {} steps/s", wanted_hz, min_rate_hz,
                       max_rate_hz);
}

}  // namespace nckit::drive
