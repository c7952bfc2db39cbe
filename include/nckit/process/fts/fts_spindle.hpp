#pragma once
// The spindle as the fast tool servo's clock: the controller updates at every encoder count, so
// when the spindle speed ripples the time between updates ripples with it.
#include <vector>

namespace nckit {

//! Spindle speed ripple: n(t) = rpm (1 + fraction sin(per_turn theta + phase)
//!                                     + slow_fraction sin(2 pi slow_hz t)).
//! The default, ±0.2 % once per turn, is what a spindle drive's speed loop leaves of the load
//! torque a cut that is not round puts on it, plus the encoder's own once-per-turn eccentricity;
//! repeating with the angle, it is part of what learning across revolutions removes. The slow
//! component stands for a speed loop hunting at a frequency of its own (off by default): it does
//! not repeat per turn, so learning only follows it.
struct SpindleRipple {
    double fraction = 0.002;     //!< amplitude of the synchronous part, fraction of the nominal speed
    int per_turn = 1;            //!< its cycles per turn
    double phase_deg = 0.0;      //!< its phase at the major axis (theta = 0), deg
    double slow_fraction = 0.0;  //!< amplitude of the non-synchronous part, fraction
    double slow_hz = 0.7;        //!< its frequency, Hz
};

//! Tick durations of a spindle turning at `rpm` with `ripple`, one tick per encoder count.
class SpindleClock {
public:
    //! Throws std::invalid_argument for rpm <= 0, counts < 1 or a ripple that could stop the
    //! spindle (fraction + slow_fraction >= 1): jobs are checked before a clock is built.
    SpindleClock(double rpm, int counts_per_turn, const SpindleRipple& ripple);

    //! s from count `count` (0 .. counts - 1) to the next, starting at time `t_s`: the time the
    //! spindle model (plan/spindle_model.hpp) takes through the count, exactly, shortened by the
    //! slow component at t_s. Without the slow component this depends on the count alone, bit
    //! for bit, every turn.
    [[nodiscard]] double tick_period_s(int count, double t_s) const;
    //! s per count at the nominal speed: the controller's own idea of its period.
    [[nodiscard]] double nominal_period_s() const { return nominal_period_s_; }
    //! Angle of `count` from the major axis, deg.
    [[nodiscard]] double angle_deg(int count) const;
    [[nodiscard]] int counts_per_turn() const { return counts_; }

private:
    int counts_ = 0;
    double nominal_period_s_ = 0.0;
    SpindleRipple ripple_;
    std::vector<double> synchronous_speed_;  //!< each count's mean speed over the nominal, from the exact period
};

}  // namespace nckit
