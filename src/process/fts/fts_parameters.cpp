#include <cmath>

#include <fmt/format.h>

#include "nckit/process/fts/fast_tool_servo.hpp"

namespace nckit {

namespace {

//! Ticks per run beyond which a job is surely a typo (a 0.0001 mm/rev feed, say): 2^31 ticks
//! is 40 hours of spindle time at 15 kHz.
constexpr double max_ticks = 2147483648.0;

bool finite_positive(double x) {
    return std::isfinite(x) && x > 0.0;
}

}  // namespace

Diagnostics check_fts_parameters(const FtsParameters& p) {
    Diagnostics out;
    auto fail = [&](std::string message) { out.push_back(error_at(p.where, "fts-parameter", std::move(message))); };
    const FtsServo& s = p.servo;
    if (!finite_positive(s.natural_frequency_hz)) {
        fail(fmt::format("servo natural_frequency_hz must be positive, not {}", s.natural_frequency_hz));
    }
    if (!std::isfinite(s.damping) || s.damping < 0.0) {
        fail(fmt::format("servo damping must be 0 or more, not {}", s.damping));
    }
    // The model's gain, frequency and damping scale by 1 + e: they must stay positive.
    if (!std::isfinite(s.model_error) || s.model_error <= -0.9 || s.model_error >= 1.0) {
        fail(fmt::format("servo model_error must lie in (-0.9, 1), not {}", s.model_error));
    }
    if (s.dac_bits < 2 || s.dac_bits > 32) {
        fail(fmt::format("servo dac_bits must lie in 2 .. 32, not {}", s.dac_bits));
    }
    if (!finite_positive(s.stroke_mm)) {
        fail(fmt::format("servo stroke_mm must be positive, not {}", s.stroke_mm));
    }
    if (!finite_positive(p.rpm)) fail(fmt::format("rpm must be positive, not {}", p.rpm));
    if (p.encoder_counts < 8) {
        fail(fmt::format("encoder counts per turn must be 8 or more, not {}", p.encoder_counts));
    }
    const SpindleRipple& r = p.ripple;
    if (!std::isfinite(r.fraction) || r.fraction < 0.0 || !std::isfinite(r.slow_fraction) || r.slow_fraction < 0.0 ||
        r.fraction + r.slow_fraction >= 0.5) {
        fail(fmt::format("spindle ripple fractions must be 0 or more and together below 0.5, not {} + {}", r.fraction,
                         r.slow_fraction));
    }
    if (r.per_turn < 1) fail(fmt::format("ripple cycles per turn must be 1 or more, not {}", r.per_turn));
    if (!std::isfinite(r.phase_deg) || !std::isfinite(r.slow_hz) || r.slow_hz < 0.0) {
        fail("ripple phase and slow frequency must be finite, the frequency 0 or more");
    }
    if (!finite_positive(p.feed_mm_rev)) {
        fail(fmt::format("feed per turn must be positive, not {} mm", p.feed_mm_rev));
    }
    if (!std::isfinite(p.z_start_mm) || !std::isfinite(p.z_end_mm) || !(p.z_end_mm > p.z_start_mm)) {
        fail(fmt::format("the cut needs z_end > z_start, not {} .. {} mm", p.z_start_mm, p.z_end_mm));
    }
    if (p.air_turns < 0) fail(fmt::format("air turns must be 0 or more, not {}", p.air_turns));
    if (p.trace_turns < 0) fail(fmt::format("trace turns must be 0 or more, not {}", p.trace_turns));
    if (!(p.learning.gain > 0.0 && p.learning.gain < 2.0)) {
        fail(fmt::format("learning gain must lie in (0, 2), not {}", p.learning.gain));
    }
    if (p.learning.harmonics < 0 || 2 * p.learning.harmonics + 1 > p.encoder_counts) {
        fail(fmt::format("learned harmonics must lie in 0 .. {} (below half the counts per turn), not {}",
                         (p.encoder_counts - 1) / 2, p.learning.harmonics));
    }
    if (out.empty()) {
        const double turns = (p.z_end_mm - p.z_start_mm) / p.feed_mm_rev + p.air_turns + 1.0;
        if (turns * p.encoder_counts > max_ticks) {
            fail(fmt::format("the job runs {:.0f} turns of {} counts: over {:.0f} ticks", turns, p.encoder_counts,
                             max_ticks));
        }
    }
    return out;
}

}  // namespace nckit
