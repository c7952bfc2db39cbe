#pragma once
// Eccentric shaft turning by electronic cam (docs/processes/eccentric.md): instead of a macro of
// short G1 blocks, the X axis is slaved to the spindle angle θ and follows
//   a(θ) = e·cos θ + sqrt((r + Rn)² − e²·sin² θ) − Rn      (radius; X = 2a in diameter terms)
// at every encoder count, so the eccentric cylinder of radius r about C = (e, 0) comes out
// whatever the spindle speed, within what the X axis can do.
#include <filesystem>
#include <optional>
#include <string>

#include "nckit/core/machine.hpp"
#include "nckit/core/result.hpp"
#include "nckit/core/source_location.hpp"

namespace nckit {

//! The job file's [eccentric] table.
struct EccentricJob {
    double blank_diameter_mm = 0;
    double eccentricity_mm = 0;      //!< e: distance of the eccentric's centre from the spindle axis
    double eccentric_radius_mm = 0;  //!< r
    double z_start_mm = 0;
    double z_end_mm = 0;
    double rpm = 0;             //!< spindle speed of the turning pass
    double feed_mm_rev = 0;     //!< along Z
    double nose_radius_mm = 0;  //!< Rn: the tool nose, compensated exactly
    int updates_per_turn = 0;   //!< cam updates per turn (0: the machine's encoder counts)
    double model_error = 0;     //!< the controller's X servo model off by this fraction in frequency and damping
    SourceLocation rpm_at;      //!< where speed problems point
    SourceLocation radius_at;   //!< where geometry problems point
    SourceLocation feed_at;     //!< where length problems point (the program's size)
};

[[nodiscard]] Result<EccentricJob> load_eccentric_job(const std::filesystem::path& path);
[[nodiscard]] Result<EccentricJob> parse_eccentric_job(std::string_view toml_text, const std::string& file_name);

//! The cam a(θ) and its derivatives w.r.t. θ (rad), exact.
struct EccentricCamPoint {
    double radius_mm = 0;   //!< a
    double d1_mm_rad = 0;   //!< da/dθ
    double d2_mm_rad2 = 0;  //!< d²a/dθ²
    double d3_mm_rad3 = 0;  //!< d³a/dθ³
};
[[nodiscard]] EccentricCamPoint eccentric_cam(const EccentricJob& job, double theta_rad);

//! A section as cut: least-squares circle through the tool's path relative to the part.
struct SectionFit {
    double roundness_um = 0;      //!< max − min distance of the cut points from the fitted centre
    double center_offset_um = 0;  //!< |fitted centre − drawing centre (e, 0)|
    double radius_error_um = 0;   //!< fitted radius − r
    double max_deviation_um = 0;  //!< largest |radial error| against the drawing's circle
};

//! Which machine limit sets the highest spindle speed.
struct RpmLimits {
    double velocity = 0;  //!< rpm at which |ȧ| reaches the X axis's max_velocity
    double acceleration = 0;
    double jerk = 0;
    double following = 0;  //!< rpm up to which the servo keeps the section within 1 µm (inf: ideal axis)
};

struct EccentricReport {
    EccentricJob job;
    SectionFit compensated;    //!< feedforward from the known cam (model inversion)
    SectionFit uncompensated;  //!< the cam written straight to the servo
    bool servo_axis = false;   //!< X has a servo model ([axis.servo]); otherwise it follows ideally
    RpmLimits limits;
    double max_rpm = 0;             //!< the lowest of the limits
    std::string limited_by;         //!< "velocity", "acceleration", "jerk" or "following"
    double peak_velocity_mm_s = 0;  //!< of X (radius) at the job's rpm
    double peak_acceleration_mm_s2 = 0;
    double peak_jerk_mm_s3 = 0;
    double x_min_diameter_mm = 0;  //!< 2·a(180°)
    double x_max_diameter_mm = 0;  //!< 2·a(0)
    int updates_per_turn = 0;
    double turns = 0;         //!< of the pass: |z_end − z_start| / feed
    double cycle_time_s = 0;  //!< of the pass at the job's rpm
};

//! Simulates the section at the job's rpm with and without compensation and finds the highest
//! rpm. Errors (at the job's keys): an X axis missing from the machine, or a job rpm above the
//! highest the X axis can follow (the message gives it).
[[nodiscard]] Result<EccentricReport> simulate_eccentric(const EccentricJob& job, const MachineConfig& machine);

//! One section at `rpm`: the X servo (or an ideal axis) driven at every update, after enough
//! turns for the start to die away. `compensate` adds model-inversion feedforward.
[[nodiscard]] SectionFit simulate_section(const EccentricJob& job, const MachineConfig& machine, double rpm,
                                          bool compensate);

}  // namespace nckit
