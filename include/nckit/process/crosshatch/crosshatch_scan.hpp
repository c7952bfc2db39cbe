#pragma once
// The whole crosshatch scan: the laser tracks on the bore wall, the motors' step streams (feed
// motor = axis 0, Z; rotation motor = axis 1, A, as in examples/machines/crosshatch.toml), the
// G-code with a rotary A axis, and the unrolled bore drawn as SVG.
//
// Timeline of one cycle (timer clock ticks): the down stroke, feed step k of F at k·d_f; the up
// stroke likewise; then the index move, |M| rotation steps at the index divisor. The laser is on
// during the strokes and off during the index move. Rotation steps during the strokes:
//   one_time_base: step j of the stroke's R at round(j·F·d_f / R) — the count ratio is exact;
//   free_running_timers: every d_r ticks of the rotation counter, which holds its phase while
//   the index move runs on the index divisor; its rounding makes the head drift against the feed.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "nckit/drive/step_generator.hpp"
#include "nckit/process/crosshatch/crosshatch.hpp"

namespace nckit {

//! One laser track: a helix on the bore wall, straight on the unrolled bore.
struct CrosshatchTrack {
    int cycle = 0;          //!< 0-based down-and-up cycle
    bool down = true;       //!< into the bore (Z falling) or out
    double start_s = 0;     //!< s from the scan start
    double end_s = 0;       //!< s
    double start_deg = 0;   //!< head angle, unwrapped (rotation steps / steps per degree)
    double end_deg = 0;     //!< deg
    double start_z_mm = 0;  //!< 0 at the bore mouth, -stroke at the bottom
    double end_z_mm = 0;    //!< mm
};

//! The scan as the drive makes it.
struct CrosshatchScan {
    std::vector<CrosshatchTrack> tracks;
    double duration_s = 0;             //!< whole scan, index moves included
    double stroke_mm = 0;              //!< stroke as stepped: feed steps / steps per mm
    double track_angle_deg = 0;        //!< included angle of the drawn helices
    double track_angle_error_deg = 0;  //!< track_angle_deg - the wanted crosshatch angle
    //! What the timers' divisor rounding alone can do to the angle (first order); it reaches the
    //! tracks only with free-running timers.
    double timer_angle_error_bound_deg = 0;
    double drift_deg_per_stroke = 0;  //!< head angle at a stroke's end minus N/I turns
    double closure_error_steps = 0;   //!< |head position after the scan - start|, mod a turn
    std::int64_t feed_steps = 0;      //!< steps issued, both directions
    std::int64_t rotation_steps = 0;  //!< steps issued, index moves included
};

[[nodiscard]] CrosshatchScan build_crosshatch_scan(const CrosshatchPlan& plan);

//! Axis indices of the step stream.
inline constexpr std::uint8_t crosshatch_feed_axis = 0;
inline constexpr std::uint8_t crosshatch_rotation_axis = 1;

//! Every motor step of the scan in time order (ties: feed first) with the port byte the motor's
//! phase table writes after it (the seed's active-low encoding; 0 without a phase table). The
//! stream is produced as it goes, so a long scan needs no memory.
void for_each_crosshatch_step(const CrosshatchPlan& plan,
                              const std::function<void(const StepEvent& step, std::uint8_t port)>& sink);

//! The scan as a program for a controller with Z and a rotary A: G94 feed on Z (the rotary axis
//! follows, as LinuxCNC measures mixed moves), laser M-codes around each stroke pair. The
//! pattern as commanded: whole motor steps of the one-time-base drive, whatever the job's timing.
[[nodiscard]] std::string crosshatch_gcode(const CrosshatchPlan& plan, const std::string& job_name);

//! The bore unrolled (angle across, depth down, to scale) with every track drawn.
[[nodiscard]] std::string crosshatch_svg(const CrosshatchPlan& plan, const CrosshatchScan& scan);

}  // namespace nckit
