#pragma once
// The fast tool servo's controller, one piece per class: the DAC it commands through, the
// feedforward that inverts its model of the axis, and the learning that corrects what that model
// gets wrong, turn after turn. Each works in encoder counts: the controller updates once per
// count, so its nominal period is one count at the nominal spindle speed.
#include <array>
#include <complex>
#include <cstdint>
#include <span>
#include <vector>

#include "nckit/drive/servo_model.hpp"

namespace nckit {

//! A DAC of `bits` over `stroke_mm`, centred: code 2^(bits-1) is 0 mm, mid-stroke.
struct Dac {
    int bits = 16;           //!< resolution; codes 0 .. 2^bits - 1
    double stroke_mm = 1.0;  //!< mm, full scale: codes span -stroke/2 .. stroke/2 - one step

    //! One code's displacement, mm: stroke / 2^bits (16 bits over 1 mm: 15.26 nm).
    [[nodiscard]] double step_mm() const;

    struct Output {
        std::int64_t code = 0;    //!< the code written
        double command_mm = 0.0;  //!< what that code commands, mm from mid-stroke
        bool clamped = false;     //!< the wanted value lay beyond the codes: the end code was used
    };
    //! The nearest code to `wanted_mm` (ties away from zero), clamped to the DAC's range.
    [[nodiscard]] Output convert(double wanted_mm) const;
};

//! Zero-phase error tracking control (Tomizuka 1987) of the zero-order-hold discretisation of
//! k / (T^2 s^2 + 2 zeta T s + 1): y[n] / u[n] = (b1 z + b2) / (z^2 + a1 z + a2). The poles are
//! inverted exactly; the sampling zero at -b2/b1 lies close to -1 at any useful rate, where an
//! exact inverse would ring at half the tick rate, so its factor is replaced by the zero-phase
//! (1 + beta q) / (1 + beta)^2, beta = b2 / b1, whose gain error is ~ beta W^2 / (1 + beta)^2
//! at W rad per tick (3e-4 at 2 cycles per 360-count turn). The result is a 4-tap FIR over the
//! wanted positions y[n-1] .. y[n+2]: a preview of two ticks, which the known profile gives.
class ZpetcFeedforward {
public:
    //! Throws std::invalid_argument for parameters ServoModel rejects.
    ZpetcFeedforward(const drive::ServoParameters& model, double period_s);

    //! The command to hold over tick n, from the wanted positions at ticks n-1, n, n+1, n+2.
    [[nodiscard]] double command(std::span<const double, 4> wanted_mm) const;

    //! u[n] = sum_j taps[j] y[n - 1 + j]; they sum to 1 / k.
    [[nodiscard]] const std::array<double, 4>& taps() const { return taps_; }
    //! beta: the sampling zero lies at z = -beta.
    [[nodiscard]] double zero_ratio() const { return beta_; }

    static constexpr int preview_ticks = 2;  //!< future wanted positions used
    static constexpr int history_ticks = 1;  //!< past wanted positions used

private:
    std::array<double, 4> taps_{};
    double beta_ = 0.0;
};

//! Position response at the ticks to a command held over each tick, at W rad per tick:
//! c (e^{jW} I - Phi)^-1 Gamma (one tick of delay included).
[[nodiscard]] std::complex<double> discrete_response(const drive::ServoDiscretisation& plant, double rad_per_tick);

//! Learning across revolutions, settings.
struct FtsLearning {
    //! Fraction of the model-inverted error taken into the correction per turn: 1 would remove it
    //! in one turn were the model exact; below 1 keeps |1 - gain G / G_model| well under 1 when
    //! the model is 10-20 % off in gain, frequency and damping.
    double gain = 0.6;
    //! Highest harmonic of the turn learned: the zero-phase low-pass Q passes 0 .. harmonics and
    //! stops the rest, so quantisation and the non-periodic part of the error are not chased up
    //! to where the model is least reliable. Must stay below half the counts per turn.
    int harmonics = 24;
};

//! Learning across revolutions in the angle domain: a repetitive controller that adds a
//! correction c to the feedforward, tick by tick,
//!   c[n] = Q (c + v)[n - N],   v[p] = -gain * Z e[p],
//! N the encoder counts per turn, e = measured - wanted position, Z the ZPETC inverse of the
//! controller's model applied to the error sequence (the "phase lead": e[p-1] .. e[p+2]), and Q a
//! zero-phase FIR low-pass: the Dirichlet kernel of harmonics 0 .. `harmonics` spread over one
//! turn (taps -N/2 .. N/2), whose response is exactly 1 at every learned harmonic and 0 at every
//! other harmonic of the turn. Per learned harmonic the error then shrinks each turn by
//! |1 - gain G Z| (G the true axis), and stays bounded everywhere while |Q (1 - gain G Z)| < 1
//! at all frequencies. Working on the time-ordered errors (not turn by turn) keeps the jump
//! between one turn's end and the next turn's start out of the learning, where a model inverse
//! would amplify it. Indexing by count makes a speed ripple that repeats each turn part of what
//! is learned. Errors of the first `ignored_ticks` (the servo's start from rest, which never
//! repeats) are not learned from.
class RepetitiveLearning {
public:
    //! Throws std::invalid_argument for counts < max(8, 2 * harmonics + 1), harmonics < 0 or a
    //! gain outside (0, 2): the job's values are checked before this is built.
    RepetitiveLearning(const ZpetcFeedforward& inverse, int counts_per_turn, const FtsLearning& settings,
                       std::int64_t ignored_ticks);

    //! Takes the error measured at this tick (ticks in order from 0), mm; returns the correction
    //! to add to this tick's command, mm.
    double next(double error_mm);

    //! Takes the inverse's taps and `gain` (in (0, 2); else std::invalid_argument) from here on,
    //! keeping what has been learned: a servo thread whose model or speed changed. Allocates nothing.
    void retune(const ZpetcFeedforward& inverse, double gain);
    //! Forgets everything learned (the spindle reversed, say); the first `ignored_ticks` after it
    //! are not learned from. Allocates nothing.
    void reset(std::int64_t ignored_ticks);

    //! sup over frequency of |Q (1 - gain G Z)| for the axis `plant` at the nominal tick (< 1:
    //! the learning converges) and the same at the learned harmonics alone (the factor the error
    //! there shrinks by per turn, once the transients have passed).
    struct Contraction {
        double any_frequency = 0.0;
        double learned_harmonics = 0.0;
    };
    [[nodiscard]] Contraction contraction(const drive::ServoDiscretisation& plant) const;

    [[nodiscard]] int counts_per_turn() const { return counts_; }
    //! Q's taps, offsets -half .. half.
    [[nodiscard]] const std::vector<double>& low_pass() const { return low_pass_; }

private:
    int counts_ = 0;
    int half_ = 0;  //!< Q spans offsets -half_ .. half_
    FtsLearning settings_;
    std::array<double, 4> inverse_taps_{};  //!< Z over e[p-1] .. e[p+2]
    std::vector<double> low_pass_;          //!< Q's taps
    std::int64_t ignored_ticks_ = 0;
    std::int64_t tick_ = 0;            //!< ticks taken so far
    std::array<double, 4> errors_{};   //!< e[n-3] .. e[n]
    std::vector<double> corrections_;  //!< c, ring of the last ring_ ticks
    std::vector<double> sums_;         //!< c + v, same ring
};

}  // namespace nckit
