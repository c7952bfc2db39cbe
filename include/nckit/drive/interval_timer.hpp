#pragma once
#include <cstdint>
#include <string>

namespace nckit::drive {

//! Why a step rate could not be set (Ruckig-style named outcomes, never bare integers).
enum class TimerStatus {
    ok,
    too_fast,     //!< the divisor would fall below the counter's minimum
    too_slow,     //!< the divisor would exceed the counter's 16 bits
    invalid_rate  //!< the wanted rate is zero, negative or not finite
};

//! What the counter does for one wanted step rate. When `status` is not ok, `divisor`,
//! `rate_hz` and `speed_error` are 0 and only the range fields are meaningful.
struct TimerSetting {
    TimerStatus status = TimerStatus::ok;
    double wanted_hz = 0;       //!< steps/s asked for
    std::uint32_t divisor = 0;  //!< clock counts per step
    double rate_hz = 0;         //!< steps/s the divisor really gives: clock_hz / divisor
    //! Relative, signed: rate_hz / wanted_hz - 1, i.e. crosshatch.md's |f/R - n| / n with a
    //! sign. steppers.md's |1 - R n / f| is measured against the real rate instead; the two
    //! differ only by the square of the error.
    double speed_error = 0;
    double min_rate_hz = 0;  //!< slowest rate the counter makes: clock_hz / max_divisor
    double max_rate_hz = 0;  //!< fastest rate the counter makes: clock_hz / min_divisor

    [[nodiscard]] bool ok() const { return status == TimerStatus::ok; }
    //! One line for a person: the setting, or why it failed and which range is achievable.
    [[nodiscard]] std::string message() const;
};

//! An 8253-style down counter dividing a fixed clock: one step each `divisor` clock counts.
//! Modes 2 and 3 of the 8253 need a divisor of at least 2; a loaded 0 counts 65536, so a
//! caller who uses that convention sets max_divisor = 65536 (load_value() then writes 0).
struct IntervalTimer {
    double clock_hz = 1'000'000.0;      //!< Hz, counter input clock
    std::uint32_t min_divisor = 2;      //!< smallest divisor the counter mode accepts
    std::uint32_t max_divisor = 65535;  //!< 65535, or 65536 with the 0 = 65536 convention

    [[nodiscard]] double min_rate_hz() const { return clock_hz / max_divisor; }
    [[nodiscard]] double max_rate_hz() const { return clock_hz / min_divisor; }

    //! The divisor whose rate lies nearest `wanted_hz` (least |speed_error|), or why none
    //! can: a wanted rate outside [min_rate_hz, max_rate_hz] is an error, never clamped.
    [[nodiscard]] TimerSetting setting_for(double wanted_hz) const;

    //! The 16-bit value written to the counter for `divisor` (65536 is written as 0).
    [[nodiscard]] static std::uint16_t load_value(std::uint32_t divisor) {
        return static_cast<std::uint16_t>(divisor & 0xFFFFU);
    }
};

}  // namespace nckit::drive
