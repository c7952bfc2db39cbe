#include "restart_preamble.hpp"

#include <algorithm>
#include <filesystem>
#include <iterator>

#include <fmt/format.h>

#include "nckit/core/format_exact.hpp"
#include "nckit/interp/move_gcode.hpp"

namespace nckit::restart_detail {

namespace {

void axis_word(std::string& out, Axis axis, double value, int decimals, double& worst) {
    out += ' ';
    out += letter(axis);
    if (decimals < 0) {
        append_exact(out, value);
    } else {
        worst = std::max(worst, append_rounded(out, value, decimals));
    }
}

}  // namespace

void note_io(const Io& io, const MachineConfig& machine, RestartIo& state) {
    switch (io.kind) {
        case IoKind::tool_select:
            state.tool_selected = io.number;
            return;
        case IoKind::spindle_speed:
            state.speed_set = true;
            state.speed = io.value;
            state.constant_surface_speed = io.constant_surface_speed;
            state.rpm_clamp = io.rpm_clamp;
            return;
        case IoKind::mcode:
            break;
    }
    const int m = io.number;
    if (m == 3 || m == 4 || m == 5) {
        state.spindle_mcode = m;
        state.spindle_rpm = io.value;
    } else if (m == 6) {
        state.tool_in_spindle = state.tool_selected;
    } else if (m == 7) {
        state.mist = true;
    } else if (m == 8) {
        state.flood = true;
    } else if (m == 9) {
        state.mist = state.flood = false;
    } else if (machine.is_laser_on_mcode(m)) {
        if (std::find(state.laser_on.begin(), state.laser_on.end(), m) == state.laser_on.end())
            state.laser_on.push_back(m);
    } else if (machine.is_laser_off_mcode(m)) {
        state.laser_on.clear();
    }
}

std::string location_text(const SourceLocation& where) {
    return fmt::format("{}:{}", std::filesystem::path(where.file_name()).filename().string(), where.line);
}

const char* plane_code(Plane plane) {
    return plane == Plane::xy ? "G17" : plane == Plane::zx ? "G18" : "G19";
}

//! The comment lines that record the program's own frame at the target: the moves below carry
//! it already (machine coordinates), so it is written for the operator, not set again.
void frame_comments(std::string& out, const ModalView& s, const MachineConfig& machine, bool set_again) {
    auto vector_text = [&](const AxisVector& v) {
        std::string text;
        for (const AxisConfig& axis : machine.axes) {
            text += ' ';
            text += letter(axis.axis);
            append_exact(text, v[axis.axis]);
        }
        return text;
    };
    fmt::format_to(std::back_inserter(out), "( program state: {} {} {} {}{} G{} offset{} )\n",
                   s.length_factor_mm == 1.0 ? "G21" : "G20", s.incremental ? "G91" : "G90", plane_code(s.plane),
                   feed_mode_code(s.feed_mode, machine), s.diameter_mode ? " G7" : "", 54 + s.work_system,
                   vector_text(s.work_offset));
    fmt::format_to(std::back_inserter(out), "( G92{} G52{} )\n", vector_text(s.g92_offset), vector_text(s.g52_offset));
    fmt::format_to(std::back_inserter(out), "( tool length G{}{} H{}{}{} )\n", s.length_offset_code / 10,
                   s.length_offset_code % 10 != 0 ? ".1" : "", s.length_offset_h, vector_text(s.tool_offset),
                   s.transform_active ? ", mirror/scaling/rotation in force" : "");
    out += set_again ? "( set again after the approach; the rest is written in this frame )\n"
                     : "( positions below are machine coordinates with all of these applied )\n";
}

void io_blocks(std::string& out, const RestartIo& io) {
    if (io.tool_in_spindle > 0) fmt::format_to(std::back_inserter(out), "T{} M6\n", io.tool_in_spindle);
    if (io.tool_selected != io.tool_in_spindle && io.tool_selected > 0)
        fmt::format_to(std::back_inserter(out), "T{}\n", io.tool_selected);
    if (io.speed_set) {
        if (io.constant_surface_speed) {
            out += "G96";
            if (io.rpm_clamp > 0) {
                out += " D";
                append_exact(out, io.rpm_clamp);
            }
        } else {
            out += "G97";
        }
        out += " S";
        append_exact(out, io.speed);
        out += '\n';
    }
    if (io.spindle_mcode != 5) fmt::format_to(std::back_inserter(out), "M{}\n", io.spindle_mcode);
    if (io.mist) out += "M7\n";
    if (io.flood) out += "M8\n";
}

Axis retract_axis_of(const MachineConfig& machine) {
    if (machine.diameter_mode || machine.find(Axis::Y) == nullptr) return Axis::X;
    return Axis::Z;
}

void approach_blocks(std::string& out, RestartApproach& a, const MachineConfig& machine, int decimals, double& worst) {
    const Axis r = a.retract_axis;
    out += "( approach: retract, rapid over the restart point from the side the path came, feed onto it )\n";
    bool first = true;
    // Only the end points of the steps are written: where they start does not show.
    for (const ApproachStep& step : approach_steps(a, machine, a.point)) {
        std::string block = first ? std::string(feed_mode_code(FeedMode::per_minute, machine)) + " G64 G0"
                                  : std::string(step.line.rapid ? "G0" : "G1");
        first = false;
        for (const AxisConfig& axis : machine.axes) {
            if ((axis.axis == r) == step.retract_axis_only) {
                axis_word(block, axis.axis, step.line.to[axis.axis], decimals, worst);
            }
        }
        if (!step.line.rapid) {
            block += " F";
            append_exact(block, a.feed_mm_min);
        }
        out += block + '\n';
    }
}

bool frame_can_be_set(const ModalView& s, const MachineConfig& machine) {
    return !s.transform_active && !s.diameter_mode && !machine.diameter_mode &&
           machine.gcode_system != GCodeSystem::a && s.work_system < 6;
}

GcodeFrame program_frame(const ModalView& s, const MachineConfig& machine) {
    GcodeFrame frame;
    for (const AxisConfig& axis : machine.axes) {
        const Axis a = axis.axis;
        frame.origin_mm[a] = s.work_offset[a] + s.g92_offset[a] + s.g52_offset[a] + s.tool_offset[a];
    }
    frame.length_factor_mm = s.length_factor_mm;
    frame.incremental = s.incremental;
    return frame;
}

namespace {

//! " X1.5 Y0 Z-2" of `v` in program units (rotary axes as they are); nothing when all are zero
//! and `skip_zero`.
std::string program_words(const AxisVector& v, const ModalView& s, const MachineConfig& machine, bool skip_zero) {
    std::string words;
    bool any = false;
    for (const AxisConfig& axis : machine.axes) {
        const double factor = axis.kind == AxisKind::rotary ? 1.0 : s.length_factor_mm;
        any = any || v[axis.axis] != 0.0;
        words += ' ';
        words += letter(axis.axis);
        append_exact(words, v[axis.axis] / factor);
    }
    return skip_zero && !any ? std::string() : words;
}

}  // namespace

void frame_blocks(std::string& out, const ModalView& s, const MachineConfig& machine, const AxisVector* point) {
    out += "( the program's frame at the target )\n";
    out += s.length_factor_mm == 1.0 ? "G21\n" : "G20\n";
    fmt::format_to(std::back_inserter(out), "G10 L2 P{}{}\n", s.work_system + 1,
                   program_words(s.work_offset, s, machine, false));
    fmt::format_to(std::back_inserter(out), "G{}\n", 54 + s.work_system);
    if (const std::string words = program_words(s.g52_offset, s, machine, true); !words.empty()) {
        out += "G52" + words + '\n';
    }
    switch (s.length_offset_code) {
        case 430:
            fmt::format_to(std::back_inserter(out), "G43 H{}\n", s.length_offset_h);
            break;
        case 440:
            fmt::format_to(std::back_inserter(out), "G44 H{}\n", s.length_offset_h);
            break;
        case 431:
            out += "G43.1" + program_words(s.tool_offset, s, machine, false) + '\n';
            break;
        default:
            break;  // G49, as the header left it
    }
    bool g92 = false;
    for (const AxisConfig& axis : machine.axes) g92 = g92 || s.g92_offset[axis.axis] != 0.0;
    if (g92 && point != nullptr) {
        // G92 makes the point the tool stands at read as the program read it.
        AxisVector reads;
        for (const AxisConfig& axis : machine.axes) {
            const Axis a = axis.axis;
            reads[a] = (*point)[a] - s.work_offset[a] - s.g52_offset[a] - s.tool_offset[a] - s.g92_offset[a];
        }
        out += "G92" + program_words(reads, s, machine, false) + '\n';
    }
}

}  // namespace nckit::restart_detail
