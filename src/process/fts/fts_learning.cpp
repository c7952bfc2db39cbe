#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "nckit/process/fts/fts_controller.hpp"

namespace nckit {

namespace {

//! Slot of tick p in a ring of `size`; ticks before 0 land on slots not yet written (zeros).
std::size_t slot(std::int64_t p, std::size_t size) {
    const auto s = static_cast<std::int64_t>(size);
    return static_cast<std::size_t>(((p % s) + s) % s);
}

}  // namespace

RepetitiveLearning::RepetitiveLearning(const ZpetcFeedforward& inverse, int counts_per_turn,
                                       const FtsLearning& settings, std::int64_t ignored_ticks)
    : counts_(counts_per_turn),
      settings_(settings),
      inverse_taps_(inverse.taps()),
      ignored_ticks_(std::max<std::int64_t>(ignored_ticks, 0)) {
    if (counts_per_turn < 8 || settings.harmonics < 0 || counts_per_turn < 2 * settings.harmonics + 1) {
        throw std::invalid_argument("learning needs 8 or more counts and 0 <= harmonics < counts / 2");
    }
    if (!(settings.gain > 0.0 && settings.gain < 2.0)) {
        throw std::invalid_argument("learning gain must lie in (0, 2)");
    }
    const int n = counts_per_turn;
    half_ = n / 2;
    low_pass_.resize(static_cast<std::size_t>(2 * half_ + 1));
    for (int i = -half_; i <= half_; ++i) {
        double tap = 1.0;
        for (int m = 1; m <= settings.harmonics; ++m) {
            // m |i| mod n: small angles, and taps at -i and +i computed alike (exactly symmetric).
            const auto k = static_cast<double>((static_cast<std::int64_t>(m) * std::abs(i)) % n);
            tap += 2.0 * std::cos(2.0 * std::numbers::pi * k / n);
        }
        tap /= n;
        // With n even the kernel's period has one tap at -n/2 = +n/2: half of it at each end
        // keeps Q symmetric (zero-phase) and its taps summed over a period unchanged.
        if (n % 2 == 0 && (i == -half_ || i == half_)) tap *= 0.5;
        low_pass_[static_cast<std::size_t>(i + half_)] = tap;
    }
    // Reads reach back N + half ticks; writes run 2 ticks behind the current one.
    const auto ring = static_cast<std::size_t>(n + half_ + 8);
    corrections_.assign(ring, 0.0);
    sums_.assign(ring, 0.0);
}

double RepetitiveLearning::next(double error_mm) {
    const std::int64_t n = tick_++;
    const std::size_t ring = corrections_.size();
    std::rotate(errors_.begin(), errors_.begin() + 1, errors_.end());
    errors_[3] = error_mm;
    // v[p] needs e[p+2]: it is ready two ticks late, far inside the turn of delay learning has.
    const std::int64_t p = n - 2;
    if (p >= 0) {
        double v = 0.0;
        if (p - 1 >= ignored_ticks_) {
            v = -settings_.gain * (inverse_taps_[0] * errors_[0] + inverse_taps_[1] * errors_[1] +
                                   inverse_taps_[2] * errors_[2] + inverse_taps_[3] * errors_[3]);
        }
        sums_[slot(p, ring)] = corrections_[slot(p, ring)] + v;
    }
    // c[n] = sum_i q_i (c + v)[n - N + i], i = -half .. half: all at or before n - 2.
    double c = 0.0;
    const std::int64_t first = n - counts_ - half_;
    std::size_t s = slot(first, ring);
    for (const double q : low_pass_) {
        c += q * sums_[s];
        if (++s == ring) s = 0;
    }
    corrections_[slot(n, ring)] = c;
    return c;
}

void RepetitiveLearning::retune(const ZpetcFeedforward& inverse, double gain) {
    if (!(gain > 0.0 && gain < 2.0)) throw std::invalid_argument("learning gain must lie in (0, 2)");
    inverse_taps_ = inverse.taps();
    settings_.gain = gain;
}

void RepetitiveLearning::reset(std::int64_t ignored_ticks) {
    std::fill(corrections_.begin(), corrections_.end(), 0.0);
    std::fill(sums_.begin(), sums_.end(), 0.0);
    errors_ = {};
    tick_ = 0;
    ignored_ticks_ = std::max<std::int64_t>(ignored_ticks, 0);
}

RepetitiveLearning::Contraction RepetitiveLearning::contraction(const drive::ServoDiscretisation& plant) const {
    auto factor = [&](double w, bool with_low_pass) {
        std::complex<double> inverse = 0.0;
        for (int j = 0; j < 4; ++j)
            inverse += inverse_taps_[static_cast<std::size_t>(j)] * std::polar(1.0, w * (j - 1));
        double q = 1.0;
        if (with_low_pass) {
            q = 0.0;
            for (int i = -half_; i <= half_; ++i) q += low_pass_[static_cast<std::size_t>(i + half_)] * std::cos(w * i);
        }
        return std::abs(q) * std::abs(1.0 - settings_.gain * discrete_response(plant, w) * inverse);
    };
    Contraction out;
    for (int m = 0; m <= settings_.harmonics; ++m) {
        out.learned_harmonics = std::max(out.learned_harmonics, factor(2.0 * std::numbers::pi * m / counts_, false));
    }
    // Eight points per harmonic spacing up to half the tick rate: Q's lobes are one spacing wide.
    const int points = 4 * counts_;
    for (int k = 0; k <= points; ++k) {
        out.any_frequency = std::max(out.any_frequency, factor(std::numbers::pi * k / points, true));
    }
    return out;
}

}  // namespace nckit
