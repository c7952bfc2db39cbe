#include "nckit/interp/move_gcode.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iterator>
#include <variant>

#include <fmt/format.h>

#include "nckit/core/format_exact.hpp"
#include "nckit/interp/arc_geometry.hpp"

namespace nckit {

namespace {

const char* plane_code(Plane plane) {
    switch (plane) {
        case Plane::xy:
            return "G17";
        case Plane::zx:
            return "G18";
        case Plane::yz:
            return "G19";
    }
    return "G17";
}

//! The centre-offset letter of a plane axis: I for X, J for Y, K for Z.
char offset_letter(Axis axis) {
    return axis == Axis::X ? 'I' : axis == Axis::Y ? 'J' : 'K';
}

void source_comment(std::string& out, const SourceLocation& where) {
    std::string name = comment_text(std::filesystem::path(where.file_name()).filename().string());
    fmt::format_to(std::back_inserter(out), " ({}:{})", name, where.line);
}

}  // namespace

const char* feed_mode_code(FeedMode mode, const MachineConfig& machine) {
    const bool per_revolution = mode == FeedMode::per_revolution;
    if (machine.gcode_system == GCodeSystem::a) return per_revolution ? "G99" : "G98";
    return per_revolution ? "G95" : "G94";
}

void GcodeWriter::append_header(std::string& out, const std::string& source_name) const {
    fmt::format_to(std::back_inserter(out), "( {} expanded by nckit for machine {} )\n",
                   comment_text(std::filesystem::path(source_name).filename().string()), comment_text(machine_.name));
    out += "( one move per block, absolute machine coordinates in mm; dwell P in ms )\n";
    // Offsets cleared (G54, and G92, which LinuxCNC keeps between programs) so that program
    // coordinates are machine coordinates; radius mode because the moves carry radii whatever
    // the program wrote.
    // Lathe system A has no G90/G91 (U and W are the incremental words) and its G90, G94 are
    // turning and facing cycles.
    if (machine_.gcode_system == GCodeSystem::a) {
        out += "G21 G98 G18 G40 G80 G54 G64\n";
    } else {
        fmt::format_to(std::back_inserter(out), "G21 G90 {} G17 G40 G49 G80 G54 G64\n",
                       feed_mode_code(FeedMode::per_minute, machine_));
    }
    out += "G92.1\n";
    out += "G10 L2 P1";
    for (const AxisConfig& axis : machine_.axes) fmt::format_to(std::back_inserter(out), " {}0", letter(axis.axis));
    out += '\n';
    if (machine_.diameter_mode) out += "G8\n";
}

void GcodeWriter::number(std::string& out, char letter, double value, double scale_mm) {
    out += ' ';
    out += letter;
    if (decimals_ < 0) {
        append_exact(out, value);
    } else {
        worst_deviation_mm_ = std::max(worst_deviation_mm_, append_rounded(out, value, decimals_) * scale_mm);
    }
}

double GcodeWriter::length_factor(Axis axis) const {
    const AxisConfig* config = machine_.find(axis);
    return config != nullptr && config->kind == AxisKind::rotary ? 1.0 : frame_.length_factor_mm;
}

AxisVector GcodeWriter::to_program(const AxisVector& machine) const {
    const AxisVector work = machine - frame_.origin_mm;
    return frame_.transform.active() ? frame_.transform.unmap(work) : work;
}

void GcodeWriter::append_axes(std::string& out, const AxisVector& position) {
    const AxisVector now = to_program(position);
    const AxisVector before = to_program(last_);
    for (std::size_t i = 0; i < axis_count; ++i) {
        auto axis = static_cast<Axis>(i);
        if (machine_.find(axis) == nullptr) continue;
        const double diameter = frame_.diameter && axis == Axis::X ? 2.0 : 1.0;
        const double factor = length_factor(axis) / diameter;
        double value = now[axis] / factor;
        if (frame_.incremental) value -= before[axis] / factor;
        number(out, letter(axis), value, factor);
    }
    last_ = position;
}

void GcodeWriter::append_feed(std::string& out, const Feed& feed) {
    double value = feed.mode == FeedMode::per_revolution ? feed.mm_per_rev : feed.mm_per_min;
    if (feed.mode != feed_mode_) {
        out += ' ';
        out += feed_mode_code(feed.mode, machine_);
        feed_mode_ = feed.mode;
        feed_ = -1;
    }
    if (value != feed_) {
        // Feeds are never rounded: no input increment applies to them, and under G95 or in a
        // thread an error is multiplied by the rpm or the turns.
        out += " F";
        append_exact(out, value / frame_.length_factor_mm);
        feed_ = value;
    }
}

void GcodeWriter::append_path(std::string& out, const PathControl& path) {
    if (path.exact_stop == path_.exact_stop && path.tolerance_mm == path_.tolerance_mm) return;
    if (path.exact_stop) {
        out += "G61 ";
    } else if (path.tolerance_mm > 0) {
        out += "G64 P";
        append_exact(out, path.tolerance_mm);
        out += ' ';
    } else {
        out += "G64 ";
    }
    path_ = path;
}

void GcodeWriter::append(std::string& out, const Move& move) {
    std::visit(
        [&](const auto& m) {
            using T = std::decay_t<decltype(m)>;
            if constexpr (std::is_same_v<T, Line>) {
                append_path(out, m.path);
                out += m.rapid ? "G0" : "G1";
                append_axes(out, m.to);
                if (!m.rapid) append_feed(out, m.feed);
            } else if constexpr (std::is_same_v<T, Arc>) {
                append_path(out, m.path);
                const PlaneAxes in = plane_axes(m.plane);
                if (m.center[in.first] == m.from[in.first] && m.center[in.second] == m.from[in.second]) {
                    // An arc of radius 0 (LinuxCNC's compensation on a hole of the tool's size) is
                    // the straight line it is in space; as an arc no reader would take it back.
                    out += "G1";
                    append_axes(out, m.to);
                    append_feed(out, m.feed);
                    return;
                }
                if (m.plane != plane_) {
                    out += plane_code(m.plane);
                    out += ' ';
                    plane_ = m.plane;
                }
                // Under a mirror the reader turns the arc round again.
                const bool clockwise = (m.direction == ArcDirection::clockwise) != frame_.transform.reverses(m.plane);
                out += clockwise ? "G2" : "G3";
                append_axes(out, m.to);
                PlaneAxes p = plane_axes(m.plane);
                const AxisVector center = to_program(m.center), from = to_program(m.from);
                for (Axis axis : {p.first, p.second}) {
                    number(out, offset_letter(axis), (center[axis] - from[axis]) / length_factor(axis),
                           length_factor(axis));
                }
                append_feed(out, m.feed);
            } else if constexpr (std::is_same_v<T, SyncMove>) {
                out += "G33";
                append_axes(out, m.to);
                out += " K";  // the lead, mm/rev (LinuxCNC and nckit read K), never rounded
                append_exact(out, m.feed.mm_per_rev / frame_.length_factor_mm);
                // A multi-start thread's start angle, in Fanuc's 0.001 degree (the angle came
                // from such a Q, so it is a whole number of them).
                if (m.start_angle_deg != 0) {
                    fmt::format_to(std::back_inserter(out), " Q{}", std::llround(m.start_angle_deg * 1000.0));
                }
            } else if constexpr (std::is_same_v<T, Dwell>) {
                out += "G4 P";
                append_exact(out, m.seconds * 1000.0);
            } else if constexpr (std::is_same_v<T, Io>) {
                switch (m.kind) {
                    case IoKind::mcode:
                        fmt::format_to(std::back_inserter(out), "M{}", m.number);
                        ended_ = m.number == 2 || m.number == 30;
                        break;
                    case IoKind::tool_select:
                        fmt::format_to(std::back_inserter(out), "T{}", m.number);
                        break;
                    case IoKind::spindle_speed:
                        if (m.constant_surface_speed) {
                            // LinuxCNC's form of the clamp (G96 D) rather than Fanuc's G50 S.
                            out += "G96";
                            if (m.rpm_clamp > 0) {
                                out += " D";
                                append_exact(out, m.rpm_clamp);
                            }
                            out += " S";
                        } else {
                            out += "G97 S";
                        }
                        append_exact(out, m.value);
                        break;
                }
            }
        },
        move.what);
    source_comment(out, move.where);
    out += '\n';
}

void GcodeWriter::append_footer(std::string& out) const {
    if (!ended_) out += "M30\n";
}

}  // namespace nckit
