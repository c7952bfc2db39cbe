// The piston job through the fast tool servo simulation: the cam engine as the controller's
// profile, the stroke reference as the slide's path, and the checks that the job's servo can be
// commanded at all before three runs of it are timed out.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "nckit/process/piston/piston.hpp"

namespace nckit {

namespace {

//! The learned harmonics of FtsLearning unless the encoder has too few counts for them.
constexpr int default_harmonics = FtsLearning{}.harmonics;

//! The largest |table − reference| at the reference's points and half-way between them.
StrokeFit fit_stroke(const cam::CamTable& table, const StrokeReference& reference, double limit_mm) {
    StrokeFit fit;
    fit.limit_mm = limit_mm;
    const std::size_t points = 2 * stroke_reference_points(table) - 1;
    const std::size_t count = 1440;
    std::vector<double> turn;
    for (std::size_t i = 0; i < points; ++i) {
        const double f = static_cast<double>(i) / static_cast<double>(points - 1);
        const double z = table.z_from_mm() + f * (table.z_to_mm() - table.z_from_mm());
        sample_turn(table, z, count, turn);
        const double centre = reference.radius_mm(z);
        for (std::size_t k = 0; k < count; ++k) {
            const double d = std::abs(turn[k] - centre);
            if (d > fit.peak_displacement_mm) {
                fit.peak_displacement_mm = d;
                fit.theta_deg = 360.0 * static_cast<double>(k) / static_cast<double>(count);
                fit.z_mm = z;
            }
        }
    }
    return fit;
}

}  // namespace

FtsParameters piston_fts_parameters(const cam::PistonJob& job, const PistonRunOptions& options) {
    FtsParameters p;
    p.servo.natural_frequency_hz = job.servo.natural_frequency_hz;
    p.servo.damping = job.servo.damping;
    p.servo.model_error = job.servo.model_error;
    p.servo.dac_bits = job.servo.dac_bits;
    p.servo.stroke_mm = job.servo.stroke_mm;
    p.rpm = job.rpm;
    p.encoder_counts = static_cast<int>(job.encoder_counts);  // the job reader caps it at 10^7
    if (job.source.ripple_given) p.ripple.fraction = job.spindle_ripple;
    p.feed_mm_rev = job.feed_mm_rev;
    p.z_start_mm = job.z_mm.front();
    p.z_end_mm = job.z_mm.back();
    p.air_turns = options.air_turns;
    p.learning.harmonics = std::min(default_harmonics, std::max(0, (p.encoder_counts - 1) / 2));
    p.trace_turns = options.trace_turns;
    p.where = job.source.servo;
    return p;
}

Result<PistonSimulation> simulate_piston(const cam::PistonJob& job, const PistonRunOptions& options) {
    PistonSimulation out;
    out.parameters = piston_fts_parameters(job, options);
    const FtsParameters& p = out.parameters;
    // The controller's preview and its learning's phase lead span a few counts; below 8 a turn
    // has no shape left to follow.
    if (job.encoder_counts < 8) {
        return error_at(
            job.source.encoder_counts, "piston-encoder",
            fmt::format("the fast tool servo needs at least 8 encoder counts per turn, not {}", job.encoder_counts));
    }

    const cam::CamTable table = cam::build_cam_table(job);
    out.table_theta_cells = table.theta_cells();
    out.table_z_cells = table.z_cells();
    out.table_bytes = table.memory_bytes();
    out.table_error_bound_mm = table.error_bound_mm();
    out.table_tolerance_mm = table.tolerance_mm();

    const StrokeReference reference(table, stroke_reference_points(table));
    const Dac dac{p.servo.dac_bits, p.servo.stroke_mm};
    out.fit = fit_stroke(table, reference, 0.5 * p.servo.stroke_mm - dac.step_mm());
    if (out.fit.peak_displacement_mm > out.fit.limit_mm) {
        return error_at(job.source.stroke, "piston-stroke",
                        fmt::format("the profile swings {:.6f} mm from the middle of its radial range (theta {} deg, "
                                    "Z {:.4f} mm), beyond the {:.6f} mm half a stroke of {} mm reaches",
                                    out.fit.peak_displacement_mm, out.fit.theta_deg, out.fit.z_mm, out.fit.limit_mm,
                                    p.servo.stroke_mm));
    }
    out.acceleration_mm_s2 = job.demand.acceleration_mm_s2(job.rpm);
    out.acceleration_limit_mm_s2 = job.servo.max_acceleration_mm_s2();
    out.max_rpm = job.demand.max_rpm(out.acceleration_limit_mm_s2);

    // The controller reads the cam engine, never the drawing's formulas: what runs on a machine.
    const FtsProfile profile = [&](double theta_deg, double z_mm) {
        const double r = table(theta_deg, z_mm);
        return FtsDemand{r, r - reference.radius_mm(z_mm)};
    };
    Result<FtsSimulation> fts = simulate_fast_tool_servo(p, profile);
    if (!fts) return fts.diagnostics();
    out.fts = std::move(fts).value();
    out.settled_turn = settled_turn(out.fts.learning.turn_pv_um, options.settle_limit_um);
    return out;
}

}  // namespace nckit
