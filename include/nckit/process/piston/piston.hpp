#pragma once
// Oval piston turning on a fast tool servo: a piston job (nckit/process/piston/piston_job.hpp) cut in the
// fast tool servo simulation (fast_tool_servo.hpp). The drawing r(θ, Z), tabulated as the cam
// engine (CamTable), is what the controller evaluates at every encoder count; the fast axis cuts
// the radius about a reference that moves with Z only (the slide's share of the cut), the middle
// of the turn's radial range, so its stroke is used symmetrically.
//
// Job → simulation: [servo] natural_frequency_hz, damping, model_error, dac_bits and stroke_mm;
// [piston] rpm, encoder_counts, feed_mm_rev, Z from the first station to the last. The spindle
// ripple is [piston] spindle_ripple when the job gives it (0 means a perfectly steady spindle);
// a job that leaves it out gets the simulation's default (SpindleRipple: ±0.2 % once per turn),
// because a real spindle drive always leaves some, and a figure without it would flatter.
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

#include "nckit/cam/natural_spline.hpp"
#include "nckit/process/piston/piston_job.hpp"
#include "nckit/core/result.hpp"
#include "nckit/core/source_location.hpp"
#include "nckit/process/fts/fast_tool_servo.hpp"
#include "nckit/process/fts/stroke_reference.hpp"

namespace nckit {

//! The largest |r − reference| over the turned surface: what the fast axis must travel.
struct StrokeFit {
    double peak_displacement_mm = 0;  //!< mm, largest |r(θ, z) − reference(z)|
    double theta_deg = 0;             //!< deg, where it is
    double z_mm = 0;                  //!< mm
    double limit_mm = 0;              //!< mm, what the DAC reaches: stroke / 2 − one code
};

//! What the run needs beyond the job.
struct PistonRunOptions {
    int trace_turns = 3;           //!< last turns of the learning run kept as a trace (0: none)
    int air_turns = 20;            //!< turns before the tool engages (FtsParameters::air_turns)
    double settle_limit_um = 1.0;  //!< µm, the per-turn peak to valley "settled" means
};

//! The piston cut three ways, and what it took.
struct PistonSimulation {
    FtsParameters parameters;             //!< what the simulation ran with
    FtsSimulation fts;                    //!< the three runs, the trace
    std::size_t table_theta_cells = 0;    //!< cam table cells around the turn
    std::size_t table_z_cells = 0;        //!< cam table cells along Z
    std::size_t table_bytes = 0;          //!< bytes of patch coefficients
    double table_error_bound_mm = 0;      //!< mm, the cam engine's stated bound (CamTable)
    double table_tolerance_mm = 0;        //!< mm, the bound it was built to
    StrokeFit fit;                        //!< the displacement against the stroke
    double acceleration_mm_s2 = 0;        //!< mm/s², the profile's peak radial acceleration at rpm
    double acceleration_limit_mm_s2 = 0;  //!< mm/s², the job's max_acceleration_g
    double max_rpm = 0;                   //!< rpm where the acceleration reaches the limit
    //! Turn (0 = the first air turn) from which every turn of the learning run stays within
    //! settle_limit_um; -1 when it never does.
    int settled_turn = -1;
};

//! The simulation's parameters for `job` (see the file note for the mapping). The learned
//! harmonics are capped below half the encoder counts, so a coarse encoder still learns.
[[nodiscard]] FtsParameters piston_fts_parameters(const cam::PistonJob& job, const PistonRunOptions& options = {});

//! Builds the cam engine and the stroke reference, checks the displacement fits the DAC's range
//! ("piston-stroke", at stroke_mm) and the encoder gives the controller enough counts
//! ("piston-encoder"), then runs simulate_fast_tool_servo; its diagnostics point at [servo].
[[nodiscard]] Result<PistonSimulation> simulate_piston(const cam::PistonJob& job, const PistonRunOptions& options = {});

}  // namespace nckit
