// The crosshatch scan on the timer clock: tracks, closure and the merged step streams.
#include <cmath>
#include <cstdlib>
#include <numbers>

#include "nckit/drive/phase_table.hpp"
#include "nckit/process/crosshatch/crosshatch_scan.hpp"

namespace nckit {

namespace {

//! The scan's timing in counter clock ticks, shared by the tracks and the step streams so the
//! two cannot disagree.
struct Timeline {
    std::int64_t feed_steps = 0;                   //!< F, per stroke
    std::int64_t rotation_steps = 0;               //!< R, per stroke (one time base)
    std::int64_t feed_divisor = 0;                 //!< d_f, ticks per feed step
    std::int64_t rotation_divisor = 0;             //!< d_r (free-running timers)
    std::int64_t index_divisor = 0;                //!< d_i, ticks per step of the index move
    const std::vector<std::int64_t>& index_steps;  //!< M of each cycle, signed
    double ns_per_tick = 0;
    bool free_running = false;

    explicit Timeline(const CrosshatchPlan& plan)
        : feed_steps(plan.feed_steps_per_stroke),
          rotation_steps(plan.rotation_steps_per_stroke),
          feed_divisor(plan.feed.timer.divisor),
          rotation_divisor(plan.rotation.timer.divisor),
          index_divisor(plan.index_timer.divisor),
          index_steps(plan.index_moves_steps),
          ns_per_tick(1e9 / plan.job.timer_clock_hz),
          free_running(plan.job.timing == CrosshatchTiming::free_running_timers) {}

