#pragma once
// Oval piston turning with a fast tool servo (docs/processes/piston.md), simulated: the voice-coil
// axis is the drive layer's exact second-order model, commanded through a DAC once per spindle
// encoder count while the spindle's speed ripples. Three runs on the same conditions show what
// each compensation buys: none (the wanted displacement written straight to the DAC), model-
// inverse feedforward with preview, and feedforward plus learning across revolutions. The
// controller's model is off by `model_error`; only the true axis makes the measured errors.
//
// Time line of every run: the spindle turns `air_turns` at the first station with the tool clear
// of the part, the servo already following the profile (so learning has converged before the
// tool engages), then feeds along z at `feed_mm_rev` from z_start to z_end: the turned surface,
// over which errors are measured.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "nckit/core/result.hpp"
#include "nckit/core/source_location.hpp"
#include "nckit/process/fts/fts_controller.hpp"
#include "nckit/process/fts/fts_spindle.hpp"

namespace nckit {

//! The job's [servo] section.
struct FtsServo {
    double natural_frequency_hz = 135.0;  //!< Hz, the true axis's f_n (its gain is 1)
    double damping = 0.3;                 //!< zeta of the true axis
    //! The controller's model has gain, natural frequency and damping all (1 + model_error)
    //! times the true ones: positive overrates the axis, negative underrates it.
    double model_error = 0.10;
    int dac_bits = 16;       //!< DAC resolution
    double stroke_mm = 1.0;  //!< mm, the DAC's full scale; mid-stroke is displacement 0
};

struct FtsParameters {
    FtsServo servo;
    double rpm = 2500.0;       //!< nominal spindle speed
    int encoder_counts = 360;  //!< per turn; the controller updates at every one (15 kHz here)
    SpindleRipple ripple;      //!< spindle speed ripple
    double feed_mm_rev = 0.1;  //!< mm per turn along z while cutting
    double z_start_mm = 0.0;   //!< mm, first station: the cut starts here
    double z_end_mm = 50.0;    //!< mm, the cut ends here
    int air_turns = 20;        //!< turns at z_start before the tool engages
    FtsLearning learning;      //!< learning across revolutions
    int trace_turns = 3;       //!< last turns of the learning run kept as a trace (0: none)
    SourceLocation where;      //!< the job's [servo] section, for diagnostics
};

//! What the profile wants at one point of the surface.
struct FtsDemand {
    double radius_mm = 0.0;        //!< profile radius there, mm (for the trace)
    double displacement_mm = 0.0;  //!< fast-axis displacement from mid-stroke that cuts it, mm
};
//! The drawing: (angle from the major axis in deg, z in mm) -> demand. Called in tick order,
//! a few ticks ahead of the servo (the feedforward's preview).
using FtsProfile = std::function<FtsDemand(double theta_deg, double z_mm)>;

//! One run's errors, actual - wanted fast-axis position at every tick.
struct FtsRunResult {
    double pv_um = 0.0;            //!< µm, peak to valley over the turned surface
    double rms_um = 0.0;           //!< µm, RMS over the turned surface
    double peak_command_mm = 0.0;  //!< mm, largest |command| sent (after the DAC), air turns included
    //! µm, peak to valley within each turn from the first air turn on (the final tick, where the
    //! cut ends, closes the last turn).
    std::vector<double> turn_pv_um;
};

//! One control tick of the trace. Row n's command is held from t_s to the next row's t_s; the
//! true servo (the job's values, gain 1) started from the first row's actual_mm and actual_mm_s
//! and fed these commands reproduces every later row's actual_mm.
struct FtsTraceRow {
    double t_s = 0.0;          //!< s since the spindle started (the first air turn)
    double theta_deg = 0.0;    //!< angle from the major axis
    double z_mm = 0.0;         //!< tool position along the piston
    double radius_mm = 0.0;    //!< profile radius wanted here
    double target_mm = 0.0;    //!< fast-axis displacement the profile needs
    double command_mm = 0.0;   //!< what the controller sends, after the DAC
    double actual_mm = 0.0;    //!< the true servo's position
    double actual_mm_s = 0.0;  //!< the true servo's velocity
};

struct FtsSimulation {
    FtsRunResult uncompensated;  //!< command = wanted displacement
    FtsRunResult feedforward;    //!< ZPETC of the controller's model
    FtsRunResult learning;       //!< feedforward + learning across revolutions
    //! Last trace_turns turns of the learning run, one row per tick, ending at the last tick.
    std::vector<FtsTraceRow> trace;
    double tick_rate_hz = 0.0;                             //!< nominal control rate: encoder counts per second
    double dac_step_mm = 0.0;                              //!< one DAC code, mm
    std::int64_t ticks = 0;                                //!< ticks per run, air turns included
    std::int64_t cut_ticks = 0;                            //!< ticks on the turned surface
    double duration_s = 0.0;                               //!< simulated time of one run
    RepetitiveLearning::Contraction learning_contraction;  //!< for the true axis (< 1 converges)
    double zpetc_zero_ratio = 0;                           //!< beta: the controller model's sampling zero is at -beta
};

//! The job's values checked: every problem, each at `parameters.where`, code "fts-parameter".
[[nodiscard]] Diagnostics check_fts_parameters(const FtsParameters& parameters);

//! Runs the three simulations. Errors: the checks above; a demand that is not finite
//! ("fts-profile"); a command beyond the DAC's stroke in any run ("fts-stroke": the job asks
//! more of the axis than it has).
[[nodiscard]] Result<FtsSimulation> simulate_fast_tool_servo(const FtsParameters& parameters,
                                                             const FtsProfile& profile);

//! The first turn from which every later turn's peak to valley stays <= limit_um, or -1.
[[nodiscard]] int settled_turn(const std::vector<double>& turn_pv_um, double limit_um);

//! CSV with the header `t_s,theta_deg,z_mm,radius_mm,target_mm,command_mm,actual_mm,actual_mm_s`:
//! t_s and every mm column to 1e-12 (a re-simulation from the text matches to ~1e-10 mm),
//! angles to 1e-9 deg, velocity to 1e-9 mm/s.
[[nodiscard]] std::string format_fts_trace_csv(const std::vector<FtsTraceRow>& rows);

}  // namespace nckit
