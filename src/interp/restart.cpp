#include "nckit/interp/restart.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iterator>
#include <memory>
#include <optional>
#include <variant>

#include <fmt/format.h>

#include "nckit/core/format_exact.hpp"
#include "nckit/interp/arc_geometry.hpp"
#include "nckit/interp/move_gcode.hpp"

namespace nckit {

namespace {

constexpr double takeup_mm = 1.0;     // more than any backlash a machine file may hold today
constexpr double clearance_mm = 2.0;  // the last stretch onto the point is fed, not rapid

//! One executed block as the move stream shows it: moves from one refill of the interpreter
//! with the same source line. A block run again (a loop) comes in another refill.
struct BlockKey {
    const std::string* file = nullptr;
    std::uint32_t line = 0;
    std::uint64_t batch = 0;
    bool operator==(const BlockKey&) const = default;
};

const AxisVector* end_of(const Move& move) {
    if (const auto* line = std::get_if<Line>(&move.what)) return &line->to;
    if (const auto* arc = std::get_if<Arc>(&move.what)) return &arc->to;
    if (const auto* sync = std::get_if<SyncMove>(&move.what)) return &sync->to;
    return nullptr;
}

const AxisVector* start_of(const Move& move) {
    if (const auto* line = std::get_if<Line>(&move.what)) return &line->from;
    if (const auto* arc = std::get_if<Arc>(&move.what)) return &arc->from;
    if (const auto* sync = std::get_if<SyncMove>(&move.what)) return &sync->from;
    return nullptr;
}

//! The side each axis was moving to when the move ended: for an arc the tangent at its end.
void note_directions(const Move& move, std::array<int, axis_count>& side) {
    const AxisVector* from = start_of(move);
    const AxisVector* to = end_of(move);
    if (from == nullptr) return;
    AxisVector direction;
    for (std::size_t i = 0; i < axis_count; ++i) direction.value[i] = to->value[i] - from->value[i];
    if (const auto* arc = std::get_if<Arc>(&move.what)) {
        PlaneAxes p = plane_axes(arc->plane);
        const double u = arc->to[p.first] - arc->center[p.first];
        const double v = arc->to[p.second] - arc->center[p.second];
        const double turn = arc->direction == ArcDirection::counterclockwise ? 1.0 : -1.0;
        direction[p.first] = -v * turn;
        direction[p.second] = u * turn;
        // At an extreme of the circle an axis's tangent is zero: it arrived moving outwards.
        const double radius = std::hypot(u, v);
        if (std::abs(direction[p.first]) <= 1e-9 * radius) direction[p.first] = u;
        if (std::abs(direction[p.second]) <= 1e-9 * radius) direction[p.second] = v;
    }
    for (std::size_t i = 0; i < axis_count; ++i) {
        if (std::abs(direction.value[i]) > 1e-12) side[i] = direction.value[i] > 0 ? 1 : -1;
    }
}

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

void axis_word(std::string& out, Axis axis, double value, int decimals, double& worst) {
    out += ' ';
    out += letter(axis);
    if (decimals < 0) {
        append_exact(out, value);
    } else {
        worst = std::max(worst, append_rounded(out, value, decimals));
    }
}

//! The comment lines that record the program's own frame at the target: the moves below carry
//! it already (machine coordinates), so it is written for the operator, not set again.
void frame_comments(std::string& out, const ModalView& s, const MachineConfig& machine) {
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
    out += "( positions below are machine coordinates with all of these applied )\n";
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
    const double away = a.safe_mm >= a.point[r] ? 1.0 : -1.0;
    out += "( approach: retract, rapid over the restart point from the side the path came, feed onto it )\n";
    out += feed_mode_code(FeedMode::per_minute, machine);
    out += " G64 G0";
    axis_word(out, r, a.safe_mm, decimals, worst);
    out += '\n';
    std::string before = "G0";
    std::string over = "G0";
    for (const AxisConfig& axis : machine.axes) {
        if (axis.axis == r) continue;
        const int side = a.side[index(axis.axis)];
        axis_word(before, axis.axis, a.point[axis.axis] - side * a.takeup_mm, decimals, worst);
        axis_word(over, axis.axis, a.point[axis.axis], decimals, worst);
    }
    if (before != "G0") out += before + '\n' + over + '\n';
    const double near = a.point[r] + away * a.clearance_mm;
    if (away * (a.safe_mm - near) > 0) {
        out += "G0";
        axis_word(out, r, near, decimals, worst);
        out += '\n';
    }
    out += "G1";
    axis_word(out, r, a.point[r], decimals, worst);
    out += " F";
    append_exact(out, a.feed_mm_min);
    out += '\n';
}

std::uint32_t line_count(const std::string& text) {
    return static_cast<std::uint32_t>(std::count(text.begin(), text.end(), '\n'));
}

}  // namespace

Result<RestartReport> write_restart(Interpreter& interpreter, const RestartTarget& target,
                                    const std::string& source_name, std::string& out, int decimals) {
    const MachineConfig& machine = interpreter.machine();
    RestartReport report;
    report.state = interpreter.modal_view();
    std::array<int, axis_count> side{};
    std::optional<AxisVector> position;  // where the last motion before the target ended
    std::optional<BlockKey> previous;
    std::int64_t blocks = 0, hits = 0, records = 0;
    bool previous_comp = false;
    std::optional<Move> thread_start;  // first move of the run of G32/G33 moves just made
    const std::string* main_file = nullptr;
    std::optional<Move> first;  // the target's first move
    for (;;) {
        InterpResult result = interpreter.next();
        if (auto* error = std::get_if<Diagnostic>(&result)) return std::move(*error);
        if (std::holds_alternative<ProgramEnd>(result)) break;
        Move& move = std::get<Move>(result);
        if (main_file == nullptr) main_file = move.where.file.get();
        const ModalView view = interpreter.modal_view();
        BlockKey key{move.where.file.get(), move.where.line, interpreter.output_batch()};
        if (!previous || !(key == *previous)) {
            ++blocks;
            previous = key;
            bool hit = false;
            switch (target.kind) {
                case RestartTarget::Kind::block:
                    hit = blocks == target.number;
                    break;
                case RestartTarget::Kind::line:
                    hit = key.file == main_file && move.where.line == target.number && ++hits == 1;
                    break;
                case RestartTarget::Kind::sequence:
                    hit = move.sequence_number == target.number && ++hits == target.occurrence;
                    break;
            }
            if (hit) {
                if (view.cutter_compensation && previous_comp) {
                    return error_at(
                        move.where, "restart-cutter-comp",
                        "the block lies inside cutter compensation (G41/G42): its start depends on the "
                        "blocks before it; restart at the block that switches compensation on or after G40");
                }
                if (std::holds_alternative<SyncMove>(move.what) && thread_start) {
                    return error_at(move.where, "restart-mid-thread",
                                    fmt::format("the block is in the middle of a thread pass; restart at the pass's "
                                                "start, {}{}",
                                                location_text(thread_start->where),
                                                thread_start->sequence_number >= 0
                                                    ? fmt::format(" (N{})", thread_start->sequence_number)
                                                    : std::string()));
                }
                report.where = move.where;
                report.sequence_number = move.sequence_number;
                report.block = blocks;
                report.first_record = records;
                first = std::move(move);
                break;
            }
        }
        ++records;
        report.state = view;
        previous_comp = view.cutter_compensation;
        if (const auto* io = std::get_if<Io>(&move.what)) note_io(*io, machine, report.io);
        if (const AxisVector* end = end_of(move)) {
            position = *end;
            note_directions(move, side);
            if (std::holds_alternative<SyncMove>(move.what)) {
                if (!thread_start) thread_start = move;
            } else {
                thread_start.reset();
            }
        }
    }
    if (!first) {
        const char* what = target.kind == RestartTarget::Kind::block  ? "block"
                           : target.kind == RestartTarget::Kind::line ? "line"
                                                                      : "N";
        std::string text = target.kind == RestartTarget::Kind::sequence
                               ? fmt::format("N{} is reached {} times, not {}", target.number, hits, target.occurrence)
                               : fmt::format("{} {} is not reached by a block that moves ({} blocks run)", what,
                                             target.number, blocks);
        return error_at(make_location(std::make_shared<const std::string>(source_name), 1, 1), "restart-not-reached",
                        std::move(text));
    }

    // The preamble and approach, then the target's moves and everything after them.
    GcodeWriter writer(machine);
    writer.round_to_decimals(decimals);
    bool preamble_written = false;
    std::optional<Move> pending = std::move(first);
    for (;;) {
        if (!pending) {
            InterpResult result = interpreter.next();
            if (auto* error = std::get_if<Diagnostic>(&result)) return std::move(*error);
            if (std::holds_alternative<ProgramEnd>(result)) break;
            pending = std::move(std::get<Move>(result));
        }
        if (!preamble_written) {
            preamble_written = true;
            RestartApproach& a = report.approach;
            a.retract_axis = retract_axis_of(machine);
            if (const AxisConfig* axis = machine.find(a.retract_axis)) a.safe_mm = axis->max;
            if (machine.restart_safe_mm) a.safe_mm = *machine.restart_safe_mm;
            // Moves are continuous: the target starts where the last motion before it ended.
            const AxisVector* start = start_of(*pending);
            a.moves = position.has_value() || start != nullptr;
            a.point = position ? *position : start != nullptr ? *start : AxisVector{};
            a.side = side;
            a.takeup_mm = takeup_mm;
            a.clearance_mm = clearance_mm;
            a.feed_mm_min = machine.restart_feed_mm_min;
            fmt::format_to(std::back_inserter(out), "( {} restarted by nckit at {}{}, block {} )\n",
                           std::filesystem::path(source_name).filename().string(), location_text(report.where),
                           report.sequence_number >= 0 ? fmt::format(" N{}", report.sequence_number) : std::string(),
                           report.block);
            writer.append_header(out, source_name);
            frame_comments(out, report.state, machine);
            io_blocks(out, report.io);
            if (a.moves) approach_blocks(out, a, machine, decimals, report.worst_deviation_mm);
            for (int m : report.io.laser_on) fmt::format_to(std::back_inserter(out), "M{}\n", m);
            const ModalView& s = report.state;
            fmt::format_to(std::back_inserter(out), "{} {}", plane_code(s.plane), feed_mode_code(s.feed_mode, machine));
            if (s.feed > 0) {
                out += " F";
                append_exact(out, s.feed);
            }
            if (s.path.exact_stop) {
                out += " G61";
            } else if (s.path.tolerance_mm > 0) {
                out += " G64 P";
                append_exact(out, s.path.tolerance_mm);
            } else {
                out += " G64";
            }
            out += "\n( the rest of the program from the target on )\n";
            writer.assume_modes(s.plane, s.feed_mode, s.feed > 0 ? s.feed : -1, s.path);
            report.rest_line = line_count(out) + 1;
        }
        writer.append(out, *pending);
        pending.reset();
    }
    writer.append_footer(out);
    report.worst_deviation_mm = std::max(report.worst_deviation_mm, writer.worst_deviation_mm());
    return report;
}

}  // namespace nckit