    [[nodiscard]] std::int64_t stroke_ticks() const { return feed_steps * feed_divisor; }
    [[nodiscard]] std::int64_t index_ticks(int cycle) const { return std::llabs(index_steps[cycle]) * index_divisor; }
    //! Rotation steps the head advances over one stroke (fractional with free-running timers).
    [[nodiscard]] double rotation_per_stroke() const {
        if (!free_running) return static_cast<double>(rotation_steps);
        return static_cast<double>(stroke_ticks()) / static_cast<double>(rotation_divisor);
    }
    [[nodiscard]] double seconds(double ticks) const { return ticks * ns_per_tick * 1e-9; }
    [[nodiscard]] std::int64_t ns(double ticks) const { return std::llround(ticks * ns_per_tick); }
};

double fold_half_turn(double steps, double turn) {
    double folded = std::fmod(steps, turn);
    if (folded > turn / 2) folded -= turn;
    if (folded < -turn / 2) folded += turn;
    return folded;
}

}  // namespace

CrosshatchScan build_crosshatch_scan(const CrosshatchPlan& plan) {
    const Timeline timeline(plan);
    const double spu_deg = plan.rotation.steps_per_unit;
    CrosshatchScan scan;
    scan.stroke_mm = static_cast<double>(timeline.feed_steps) / plan.feed.steps_per_unit;
    const double advance = timeline.rotation_per_stroke();
    double position_steps = 0;  // head, continuous
    std::int64_t ticks = 0;
    std::int64_t index_steps_total = 0;
    for (int cycle = 0; cycle < plan.job.cycles; ++cycle) {
        for (bool down : {true, false}) {
            CrosshatchTrack track;
            track.cycle = cycle;
            track.down = down;
            track.start_s = timeline.seconds(static_cast<double>(ticks));
            track.end_s = timeline.seconds(static_cast<double>(ticks + timeline.stroke_ticks()));
            track.start_deg = position_steps / spu_deg;
            track.end_deg = (position_steps + advance) / spu_deg;
            track.start_z_mm = down ? 0.0 : -scan.stroke_mm;
            track.end_z_mm = down ? -scan.stroke_mm : 0.0;
            scan.tracks.push_back(track);
            position_steps += advance;
            ticks += timeline.stroke_ticks();
        }
        position_steps += static_cast<double>(timeline.index_steps[cycle]);
        ticks += timeline.index_ticks(cycle);
        index_steps_total += std::llabs(timeline.index_steps[cycle]);
    }
    scan.duration_s = timeline.seconds(static_cast<double>(ticks));
    scan.feed_steps = 2 * timeline.feed_steps * plan.job.cycles;
    // Only whole steps are issued: with free-running timers the phase the counter holds at the
    // end is not a step.
    const double stroke_steps = 2.0 * advance * plan.job.cycles;
    scan.rotation_steps = static_cast<std::int64_t>(std::floor(stroke_steps + 1e-9)) + index_steps_total;
    scan.closure_error_steps = std::abs(fold_half_turn(position_steps, plan.rotation_steps_per_turn));
    scan.drift_deg_per_stroke = (advance - plan.turns_per_stroke * plan.rotation_steps_per_turn) / spu_deg;

    // The angle the drawn helices make: axial travel against the wall's circumferential travel.
    const double circumference_mm = std::numbers::pi * plan.job.bore_diameter_mm;
    const double wall_mm = advance / plan.rotation_steps_per_turn * circumference_mm;
    scan.track_angle_deg = 2.0 * std::atan2(scan.stroke_mm, wall_mm) * 180.0 / std::numbers::pi;
    scan.track_angle_error_deg = scan.track_angle_deg - plan.crosshatch_angle_deg;
    // d(2·atan x) = 2 dx / (1 + x²) and dx/x = the two rates' relative errors at most.
    const double x = std::tan(plan.helix_angle_deg * std::numbers::pi / 180.0);
    const double relative = std::abs(plan.rotation.timer.speed_error) + std::abs(plan.feed.timer.speed_error);
    scan.timer_angle_error_bound_deg = 2.0 * x / (1.0 + x * x) * relative * 180.0 / std::numbers::pi;
    return scan;
}

void for_each_crosshatch_step(const CrosshatchPlan& plan,
                              const std::function<void(const StepEvent& step, std::uint8_t port)>& sink) {
    const Timeline timeline(plan);
    const PhaseTableKind table = plan.job.phase_table;
    drive::PhaseSequencer feed_phases(table, drive::seed_port_encoding);
    drive::PhaseSequencer rotation_phases(table, drive::seed_port_encoding);
    auto port_after = [&](drive::PhaseSequencer& phases, int direction) -> std::uint8_t {
        if (table == PhaseTableKind::none) return 0;
        return phases.step(direction > 0 ? drive::Direction::forward : drive::Direction::reverse);
    };
    auto emit = [&](std::uint8_t axis, double ticks, int direction) {
        StepEvent event;
        event.t_ns = timeline.ns(ticks);
        event.axis = axis;
        event.direction = static_cast<std::int8_t>(direction);
        drive::PhaseSequencer& phases = axis == crosshatch_feed_axis ? feed_phases : rotation_phases;
        sink(event, port_after(phases, direction));
    };

    const std::int64_t stroke = timeline.stroke_ticks();
    const auto d_f = timeline.feed_divisor;
    const auto d_r = static_cast<double>(timeline.rotation_divisor);
    const std::int64_t R = timeline.rotation_steps;
    double rotation_position = 0;  // free-running: steps of the counter, phase included
    std::int64_t start = 0;
    for (int cycle = 0; cycle < plan.job.cycles; ++cycle) {
        for (int direction : {-1, +1}) {
            // Merge the feed steps (k·d_f) with the rotation steps of this stroke.
            std::int64_t k = 1;
            std::int64_t j = 1;
            double next_free = 0;
            if (timeline.free_running) next_free = (std::floor(rotation_position) + 1.0 - rotation_position) * d_r;
            auto rotation_tick = [&](std::int64_t index) -> double {
                if (!timeline.free_running) {
                    return static_cast<double>((index * stroke + R / 2) / (R > 0 ? R : 1));
                }
                return next_free + static_cast<double>(index - 1) * d_r;
            };
            auto rotation_left = [&](std::int64_t index) {
                if (!timeline.free_running) return index <= R;
                return rotation_tick(index) <= static_cast<double>(stroke);
            };
            while (k <= timeline.feed_steps || rotation_left(j)) {
                const double feed_at = k <= timeline.feed_steps ? static_cast<double>(k * d_f) : HUGE_VAL;
                const double rotation_at = rotation_left(j) ? rotation_tick(j) : HUGE_VAL;
                if (feed_at <= rotation_at) {
                    emit(crosshatch_feed_axis, static_cast<double>(start) + feed_at, direction);
                    ++k;
                } else {
                    emit(crosshatch_rotation_axis, static_cast<double>(start) + rotation_at, +1);
                    ++j;
                }
            }
            if (timeline.free_running) rotation_position += static_cast<double>(stroke) / d_r;
            start += stroke;
        }
        const std::int64_t index_steps = timeline.index_steps[cycle];
        for (std::int64_t m = 1; m <= std::llabs(index_steps); ++m) {
            emit(crosshatch_rotation_axis, static_cast<double>(start + m * timeline.index_divisor),
                 index_steps < 0 ? -1 : +1);
        }
        start += timeline.index_ticks(cycle);
    }
}

}  // namespace nckit
