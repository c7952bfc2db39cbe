#include "nckit/process/fts/cam_follower.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace nckit {

namespace {

//! Weight of the newest period in the spindle speed estimate (a 2 ms time constant at 15 kHz).
//! An encoder whose count rate sits just below the thread's gives no count in a rare period; the
//! estimate then moves by 1/32 of a count, so the preview the feedforward reads stays within a
//! few hundredths of a count of where the spindle goes.
constexpr double speed_filter = 1.0 / 32.0;

//! The learning's inverse is re-tuned to one count's time when the speed has moved this much.
constexpr double retune_speed_fraction = 0.02;

//! Below this speed (counts per tick) the spindle counts as stopped: no learning, no re-tune.
constexpr double stopped_counts_per_tick = 0.05;

//! Turns the revolution input may reach.
constexpr double max_revolutions = 1099511627776.0;

std::int64_t modulo(std::int64_t a, std::int64_t n) {
    const std::int64_t r = a % n;
    return r < 0 ? r + n : r;
}

bool model_valid(const CamFollowerSettings& s) {
    return std::isfinite(s.model_gain) && s.model_gain > 0.0 && std::isfinite(s.model_natural_frequency_hz) &&
           s.model_natural_frequency_hz > 0.0 && std::isfinite(s.model_damping) && s.model_damping >= 0.0 &&
           s.learning_gain > 0.0 && s.learning_gain < 2.0;
}

}  // namespace

CamFollower::CamFollower(const cam::CamTable& table, const StrokeReference* reference, int counts_per_rev,
                         double period_s, const CamFollowerSettings& initial)
    : table_(&table),
      reference_(reference),
      counts_(counts_per_rev),
      period_s_(period_s),
      harmonics_(std::min(FtsLearning{}.harmonics, std::max(0, (counts_per_rev - 1) / 2))),
      has_z_(table.z_to_mm() > table.z_from_mm()) {
    if (counts_per_rev < 8) throw std::invalid_argument("the cam follower needs 8 or more counts per turn");
    if (!(period_s > 0.0) || !std::isfinite(period_s)) throw std::invalid_argument("the servo period must be > 0");
    if (!model_valid(initial)) throw std::invalid_argument("the cam follower's model settings are out of range");
    model_ = drive::ServoParameters::from_natural_frequency(initial.model_gain, initial.model_natural_frequency_hz,
                                                            initial.model_damping);
    model_frequency_hz_ = initial.model_natural_frequency_hz;
    learning_gain_ = initial.learning_gain;
    learning_period_s_ = period_s;
    feedforward_.emplace(model_, period_s);
    count_inverse_.emplace(model_, period_s);
    learning_.emplace(*count_inverse_, counts_, FtsLearning{initial.learning_gain, harmonics_}, counts_);
    last_z_mm_ = table.z_from_mm();
}

double CamFollower::wanted_at(double position_counts, double z_mm, double scale, bool centre) const {
    const double theta_deg = 360.0 * position_counts / counts_;
    const double z = std::clamp(z_mm, table_->z_from_mm(), table_->z_to_mm());
    const double reference = centre && reference_ != nullptr ? reference_->radius_mm(z) : 0.0;
    return scale * ((*table_)(theta_deg, z) - reference);
}

void CamFollower::track_counts(const CamFollowerInput& in, const CamFollowerSettings& settings,
                               CamFollowerOutput& out) {
    // Differences in 32 bits wrap as the hardware counter does; the sum is kept in 64.
    const auto delta =
        static_cast<std::int32_t>(static_cast<std::uint32_t>(in.counts) - static_cast<std::uint32_t>(last_counts_));
    position_ += delta;
    last_counts_ = in.counts;
    if (in.reset_faults) index_fault_ = false;
    const bool rising = in.index && !last_index_;
    last_index_ = in.index;
    if (rising) {
        if (!synced_) {
            zero_ = position_;
            synced_ = true;
        } else {
            std::int64_t off = modulo(position_ - zero_, counts_);
            off = std::min(off, counts_ - off);
            if (off <= std::max(0, settings.index_tolerance_counts)) {
                zero_ = position_;
            } else {
                index_fault_ = true;  // a glitch or a slipped encoder: keep counting, say so
            }
        }
    }
    out.index_fault = index_fault_;
    out.count_in_turn = modulo(position_ - zero_, counts_);
}

void CamFollower::retune(const CamFollowerSettings& settings, CamFollowerOutput& out) {
    const bool model_changed =
        period_changed_ || settings.model_gain != model_.gain || settings.model_damping != model_.damping ||
        settings.model_natural_frequency_hz != model_frequency_hz_ || settings.learning_gain != learning_gain_;
    const double count_period_s = speed_ > stopped_counts_per_tick ? period_s_ / speed_ : learning_period_s_;
    const bool speed_moved = std::abs(count_period_s - learning_period_s_) > retune_speed_fraction * learning_period_s_;
    if (!model_changed && !speed_moved) return;
    if (!model_valid(settings)) {
        settings_fault_ = true;
        out.settings_fault = true;
        return;
    }
    try {
        const drive::ServoParameters model = drive::ServoParameters::from_natural_frequency(
            settings.model_gain, settings.model_natural_frequency_hz, settings.model_damping);
        feedforward_.emplace(model, period_s_);
        count_inverse_.emplace(model, count_period_s);
        learning_->retune(*count_inverse_, settings.learning_gain);
        model_ = model;
        model_frequency_hz_ = settings.model_natural_frequency_hz;
        period_changed_ = false;
        learning_gain_ = settings.learning_gain;
        learning_period_s_ = count_period_s;
        settings_fault_ = false;
    } catch (const std::exception&) {
        // Validated above, so not reached; if it were, the last good tuning stays.
        settings_fault_ = true;
    }
    out.settings_fault = settings_fault_;
}

