#pragma once
// A piston turning job: the drawing (D(Z), E(Z), section shape at Z stations) and the fast
// tool servo that cuts the oval, read from TOML with a FILE:LINE:COL diagnostic for each
// problem. The `nckit piston` verb is: load_piston_job → build_cam_table → write_cam_table_csv.
//
// [piston]
// rpm = 2500                        # spindle speed, rpm (0 < rpm <= 100000)
// z_mm = [0.0, 10.0, ...]           # stations from the crown, mm, strictly increasing, >= 2
// major_diameter_mm = [89.80, ...]  # D(Z), mm: numbers at the stations (natural cubic spline,
//                                   #   straight beyond the ends), a formula in Z, or a number
// ovality_mm = [0.40, ...]          # E(Z) = D − d, mm, 0 <= E < D; the same three forms
// shape = "ellipse2"                # ellipse2 | ellipse4 | ellipse, or instead:
// shape_formula = "..."             # the radial drop from D/2, mm, in Z, PHI (deg), D, E
// e4_mm = [...]                     # E4(Z), mm, the 4th-harmonic term (shape ellipse4 only)
// feed_mm_rev = 0.1                 # optional: Z feed per spindle turn, mm (0 < f <= 10)
// encoder_counts = 360              # optional: servo updates per turn (1 ..= 10,000,000)
// spindle_ripple = 0.0              # optional: spindle speed ripple, fraction of rpm, peak
//                                   #   (0 ..= 0.5)
// [[piston.segment]]                # optional, repeatable: formulas on Z intervals
// z_from_mm = 0.0                   #   mm; intervals of one function must cover the stations
// z_to_mm = 20.0                    #   end to end with no gap or overlap
// major_diameter_mm = "89.8 + 0.004*Z"   # any of major_diameter_mm, ovality_mm, e4_mm
// [servo]
// natural_frequency_hz = 135.0      # Hz, of k / (T²s² + 2ζTs + 1), 0 < f <= 100000
// damping = 0.3                     # ζ, 0 ..= 100
// dac_bits = 16                     # optional (16): DAC resolution over the stroke, 1 ..= 32
// stroke_mm = 1.0                   # mm, the fast axis's full travel, 0 < s <= 100
// model_error = 0.10                # optional (0): the controller's model off by this fraction
//                                   #   in gain, frequency and damping, 0 ..= 0.9
// max_acceleration_g = 13.0         # optional (13): the axis's acceleration limit, g
//
// Formulas are muparser expressions (see formula.hpp); Z in mm, PHI in degrees.
#include <cstdint>
#include <filesystem>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "nckit/cam/cam_table.hpp"
#include "nckit/cam/piston_profile.hpp"
#include "nckit/cam/profile_demand.hpp"
#include "nckit/core/result.hpp"
#include "nckit/core/source_location.hpp"

namespace nckit::cam {

//! mm/s² per g (standard gravity).
inline constexpr double standard_gravity_mm_s2 = 9806.65;

//! The fast tool servo as the job's [servo] gives it.
struct FastServoSpec {
    double natural_frequency_hz = 0;  //!< Hz, f_n = 1 / (2π T)
    double damping = 0;               //!< ζ, dimensionless
    int dac_bits = 16;                //!< DAC resolution over stroke_mm, bits
    double stroke_mm = 0;             //!< mm, full travel of the fast axis
    double model_error = 0;           //!< fraction the controller's model is off (gain, f_n, ζ)
    double max_acceleration_g = 13;   //!< g, the axis's acceleration limit

    [[nodiscard]] double max_acceleration_mm_s2() const { return max_acceleration_g * standard_gravity_mm_s2; }
};

//! Where in the job file later checks (the simulation's) point, and what the file leaves unsaid.
struct PistonJobSource {
    SourceLocation servo;           //!< the [servo] table
    SourceLocation stroke;          //!< [servo] stroke_mm, or the [servo] table
    SourceLocation encoder_counts;  //!< [piston] encoder_counts, or the [piston] table
    bool ripple_given = false;      //!< whether [piston] sets spindle_ripple
};

//! A checked piston job: every value in range, every formula compiled, the profile within
//! the servo's stroke and acceleration at the job's rpm.
struct PistonJob {
    double rpm = 0;            //!< spindle speed, rpm
    std::vector<double> z_mm;  //!< stations from the crown, mm, strictly increasing
    //! mm: the stations and the ends of formula intervals between them, sorted: where the
    //! drawing may bend, so where a cam table puts nodes.
    std::vector<double> z_breaks_mm;
    PistonProfile profile;              //!< r(θ, Z) as drawn
    double feed_mm_rev = 0.1;           //!< mm of Z per spindle turn
    std::int64_t encoder_counts = 360;  //!< servo updates per spindle turn
    double spindle_ripple = 0;          //!< spindle speed ripple, fraction of rpm, peak
    FastServoSpec servo;
    ProfileDemand demand;    //!< what the profile asks of the servo over the stations
    PistonJobSource source;  //!< where it stands in its file
};

//! Reads a job from TOML text; `file_name` goes into the diagnostics.
[[nodiscard]] Result<PistonJob> parse_piston_job(std::string_view toml_text, const std::string& file_name);
//! Reads a job file.
[[nodiscard]] Result<PistonJob> load_piston_job(const std::filesystem::path& path);

//! The job's cam engine: r(θ, Z) over its stations, to `tolerance_mm` (see CamTable).
[[nodiscard]] CamTable build_cam_table(const PistonJob& job, double tolerance_mm = 1e-6);

//! `z_mm,phi_deg,radius_mm` of the drawn profile at the job's stations, 0..359° (see
//! cam_table_csv.hpp for the format).
void write_cam_table_csv(std::ostream& out, const PistonJob& job);

}  // namespace nckit::cam
