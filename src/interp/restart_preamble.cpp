#include "restart_preamble.hpp"

#include <algorithm>
#include <filesystem>
#include <iterator>

#include <fmt/format.h>

#include "nckit/core/format_exact.hpp"
#include "nckit/interp/arc_geometry.hpp"
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

void io_blocks(std::string& out, const RestartIo& io, const MachineConfig& machine) {
    if (io.tool_in_spindle > 0) fmt::format_to(std::back_inserter(out), "T{} M6\n", io.tool_in_spindle);
    if (io.tool_selected != io.tool_in_spindle && io.tool_selected > 0)
        fmt::format_to(std::back_inserter(out), "T{}\n", io.tool_selected);
    if (io.speed_set) {
        // A Fanuc lathe clamps with the coordinate-setting code and S (G50 in system A, G92 in
        // B and C), a mode of its own that stays under G97 too; elsewhere G96 D carries the
        // clamp, as LinuxCNC reads it.
        const bool lathe = machine.gcode_system != GCodeSystem::none;
        if (io.rpm_clamp > 0 && lathe) {
            out += machine.gcode_system == GCodeSystem::a ? "G50 S" : "G92 S";
            append_exact(out, io.rpm_clamp);
            out += '\n';
        }
        if (io.constant_surface_speed) {
            out += "G96";
            if (io.rpm_clamp > 0 && !lathe) {
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

bool frame_can_be_set(const ModalView& s) {
    return s.work_system < 6;
}

GcodeFrame program_frame(const ModalView& s, const MachineConfig& machine) {
    GcodeFrame frame;
    for (const AxisConfig& axis : machine.axes) {
        const Axis a = axis.axis;
        frame.origin_mm[a] = s.work_offset[a] + s.g92_offset[a] + s.g52_offset[a] + s.tool_offset[a];
    }
    frame.length_factor_mm = s.length_factor_mm;
    frame.incremental = s.incremental;
    frame.diameter = s.diameter_mode;
    frame.transform = s.transform;
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
    const GCodeSystem system = machine.gcode_system;
    out += "( the program's frame at the target )\n";
    // Lathe system C writes inch and metric as G70 / G71.
    const bool metric = s.length_factor_mm == 1.0;
    out += system == GCodeSystem::c ? (metric ? "G71\n" : "G70\n") : (metric ? "G21\n" : "G20\n");
    // Every work system that holds an offset (a later block may select it), the active one always.
    for (std::size_t k = 0; k < s.work_offsets.size(); ++k) {
        const std::string words = program_words(s.work_offsets[k], s, machine, k != s.work_system);
        if (!words.empty()) fmt::format_to(std::back_inserter(out), "G10 L2 P{}{}\n", k + 1, words);
    }
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
        // G92 (G50 in lathe system A) makes the point the tool stands at read as the program
        // read it.
        AxisVector reads;
        for (const AxisConfig& axis : machine.axes) {
            const Axis a = axis.axis;
            reads[a] = (*point)[a] - s.work_offset[a] - s.g52_offset[a] - s.tool_offset[a] - s.g92_offset[a];
        }
        out += system == GCodeSystem::a ? "G50" : "G92";
        out += program_words(reads, s, machine, false) + '\n';
    }
}

void transform_blocks(std::string& out, const ModalView& s, const MachineConfig& machine, const AxisVector* point) {
    const TransformView& t = s.transform;
    if (!t.active()) return;
    out += "( mirror, scaling and rotation at the target )\n";
    auto length = [&](Axis axis, double mm) {
        const AxisConfig* config = machine.find(axis);
        return config != nullptr && config->kind == AxisKind::rotary ? mm : mm / s.length_factor_mm;
    };
    std::string mirror;
    for (const AxisConfig& axis : machine.axes) {
        if (!t.mirrored[index(axis.axis)]) continue;
        mirror += ' ';
        mirror += letter(axis.axis);
        append_exact(mirror, length(axis.axis, t.mirror_at[axis.axis]));
    }
    if (!mirror.empty()) out += "G51.1" + mirror + '\n';
    if (t.scale_on) {
        out += "G51";
        for (const AxisConfig& axis : machine.axes) {
            out += ' ';
            out += letter(axis.axis);
            append_exact(out, length(axis.axis, t.scale_center[axis.axis]));
        }
        // A factor per axis (I J K for X Y Z): P takes no negative factor.
        for (Axis axis : {Axis::X, Axis::Y, Axis::Z}) {
            if (machine.find(axis) == nullptr) continue;
            out += ' ';
            out += "IJK"[index(axis)];
            append_exact(out, t.scale[index(axis)]);
        }
        out += '\n';
    }
    if (t.rotate_on) {
        const PlaneAxes axes = plane_axes(t.rotate_plane);
        fmt::format_to(std::back_inserter(out), "{}\nG68 {}", plane_code(t.rotate_plane), letter(axes.first));
        append_exact(out, length(axes.first, t.rotate_first));
        out += ' ';
        out += letter(axes.second);
        append_exact(out, length(axes.second, t.rotate_second));
        out += " R";
        append_exact(out, t.rotate_deg);
        out += '\n';
    }
    if (point == nullptr) return;
    // The reader takes the point it stood at when the transforms came on as the programmed
    // point; one move to where the tool stands, in the transformed program's coordinates, makes
    // the programmed point the one the original run had (incremental words start from it).
    const GcodeFrame frame = program_frame(s, machine);
    const AxisVector programmed = t.unmap(*point - frame.origin_mm);
    out += "G0";
    for (const AxisConfig& axis : machine.axes) {
        out += ' ';
        out += letter(axis.axis);
        append_exact(out, length(axis.axis, programmed[axis.axis]));
    }
    out += '\n';
}

}  // namespace nckit::restart_detail
