#pragma once
// Crosshatch laser hardening of cylinder bores (docs/processes/crosshatch.md). A laser
// head inside the bore moves axially (feed stepper, lead screw) while it rotates (rotation
// stepper): a down stroke and an up stroke with the rotation running draw two helices of opposite
// slope; `heads` cycles, each started `index_deg` further round, make the diamond net.
//
// Names: V1 is the rotation speed of the head, V2 the speed of the feed lead screw (the paper
// swaps them in its section 3.2; nckit uses these throughout).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "nckit/core/machine.hpp"
#include "nckit/core/result.hpp"
#include "nckit/core/source_location.hpp"
#include "nckit/drive/interval_timer.hpp"

namespace nckit {

//! How the two motors' steps are timed.
enum class CrosshatchTiming {
    //! Both motors from one time base: the feed timer paces the strokes and the rotation steps of
    //! a stroke are spread over it in the exact count ratio. Closure is exact in steps.
    one_time_base,
    //! Each motor on its own interval timer with its rounded divisor (the paper's two 8253
    //! channels): the rotation drifts against the feed by the divisors' rounding.
    free_running_timers
};

//! The job file's [crosshatch] table.
struct CrosshatchJob {
    double bore_diameter_mm = 0;              //!< D
    double bore_length_mm = 0;                //!< H, the stroke
    double lead_screw_pitch_mm = 0;           //!< L
    int heads = 0;                            //!< I, helix starts
    double lines_per_length = 0;              //!< N, lines of one helix family crossing an axial line over H
    double feed_screw_rpm = 0;                //!< V2, lead-screw speed
    double step_angle_deg = 1.5;              //!< motor step (one beat of the phase table)
    double gear_ratio = 3.0;                  //!< motor turns per screw turn or head turn (both motors)
    double timer_clock_hz = 1e6;              //!< interval timer input clock
    std::uint32_t timer_max_divisor = 65535;  //!< 16-bit counter
    double index_deg = 0;                     //!< wanted offset between successive cycles (default 360/I)
    int cycles = 0;                           //!< down-and-up cycles in the scan (default I)
    double index_rpm = 0;                     //!< head speed of the index move (default V1)
    CrosshatchTiming timing = CrosshatchTiming::one_time_base;
    PhaseTableKind phase_table = PhaseTableKind::three_phase_six_beat;  //!< both motors' windings
    int laser_on_mcode = 27;   //!< M-code that switches the beam on in the G-code
    int laser_off_mcode = 28;  //!< M-code that switches it off

    //! Where checks that involve several keys point (the file's lines for these keys).
    SourceLocation feed_screw_rpm_at;
    SourceLocation timer_clock_at;
    SourceLocation index_rpm_at;
    SourceLocation bore_length_at;
};

//! Reads and checks a job file; every error carries FILE:LINE:COL.
[[nodiscard]] Result<CrosshatchJob> load_crosshatch_job(const std::filesystem::path& path);
[[nodiscard]] Result<CrosshatchJob> parse_crosshatch_job(std::string_view toml_text, const std::string& file_name);

//! One motor's stepping: what it must do and what the counter makes of it.
struct MotorDrive {
    double shaft_rpm = 0;       //!< head or screw speed
    double steps_per_unit = 0;  //!< motor steps per mm (feed) or per head degree (rotation)
    drive::TimerSetting timer;  //!< divisor, real rate, relative speed error
};

//! Everything the job implies, before any step is generated.
struct CrosshatchPlan {
    CrosshatchJob job;
    double feed_mm_min = 0;           //!< axial speed L·V2
    double rotation_rpm = 0;          //!< V1 = L·V2·(N/I)/H
    double surface_speed_mm_min = 0;  //!< π·D·V1
    double turns_per_stroke = 0;      //!< N/I head turns while the head travels H
    double stroke_time_s = 0;         //!< H / axial speed, nominal
    double line_spacing_mm = 0;       //!< H/N, axial distance between lines of one family
    double helix_angle_deg = 0;       //!< β: atan(axial / surface speed)
    double crosshatch_angle_deg = 0;  //!< 2β, the included angle of the two helix families
    MotorDrive rotation;
    MotorDrive feed;
    drive::TimerSetting index_timer;             //!< the rotation motor's counter during the index move
    std::int64_t feed_steps_per_stroke = 0;      //!< round(H·spu): the stroke as stepped
    std::int64_t rotation_steps_per_stroke = 0;  //!< round(N/I·steps per head turn)
    double rotation_steps_per_turn = 0;          //!< motor steps per head turn: gear·360/step
    double round_trip_deg = 0;                   //!< α1: head rotation over a down-and-up cycle, mod 360
    bool special = false;                        //!< α1 ≡ index: the pattern closes with no correction
    std::int64_t index_move_steps = 0;           //!< signed correction after the first cycle (negative: back)
    double index_move_deg = 0;                   //!< the same in head degrees
    //! The correction after each cycle, in steps. Cycle c ends at the absolute target
    //! round((c + 1)·index·spu) (mod a turn), so an index of no whole number of steps makes
    //! moves one step apart that never add up to an error (absolute rounding, as the step
    //! generator's counts).
    std::vector<std::int64_t> index_moves_steps;
};

//! Computes the speeds, step counts, timer divisors and the index rule. Errors (located at the
//! key that decides them): a step rate the counter cannot make, a stroke of no steps.
[[nodiscard]] Result<CrosshatchPlan> plan_crosshatch(const CrosshatchJob& job);

}  // namespace nckit
