#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <string>

#include <fmt/format.h>

#include "nckit/drive/variable_period_servo.hpp"
#include "nckit/process/fts/fast_tool_servo.hpp"

namespace nckit {

namespace {

enum class Compensation { none, feedforward, learning };

const char* run_name(Compensation c) {
    switch (c) {
        case Compensation::none:
            return "uncompensated";
        case Compensation::feedforward:
            return "feedforward";
        case Compensation::learning:
            return "learning";
    }
    return "";
}

//! The tick numbering every run shares: air turns from tick 0, the cut from air_ticks to last.
struct TimeLine {
    int counts = 0;
    std::int64_t air_ticks = 0;
    std::int64_t last_tick = 0;
    double z_start_mm = 0, z_end_mm = 0, feed_mm_rev = 0;

    [[nodiscard]] int count(std::int64_t tick) const {
        const std::int64_t c = tick % counts;
        return static_cast<int>(c < 0 ? c + counts : c);
    }
    [[nodiscard]] double z_mm(std::int64_t tick) const {
        if (tick <= air_ticks) return z_start_mm;
        const double z = z_start_mm + feed_mm_rev * static_cast<double>(tick - air_ticks) / counts;
        return std::min(z, z_end_mm);
    }
};

TimeLine make_time_line(const FtsParameters& p) {
    TimeLine line;
    line.counts = p.encoder_counts;
    line.air_ticks = static_cast<std::int64_t>(p.air_turns) * p.encoder_counts;
    // The last tick is the first at or past z_end (to a part in 1e9: 50 / 0.1 is 500 turns, not 501).
    const double cut = (p.z_end_mm - p.z_start_mm) / p.feed_mm_rev * p.encoder_counts;
    line.last_tick = line.air_ticks + static_cast<std::int64_t>(std::ceil(cut * (1.0 - 1e-9)));
    line.z_start_mm = p.z_start_mm;
    line.z_end_mm = p.z_end_mm;
    line.feed_mm_rev = p.feed_mm_rev;
    return line;
}

//! Everything the runs share, built once.
struct Setup {
    const FtsParameters& parameters;
    const FtsProfile& profile;
    TimeLine line;
    SpindleClock clock;
    drive::ServoParameters plant;  //!< the true axis
    Dac dac;
    ZpetcFeedforward feedforward;     //!< from the controller's model
    double learning_contraction = 0;  //!< sup |Q (1 - gain G Z)| for the true axis
};

struct RunOutput {
    FtsRunResult result;
    std::vector<FtsTraceRow> trace;
    double duration_s = 0.0;  //!< simulated time, s
};

//! The profile's demands at ticks n-1 .. n+2, slid along as the run advances.
class DemandWindow {
public:
    explicit DemandWindow(const Setup& setup) : setup_(setup) {
        for (std::int64_t i = 0; i < 4; ++i) fill(static_cast<std::size_t>(i), i - 1);
    }
    void advance(std::int64_t tick) {  // now centred on `tick`
        std::rotate(demand_.begin(), demand_.begin() + 1, demand_.end());
        std::rotate(displacement_.begin(), displacement_.begin() + 1, displacement_.end());
        fill(3, tick + 2);
    }
    [[nodiscard]] const FtsDemand& now() const { return demand_[1]; }
    [[nodiscard]] std::span<const double, 4> displacements() const { return displacement_; }
    //! The first demand that was not finite, as an error.
    [[nodiscard]] const std::optional<Diagnostic>& error() const { return error_; }

private:
    void fill(std::size_t slot, std::int64_t tick) {
        const double theta = setup_.clock.angle_deg(setup_.line.count(tick));
        const double z = setup_.line.z_mm(tick);
        demand_[slot] = setup_.profile(theta, z);
        displacement_[slot] = demand_[slot].displacement_mm;
        if (!error_ && !(std::isfinite(demand_[slot].displacement_mm) && std::isfinite(demand_[slot].radius_mm))) {
            error_ =
                error_at(setup_.parameters.where, "fts-profile",
                         fmt::format("the profile gives no finite displacement at theta {} deg, z {} mm", theta, z));
        }
    }
    const Setup& setup_;
    std::array<FtsDemand, 4> demand_{};
    std::array<double, 4> displacement_{};
    std::optional<Diagnostic> error_;
};

Result<RunOutput> run(const Setup& setup, Compensation compensation) {
    const FtsParameters& p = setup.parameters;
    const TimeLine& line = setup.line;
    drive::VariablePeriodServo plant(setup.plant);
    std::optional<RepetitiveLearning> learning;
    if (compensation == Compensation::learning) {
        // The first turn is not learned from: its error is the servo's start from rest, which
        // never repeats.
        learning.emplace(setup.feedforward, line.counts, p.learning, line.counts);
    }
    const std::int64_t trace_first =
        compensation == Compensation::learning && p.trace_turns > 0
            ? std::max<std::int64_t>(0, line.last_tick - std::int64_t{p.trace_turns} * line.counts)
            : line.last_tick + 1;

    RunOutput out;
    // Turns the spindle makes from tick 0 to the last tick; that tick closes the last turn.
    const auto turns = static_cast<std::size_t>((line.last_tick + line.counts - 1) / line.counts);
    std::vector<double> turn_low(turns, std::numeric_limits<double>::infinity());
    std::vector<double> turn_high(turns, -std::numeric_limits<double>::infinity());
    double low = std::numeric_limits<double>::infinity();
    double high = -low;
    double sum_squares = 0.0;
    DemandWindow window(setup);
    double t_s = 0.0;

    for (std::int64_t n = 0;; ++n) {
        if (window.error()) return *window.error();
        const int count = line.count(n);
        const drive::ServoState y = plant.state();
        const FtsDemand& demand = window.now();
        const double error = y.position - demand.displacement_mm;
        const auto turn = std::min(static_cast<std::size_t>(n / line.counts), turns - 1);
        turn_low[turn] = std::min(turn_low[turn], error);
        turn_high[turn] = std::max(turn_high[turn], error);
        if (n >= line.air_ticks) {
            low = std::min(low, error);
            high = std::max(high, error);
            sum_squares += error * error;
        }

        double wanted = demand.displacement_mm;
        if (compensation != Compensation::none) wanted = setup.feedforward.command(window.displacements());
        if (learning) wanted += learning->next(error);
        const Dac::Output command = setup.dac.convert(wanted);
        if (command.clamped) {
            // A learning that cannot converge with this model error ends here too: say so.
            const std::string why =
                learning && setup.learning_contraction >= 1.0
                    ? fmt::format(" (the learning diverges: |Q (1 - gain G Z)| reaches {:.2f} with this model error)",
                                  setup.learning_contraction)
                    : std::string{};
            return error_at(p.where, "fts-stroke",
                            fmt::format("the {} run wants {:.6f} mm at t {:.6f} s (theta {} deg, z {:.4f} mm), "
                                        "beyond the DAC's stroke of {} mm{}",
                                        run_name(compensation), wanted, t_s, setup.clock.angle_deg(count), line.z_mm(n),
                                        p.servo.stroke_mm, why));
        }
        out.result.peak_command_mm = std::max(out.result.peak_command_mm, std::abs(command.command_mm));
        if (n >= trace_first) {
            out.trace.push_back({t_s, setup.clock.angle_deg(count), line.z_mm(n), demand.radius_mm,
                                 demand.displacement_mm, command.command_mm, y.position, y.velocity});
        }
        if (n == line.last_tick) break;

        const double h = setup.clock.tick_period_s(count, t_s);
        plant.step(command.command_mm, h);
        t_s += h;
        window.advance(n + 1);
    }

    out.duration_s = t_s;
    const double cut_ticks = static_cast<double>(line.last_tick - line.air_ticks + 1);
    out.result.pv_um = (high - low) * 1e3;
    out.result.rms_um = std::sqrt(sum_squares / cut_ticks) * 1e3;
    out.result.turn_pv_um.resize(turns);
    for (std::size_t k = 0; k < turns; ++k) out.result.turn_pv_um[k] = (turn_high[k] - turn_low[k]) * 1e3;
    return out;
}

drive::ServoParameters controller_model(const FtsServo& s) {
    const double scale = 1.0 + s.model_error;
    return drive::ServoParameters::from_natural_frequency(scale, s.natural_frequency_hz * scale, s.damping * scale);
}

}  // namespace

Result<FtsSimulation> simulate_fast_tool_servo(const FtsParameters& p, const FtsProfile& profile) {
    if (Diagnostics problems = check_fts_parameters(p); !problems.empty()) return problems;
    const drive::ServoParameters plant =
        drive::ServoParameters::from_natural_frequency(1.0, p.servo.natural_frequency_hz, p.servo.damping);
    const drive::ServoParameters model = controller_model(p.servo);
    const SpindleClock clock(p.rpm, p.encoder_counts, p.ripple);
    const ZpetcFeedforward feedforward(model, clock.nominal_period_s());
    const RepetitiveLearning::Contraction contraction =
        RepetitiveLearning(feedforward, p.encoder_counts, p.learning, 0)
            .contraction(drive::discretise(plant, clock.nominal_period_s()));
    const Setup setup{p,
                      profile,
                      make_time_line(p),
                      clock,
                      plant,
                      Dac{p.servo.dac_bits, p.servo.stroke_mm},
                      feedforward,
                      contraction.any_frequency};

    FtsSimulation out;
    std::array<FtsRunResult*, 3> results{&out.uncompensated, &out.feedforward, &out.learning};
    const std::array<Compensation, 3> order{Compensation::none, Compensation::feedforward, Compensation::learning};
    for (std::size_t i = 0; i < order.size(); ++i) {
        Result<RunOutput> done = run(setup, order[i]);
        if (!done) return done.diagnostics();
        *results[i] = std::move(done->result);
        if (order[i] == Compensation::learning) out.trace = std::move(done->trace);
        out.duration_s = done->duration_s;  // the same in every run: one spindle, one time line
    }
    out.tick_rate_hz = 1.0 / clock.nominal_period_s();
    out.dac_step_mm = setup.dac.step_mm();
    out.ticks = setup.line.last_tick + 1;
    out.cut_ticks = setup.line.last_tick - setup.line.air_ticks + 1;
    out.learning_contraction = contraction;
    out.zpetc_zero_ratio = setup.feedforward.zero_ratio();
    return out;
}

}  // namespace nckit
