// The eccentric section as the X axis cuts it, and the highest spindle speed it can follow.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "eccentric_section.hpp"
#include "nckit/drive/servo_model.hpp"
#include "nckit/process/eccentric/eccentric.hpp"

namespace nckit {

namespace {

constexpr double two_pi = 2.0 * std::numbers::pi;
constexpr double following_limit_um = 1.0;

double rad_s(double rpm) {
    return rpm * two_pi / 60.0;
}
double rpm_of(double rad_per_s) {
    return rad_per_s * 60.0 / two_pi;
}

int updates_per_turn(const EccentricJob& job, const MachineConfig& machine) {
    if (job.updates_per_turn > 0) return job.updates_per_turn;
    return machine.spindle.encoder_counts > 0 ? machine.spindle.encoder_counts : 360;
}

//! The largest |da/dθ|, |d²a/dθ²|, |d³a/dθ³| over a turn (sampled densely; the cam is smooth
//! and its extremes are at or near 0° and 180°, which the grid contains).
EccentricCamPoint cam_extremes(const EccentricJob& job) {
    EccentricCamPoint peak;
    constexpr int samples = 36000;
    for (int i = 0; i < samples; ++i) {
        const EccentricCamPoint p = eccentric_cam(job, two_pi * i / samples);
        peak.d1_mm_rad = std::max(peak.d1_mm_rad, std::abs(p.d1_mm_rad));
        peak.d2_mm_rad2 = std::max(peak.d2_mm_rad2, std::abs(p.d2_mm_rad2));
        peak.d3_mm_rad3 = std::max(peak.d3_mm_rad3, std::abs(p.d3_mm_rad3));
    }
    return peak;
}

//! rpm at which `derivative`·ω^power reaches `limit` (infinite when the axis has no such limit).
double rpm_at_limit(double limit, double derivative, int power) {
    if (!(limit > 0) || derivative <= 0) return std::numeric_limits<double>::infinity();
    return rpm_of(std::pow(limit / derivative, 1.0 / power));
}

}  // namespace

SectionFit simulate_section(const EccentricJob& job, const MachineConfig& machine, double rpm, bool compensate) {
    const AxisConfig* x = machine.find(Axis::X);
    const int updates = updates_per_turn(job, machine);
    const double omega = rad_s(rpm);
    const double turn_s = 60.0 / rpm;
    const double tick_s = turn_s / updates;
    const double tick_rad = two_pi / updates;
    std::vector<std::array<double, 2>> points;
    points.reserve(static_cast<std::size_t>(updates));
    auto add_point = [&](double theta, double radius_mm) {
        const double nose_centre = radius_mm + job.nose_radius_mm;
        points.push_back({nose_centre * std::cos(theta), nose_centre * std::sin(theta)});
    };
    if (x == nullptr || !x->servo) {
        // An ideal axis is where the cam puts it at every update.
        for (int n = 0; n < updates; ++n) add_point(n * tick_rad, eccentric_cam(job, n * tick_rad).radius_mm);
        return eccentric_detail::fit_section(points, job);
    }
    const AxisServoConfig& servo = *x->servo;
    const auto truth =
        drive::ServoParameters::from_natural_frequency(servo.gain, servo.natural_frequency_hz, servo.damping);
    // The controller's model, off by model_error in frequency and damping. A position loop's DC
    // gain is its scale's: known exactly, so the model keeps it.
    const double m = 1.0 + job.model_error;
    const auto model =
        drive::ServoParameters::from_natural_frequency(servo.gain, servo.natural_frequency_hz * m, servo.damping * m);
    const double start = eccentric_cam(job, 0.0).radius_mm;
    drive::ServoModel axis(truth, tick_s, {start * servo.gain, 0.0});
    // Turns for the start to die away: eight time constants 1/(ζ ω_n), at least two turns.
    const double settle_s = 8.0 / (std::max(servo.damping, 0.05) * truth.natural_frequency_rad_s());
    const int warm_turns = std::clamp(static_cast<int>(std::ceil(settle_s / turn_s)), 2, 400);
    for (int turn = 0; turn <= warm_turns; ++turn) {
        for (int n = 0; n < updates; ++n) {
            const double theta = n * tick_rad;
            double command = eccentric_cam(job, theta).radius_mm;
            if (compensate) {
                // Model inversion u = (T² ä + 2ζT ȧ + a)/k, evaluated half an update ahead: the
                // held command then matches the continuous one on average over the update.
                const EccentricCamPoint p = eccentric_cam(job, theta + tick_rad / 2);
                const double t = model.time_constant_s;
                command =
                    (t * t * p.d2_mm_rad2 * omega * omega + 2 * model.damping * t * p.d1_mm_rad * omega + p.radius_mm) /
                    model.gain;
            }
            const drive::ServoState state = axis.step(command);
            if (turn == warm_turns) add_point(theta + tick_rad, state.position);
        }
    }
    return eccentric_detail::fit_section(points, job);
}

Result<EccentricReport> simulate_eccentric(const EccentricJob& job, const MachineConfig& machine) {
    const AxisConfig* x = machine.find(Axis::X);
    if (x == nullptr) {
        return error_at(job.radius_at, "eccentric-axis", "the machine has no X axis to slave to the spindle");
    }
    EccentricReport report;
    report.job = job;
    report.servo_axis = x->servo.has_value();
    report.updates_per_turn = updates_per_turn(job, machine);
    const EccentricCamPoint peak = cam_extremes(job);
    const double omega = rad_s(job.rpm);
    report.peak_velocity_mm_s = peak.d1_mm_rad * omega;
    report.peak_acceleration_mm_s2 = peak.d2_mm_rad2 * omega * omega;
    report.peak_jerk_mm_s3 = peak.d3_mm_rad3 * omega * omega * omega;
    report.x_max_diameter_mm = 2 * eccentric_cam(job, 0.0).radius_mm;
    report.x_min_diameter_mm = 2 * eccentric_cam(job, std::numbers::pi).radius_mm;
    report.turns = std::abs(job.z_end_mm - job.z_start_mm) / job.feed_mm_rev;
    report.cycle_time_s = report.turns * 60.0 / job.rpm;

    report.limits.velocity = rpm_at_limit(x->max_velocity, peak.d1_mm_rad, 1);
    report.limits.acceleration = rpm_at_limit(x->max_acceleration, peak.d2_mm_rad2, 2);
    report.limits.jerk = rpm_at_limit(x->max_jerk, peak.d3_mm_rad3, 3);
    const double kinematic = std::min({report.limits.velocity, report.limits.acceleration, report.limits.jerk});
    report.limits.following = std::numeric_limits<double>::infinity();
    if (report.servo_axis) {
        // Deviation from the drawing grows with speed: bisect for where it reaches 1 µm.
        auto follows = [&](double rpm) {
            return simulate_section(job, machine, rpm, true).max_deviation_um <= following_limit_um;
        };
        const double top = std::isfinite(kinematic) ? kinematic : 100000.0;
        if (follows(top)) {
            report.limits.following = top;
        } else {
            double low = 0;
            double high = top;
            for (int i = 0; i < 40 && high - low > 1e-3; ++i) {
                const double mid = 0.5 * (low + high);
                (follows(mid) ? low : high) = mid;
            }
            report.limits.following = low;
        }
    }
    report.max_rpm = kinematic;
    report.limited_by = report.limits.velocity == kinematic       ? "velocity"
                        : report.limits.acceleration == kinematic ? "acceleration"
                                                                  : "jerk";
    if (report.limits.following < report.max_rpm) {
        report.max_rpm = report.limits.following;
        report.limited_by = "following";
    }
    if (job.rpm > kinematic) {
        return error_at(
            job.rpm_at, "eccentric-too-fast",
            fmt::format("at {} rpm the X axis would need {:.6g} mm/s, {:.6g} mm/s² and {:.6g} mm/s³ "
                        "(it has {}, {} and {}): it can follow up to {:.4g} rpm",
                        job.rpm, report.peak_velocity_mm_s, report.peak_acceleration_mm_s2, report.peak_jerk_mm_s3,
                        x->max_velocity, x->max_acceleration, x->max_jerk, kinematic));
    }
    if (job.rpm > report.limits.following) {
        return error_at(job.rpm_at, "eccentric-too-fast",
                        fmt::format("at {} rpm the X servo does not follow the cam within {} um: the highest "
                                    "speed within {} um is {:.4g} rpm",
                                    job.rpm, following_limit_um, following_limit_um, report.limits.following));
    }
    report.compensated = simulate_section(job, machine, job.rpm, true);
    report.uncompensated = simulate_section(job, machine, job.rpm, false);
    return report;
}

}  // namespace nckit