void CamFollower::set_period(double period_s) {
    if (!(period_s > 0.0) || !std::isfinite(period_s) || period_s == period_s_) return;
    // The learning's count time scales with the tick while the speed in counts per tick holds.
    learning_period_s_ *= period_s / period_s_;
    period_s_ = period_s;
    period_changed_ = true;
}

void CamFollower::step(const CamFollowerInput& in, const CamFollowerSettings& settings, CamFollowerOutput& out) {
    out.settings_fault = settings_fault_;
    out.input_fault = false;
    out.dac_clamped = false;
    out.learning_active = false;

    // Spindle: the position within the turn in counts (real), and how far it moved.
    double in_turn = 0.0;
    double moved = 0.0;
    std::int64_t whole = 0;  //!< counts since start, for the learning's count steps
    if (in.use_counts) {
        if (!started_) {
            last_counts_ = in.counts;
            position_ = in.counts;
        }
        const std::int64_t before = position_;
        track_counts(in, settings, out);
        moved = static_cast<double>(position_ - before);
        in_turn = static_cast<double>(out.count_in_turn);
        whole = position_;
    } else {
        double revolutions = in.revolutions;
        // Beyond 2^40 turns (35 years at 1000 rpm) the counts no longer fit the arithmetic.
        if (!std::isfinite(revolutions) || std::abs(revolutions) > max_revolutions) {
            out.input_fault = true;
            revolutions = last_position_ / counts_;
        }
        const double position = revolutions * counts_;
        if (!started_) last_position_ = position;
        moved = position - last_position_;
        last_position_ = position;
        in_turn = position - std::floor(position / counts_) * counts_;
        out.count_in_turn = static_cast<std::int64_t>(std::floor(in_turn));
        whole = static_cast<std::int64_t>(std::floor(position));
        out.index_fault = false;
    }
    // More than a turn per period is no speed a cam can follow (a counter reset, say): the
    // preview is bounded to a turn either way.
    moved = std::clamp(moved, -static_cast<double>(counts_), static_cast<double>(counts_));
    speed_ = started_ ? speed_ + speed_filter * (moved - speed_) : 0.0;
    out.counts_per_tick = speed_;
    out.angle_deg = 360.0 * in_turn / counts_;

    // Z: held inside the table, its rate for the preview.
    double z = in.z_mm;
    if (!std::isfinite(z)) {
        z = last_z_mm_;
        out.z_fault = has_z_;
        out.input_fault = true;
    } else {
        out.z_fault = has_z_ && (z < table_->z_from_mm() || z > table_->z_to_mm());
        z = std::clamp(z, table_->z_from_mm(), table_->z_to_mm());
    }
    const double z_step = started_ ? z - last_z_mm_ : 0.0;
    last_z_mm_ = z;
    started_ = true;

    retune(settings, out);

    out.cam_mm = (*table_)(out.angle_deg, z);
    out.wanted_mm = wanted_at(in_turn, z, settings.scale, settings.centre);
    double feedback = in.feedback_mm;
    if (!std::isfinite(feedback)) {
        out.input_fault = true;
        feedback = last_feedback_mm_;
    }
    last_feedback_mm_ = feedback;
    out.error_mm = feedback - out.wanted_mm;

    double command = out.wanted_mm;
    if (settings.feedforward) {
        const double v = speed_;
        const double window[4] = {wanted_at(in_turn - v, z - z_step, settings.scale, settings.centre), out.wanted_mm,
                                  wanted_at(in_turn + v, z + z_step, settings.scale, settings.centre),
                                  wanted_at(in_turn + 2.0 * v, z + 2.0 * z_step, settings.scale, settings.centre)};
        command = feedforward_->command(std::span<const double, 4>(window, 4));
    }

    // Learning: one step per count the spindle moved forward, indexed by count.
    if (settings.learning && speed_ > stopped_counts_per_tick) {
        if (!learning_on_) {
            learning_->reset(counts_);  // the first turn after (re)starting is the transient
            learned_to_ = whole;
            learning_on_ = true;
            correction_mm_ = 0.0;
        }
        const std::int64_t steps = whole - learned_to_;
        if (steps < 0) {
            learning_on_ = false;  // turned back: what was learned belongs to the other direction
            correction_mm_ = 0.0;
        } else {
            const std::int64_t taken = std::min<std::int64_t>(steps, counts_);
            for (std::int64_t i = 0; i < taken; ++i) correction_mm_ = learning_->next(out.error_mm);
            learned_to_ = whole;
            out.learning_active = taken > 0;
        }
    } else if (!settings.learning || speed_ < -stopped_counts_per_tick) {
        learning_on_ = false;
        correction_mm_ = 0.0;
    }
    command += correction_mm_;
    out.correction_mm = correction_mm_;

    if (!std::isfinite(command)) {
        command = last_command_mm_;
        out.input_fault = true;
    }
    if (settings.dac_bits >= 2 && settings.dac_bits <= 32 && settings.dac_stroke_mm > 0.0 &&
        std::isfinite(settings.dac_stroke_mm)) {
        const Dac::Output dac = Dac{settings.dac_bits, settings.dac_stroke_mm}.convert(command);
        command = dac.command_mm;
        out.dac_clamped = dac.clamped;
    }
    last_command_mm_ = command;
    out.command_mm = command;
}

}  // namespace nckit
