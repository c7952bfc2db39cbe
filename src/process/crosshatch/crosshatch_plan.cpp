// The crosshatch speeds, step counts, timer divisors and index rule (docs/processes/crosshatch.md).
#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "nckit/process/crosshatch/crosshatch.hpp"

namespace nckit {

namespace {

constexpr double pi = std::numbers::pi;

double degrees(double radians) {
    return radians * 180.0 / pi;
}

//! The counter's setting for `rate_hz`, or an error at `where` naming the motor.
Result<drive::TimerSetting> timer_for(const CrosshatchJob& job, double rate_hz, std::string_view motor,
                                      const SourceLocation& where) {
    const drive::IntervalTimer timer{job.timer_clock_hz, 2, job.timer_max_divisor};
    drive::TimerSetting setting = timer.setting_for(rate_hz);
    if (setting.ok()) return setting;
    const bool too_fast = setting.status == drive::TimerStatus::too_fast;
    return error_at(where, "crosshatch-timer",
                    fmt::format("the {} motor needs {:.6g} steps/s, {} than the counter makes ({:.6g} to {:.6g} "
                                "steps/s at {:.6g} Hz with divisors {} to {}){}",
                                motor, rate_hz, too_fast ? "faster" : "slower", setting.min_rate_hz,
                                setting.max_rate_hz, job.timer_clock_hz, timer.min_divisor, timer.max_divisor,
                                too_fast ? "" : ": a slower rate needs a prescaler or a slower clock"));
}

}  // namespace

Result<CrosshatchPlan> plan_crosshatch(const CrosshatchJob& job) {
    CrosshatchPlan plan;
    plan.job = job;
    const double motor_steps_per_turn = job.gear_ratio * 360.0 / job.step_angle_deg;
    const double screw_turns_per_stroke = job.bore_length_mm / job.lead_screw_pitch_mm;

    plan.turns_per_stroke = job.lines_per_length / job.heads;
    plan.feed_mm_min = job.lead_screw_pitch_mm * job.feed_screw_rpm;
    plan.rotation_rpm = plan.feed_mm_min * plan.turns_per_stroke / job.bore_length_mm;
    plan.surface_speed_mm_min = pi * job.bore_diameter_mm * plan.rotation_rpm;
    plan.stroke_time_s = job.bore_length_mm / plan.feed_mm_min * 60.0;
    plan.line_spacing_mm = job.bore_length_mm / job.lines_per_length;
    // tan β = H·I / (π·D·N): geometry alone, whatever the speeds.
    plan.helix_angle_deg =
        degrees(std::atan2(job.bore_length_mm * job.heads, pi * job.bore_diameter_mm * job.lines_per_length));
    plan.crosshatch_angle_deg = 2.0 * plan.helix_angle_deg;

    plan.rotation.shaft_rpm = plan.rotation_rpm;
    plan.rotation.steps_per_unit = motor_steps_per_turn / 360.0;
    plan.feed.shaft_rpm = job.feed_screw_rpm;
    plan.feed.steps_per_unit = motor_steps_per_turn / job.lead_screw_pitch_mm;
    plan.rotation_steps_per_turn = motor_steps_per_turn;
    plan.feed_steps_per_stroke = std::llround(screw_turns_per_stroke * motor_steps_per_turn);
    plan.rotation_steps_per_stroke = std::llround(plan.turns_per_stroke * motor_steps_per_turn);

    Diagnostics errors;
    // The rotation speed follows from the feed speed and the pattern, so both point at V2.
    auto rotation = timer_for(job, plan.rotation_rpm / 60.0 * motor_steps_per_turn, "rotation", job.feed_screw_rpm_at);
    auto feed = timer_for(job, job.feed_screw_rpm / 60.0 * motor_steps_per_turn, "feed", job.feed_screw_rpm_at);
    const double index_rpm = job.index_rpm > 0 ? job.index_rpm : plan.rotation_rpm;
    auto index = timer_for(job, index_rpm / 60.0 * motor_steps_per_turn, "rotation (index move)",
                           job.index_rpm > 0 ? job.index_rpm_at : job.feed_screw_rpm_at);
    for (auto* setting : {&rotation, &feed, &index}) {
        if (*setting) continue;
        errors.insert(errors.end(), setting->diagnostics().begin(), setting->diagnostics().end());
    }
    if (plan.feed_steps_per_stroke < 1) {
        errors.push_back(error_at(job.bore_length_at, "crosshatch-stroke",
                                  fmt::format("a {} mm stroke is less than one feed step ({} mm)", job.bore_length_mm,
                                              1.0 / plan.feed.steps_per_unit)));
    }
    if (!errors.empty()) return errors;
    plan.rotation.timer = *rotation;
    plan.feed.timer = *feed;
    plan.index_timer = *index;

    // Index rule, in whole motor steps so the correction the motor makes is the one reported.
    const double turn = motor_steps_per_turn;
    const double round_trip_steps = 2.0 * static_cast<double>(plan.rotation_steps_per_stroke);
    plan.round_trip_deg = std::fmod(round_trip_steps / plan.rotation.steps_per_unit, 360.0);
    const double index_steps = job.index_deg * plan.rotation.steps_per_unit;
    double head_steps = 0;  // unwrapped position at the start of each cycle
    for (int cycle = 0; cycle < job.cycles; ++cycle) {
        const double end_of_strokes = head_steps + round_trip_steps;
        const double target = std::round(static_cast<double>(cycle + 1) * index_steps);
        // α: how far the strokes overshoot the target, mod a turn. The shorter way: back by α
        // below half a turn, forward by a turn less α from half a turn on.
        double alpha = std::fmod(end_of_strokes - target, turn);
        if (alpha < 0) alpha += turn;
        const std::int64_t move = std::llround(alpha < turn / 2.0 ? -alpha : turn - alpha);
        plan.index_moves_steps.push_back(move);
        head_steps = end_of_strokes + static_cast<double>(move);
    }
    plan.index_move_steps = plan.index_moves_steps.empty() ? 0 : plan.index_moves_steps.front();
    plan.special = std::all_of(plan.index_moves_steps.begin(), plan.index_moves_steps.end(),
                               [](std::int64_t move) { return move == 0; });
    plan.index_move_deg = static_cast<double>(plan.index_move_steps) / plan.rotation.steps_per_unit;
    return plan;
}

}  // namespace nckit
