// The crosshatch scan as G-code: Z along the bore, a rotary A axis for the head.
#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

#include "nckit/core/format_fixed.hpp"
#include "nckit/process/crosshatch/crosshatch_scan.hpp"

namespace nckit {

namespace {

std::string fixed4(double value) {
    std::string out;
    append_fixed4(out, value == 0 ? 0.0 : value);  // never "-0.0000"
    return out;
}

}  // namespace

std::string crosshatch_gcode(const CrosshatchPlan& plan, const std::string& job_name) {
    const CrosshatchJob& job = plan.job;
    std::string out = "%\n";
    out += fmt::format("(crosshatch laser hardening: {})\n", job_name);
    out += fmt::format("(bore D{} x H{} mm, lead screw {} mm, {} heads, {} lines per length)\n", job.bore_diameter_mm,
                       job.bore_length_mm, job.lead_screw_pitch_mm, job.heads, job.lines_per_length);
    out += fmt::format("(rotation {:.6g} rpm, feed {:.6g} mm/min, crosshatch angle {:.4f} deg)\n", plan.rotation_rpm,
                       plan.feed_mm_min, plan.crosshatch_angle_deg);
    if (plan.special) {
        out += fmt::format("(index {:.6g} deg: special angle, the cycles close with no correction)\n", job.index_deg);
    } else {
        out += fmt::format("(index {:.6g} deg: arbitrary angle, correction {:+.6g} deg after each cycle)\n",
                           job.index_deg, plan.index_move_deg);
    }
    out += "(Z0 is the bore mouth, A0 the start of the first track. F is the axial feed: the A axis)\n";
    out += "(follows, as LinuxCNC and nckit measure a move of a linear and a rotary axis.)\n";
    out += "G21 G90 G94\n";
    out += "G0 Z0 A0\n";
    const double index_deg_min = (job.index_rpm > 0 ? job.index_rpm : plan.rotation_rpm) * 360.0;
    // Whole motor steps, as the one-time-base drive makes them: the program is the pattern as
    // commanded; the drift of free-running timers is a property of that drive, not of the job.
    const double spu_deg = plan.rotation.steps_per_unit;
    const double stroke_mm = static_cast<double>(plan.feed_steps_per_stroke) / plan.feed.steps_per_unit;
    std::int64_t head_steps = 0;
    auto a_word = [&] { return " A" + fixed4(static_cast<double>(head_steps) / spu_deg); };
    for (int cycle = 0; cycle < job.cycles; ++cycle) {
        out += fmt::format("(cycle {} of {})\n", cycle + 1, job.cycles);
        out += fmt::format("M{}\n", job.laser_on_mcode);
        head_steps += plan.rotation_steps_per_stroke;
        out += "G1 Z" + fixed4(-stroke_mm) + a_word() + " F" + fixed4(plan.feed_mm_min) + "\n";
        head_steps += plan.rotation_steps_per_stroke;
        out += "G1 Z0.0000" + a_word() + "\n";
        out += fmt::format("M{}\n", job.laser_off_mcode);
        if (plan.index_moves_steps[cycle] != 0) {
            head_steps += plan.index_moves_steps[cycle];
            out += "G1" + a_word() + " F" + fixed4(index_deg_min) + "\n";
        }
    }
    out += "M30\n%\n";
    return out;
}

}  // namespace nckit
