#pragma once
// The spindle as a clock for synchronised motion: its angle over time under the program's speed
// commands, with the drive's speed ripple, its encoder counts and the index pulse.
//
// Angle: dθ/dt = ω·(1 + r·sin(k·θ + φ)) while turning forward (M3); M4 turns backwards with the
// same ripple in the spindle's own angle. The time to turn from θ0 to θ1 has a closed form
// (∫ dθ / (1 + r sin(kθ + φ)), one period takes 2π / (k·sqrt(1 − r²))), so the angle at any time
// is exact up to rounding: there is no integration step to drift over a long program.
#include <optional>
#include <vector>

#include "nckit/core/machine.hpp"
#include "nckit/interp/move.hpp"

namespace nckit {

class SpindleModel {
public:
    //! The spindle stands at angle 0 (the index) at time 0. Throws std::invalid_argument for a
    //! ripple fraction outside [0, 1) or a harmonic below 1 (configs are checked before).
    explicit SpindleModel(const SpindleConfig& config);

    //! From `t_s` on the spindle turns at `rpm`: positive forward (M3), negative backward
    //! (M4), 0 stopped (M5). Calls come in time order.
    void set_speed(double t_s, double rpm);

    //! deg, continuous (not wrapped), at `t_s` (at or after the last set_speed).
    [[nodiscard]] double angle_deg(double t_s) const;
    //! Encoder count at `t_s`: floor(angle / 360 · counts), continuous over turns.
    [[nodiscard]] long long count_at(double t_s) const;
    //! s: the first time at or after `t_s` at which the spindle stands `past_index_deg` (in
    //! [0, 360)) past its index pulse in its turning sense (angle ≡ past_index_deg under M3,
    //! ≡ −past_index_deg under M4, mod 360°), or nothing when the spindle stands. 0: the index
    //! pulse itself.
    [[nodiscard]] std::optional<double> next_index_s(double t_s, double past_index_deg = 0) const;
    //! rpm commanded now (signed as in set_speed).
    [[nodiscard]] double rpm() const { return rpm_; }
    //! rpm averaged over a turn: the ripple slows a turn by 1/sqrt(1 − r²).
    [[nodiscard]] double mean_rpm() const;
    [[nodiscard]] const SpindleConfig& config() const { return config_; }
    //! s to turn from `from_deg` to `to_deg` (angles in the turning sense: −θ under M4,
    //! to >= from) at the current speed, exactly. The spindle must be turning.
    [[nodiscard]] double travel_time_s(double from_deg, double to_deg) const;

private:
    SpindleConfig config_;
    double rpm_ = 0;
    double since_s_ = 0;          //!< time of the last speed change
    double angle_since_deg_ = 0;  //!< angle then
};

//! The spindle commands of a move stream: S sets the speed, M3/M4 start it, M5, M2 and M30
//! stop it. Under G96 the speed follows the diameter; nckit keeps the last known rpm then.
struct SpindleCommand {
    double rpm = 0;     //!< last S in rpm, unsigned
    int direction = 0;  //!< +1 M3, -1 M4, 0 stopped

    //! Takes the event's effect; true when the spindle's speed or direction changed.
    bool apply(const Io& io);
    //! rpm to turn at, signed (0 stopped), limited to the machine's max_rpm (when set).
    [[nodiscard]] double signed_rpm(const SpindleConfig& config) const;
    //! rpm it turns at on average, unsigned: signed_rpm slowed by the ripple (mean_rpm below).
    [[nodiscard]] double mean_rpm(const SpindleConfig& config) const;
};

//! rpm averaged over a turn of a spindle commanded `rpm` (either sign): a ripple of fraction r
//! lengthens each turn by 1/sqrt(1 − r²).
[[nodiscard]] double mean_rpm(double rpm, const SpindleConfig& config);

}  // namespace nckit
