#include "canon_output.hpp"

#include <string>

#include <fmt/format.h>

#include "linuxcnc_headers.hpp"
#include "nckit/interp/arc_geometry.hpp"

namespace nckit::lcnc {

namespace {

constexpr double mm_per_inch = 25.4;
constexpr double m_per_foot = 0.3048;
//! LinuxCNC's constant surface speed limit when the program gives none (G96 without D / G50 S).
constexpr double unlimited_css_rpm = 1e30;

CANON_PLANE canon_plane(Plane plane) {
    switch (plane) {
        case Plane::xy:
            return CANON_PLANE_XY;
        case Plane::zx:
            return CANON_PLANE_XZ;
        case Plane::yz:
            return CANON_PLANE_YZ;
    }
    return CANON_PLANE_XY;
}

}  // namespace

CanonOutput::CanonOutput(const MachineConfig& machine, double g64_tolerance_mm, bool exact_path, bool line_comments)
    : machine_(machine), g64_tolerance_mm_(g64_tolerance_mm), exact_path_(exact_path), line_comments_(line_comments) {}

double CanonOutput::program(std::size_t i, double machine_value) const {
    double v = machine_value - (*work_offset_)[i] - (*g92_offset_)[i];
    return is_rotary(static_cast<Axis>(i)) ? v : v / *length_factor_mm_;
}

void CanonOutput::set_frame(const ModalView& view) {
    if (length_factor_mm_ != view.length_factor_mm) {
        USE_LENGTH_UNITS(view.length_factor_mm == mm_per_inch ? CANON_UNITS_INCHES : CANON_UNITS_MM);
        length_factor_mm_ = view.length_factor_mm;
        // Offsets are given in the units in force: send them again in the new ones.
        work_offset_.reset();
        g92_offset_.reset();
    }
    const double f = view.length_factor_mm;
    auto unit = [f](const AxisVector& v, std::size_t i) { return is_rotary(static_cast<Axis>(i)) ? v[i] : v[i] / f; };
    if (work_system_ != view.work_system || work_offset_ != view.work_offset) {
        const AxisVector& o = view.work_offset;
        SET_G5X_OFFSET(static_cast<int>(view.work_system) + 1, unit(o, 0), unit(o, 1), unit(o, 2), unit(o, 3),
                       unit(o, 4), unit(o, 5), unit(o, 6), unit(o, 7), unit(o, 8));
        work_system_ = view.work_system;
        work_offset_ = view.work_offset;
    }
    // LinuxCNC has one shift on top of the work offset: G92 and G52 both go there (its own
    // interpreter reports G52 as a G92 offset as well).
    AxisVector shift = view.g92_offset + view.g52_offset;
    if (g92_offset_ != shift) {
        SET_G92_OFFSET(unit(shift, 0), unit(shift, 1), unit(shift, 2), unit(shift, 3), unit(shift, 4), unit(shift, 5),
                       unit(shift, 6), unit(shift, 7), unit(shift, 8));
        g92_offset_ = shift;
    }
    if (plane_ != view.plane) {
        SELECT_PLANE(canon_plane(view.plane));
        plane_ = view.plane;
    }
}

void CanonOutput::set_path(const PathControl& path) {
    if (path_ && path_->exact_stop == path.exact_stop && path_->tolerance_mm == path.tolerance_mm) return;
    if (path.exact_stop) {
        SET_MOTION_CONTROL_MODE(CANON_EXACT_STOP, 0);
    } else if (exact_path_) {
        // LinuxCNC's G61: no blend at any corner (its blends leave the path by more than the G64
        // tolerance, see docs/linuxcnc-plugin.md); nearly tangent joins still keep their speed.
        SET_MOTION_CONTROL_MODE(CANON_EXACT_PATH, 0);
    } else {
        double tolerance_mm = path.tolerance_mm > 0 ? path.tolerance_mm : g64_tolerance_mm_;
        double tolerance = tolerance_mm / *length_factor_mm_;
        SET_MOTION_CONTROL_MODE(CANON_CONTINUOUS, tolerance);
        // Collinear segments are merged within the same bound (LinuxCNC's G64 P without Q).
        SET_NAIVECAM_TOLERANCE(tolerance);
    }
    path_ = path;
}

void CanonOutput::set_feed(const Feed& feed) {
    if (feed_mode_ != feed.mode) {
        SET_FEED_MODE(0, feed.mode == FeedMode::per_revolution ? 1 : 0);
        feed_mode_ = feed.mode;
        feed_rate_.reset();
    }
    double rate = (feed.mode == FeedMode::per_revolution ? feed.mm_per_rev : feed.mm_per_min) / *length_factor_mm_;
    if (feed_rate_ != rate) {
        SET_FEED_RATE(rate);
        feed_rate_ = rate;
    }
}

void CanonOutput::mark_line(const Move& move) {
    if (!line_comments_ || move.where.line == last_line_) return;
    last_line_ = move.where.line;
    COMMENT(fmt::format("nckit-line {}", move.where.line).c_str());
}

void CanonOutput::straight(const Line& line, int source_line) {
    set_path(line.path);
    const AxisVector& p = line.to;
    auto v = [&](std::size_t i) { return program(i, p[i]); };
    if (line.rapid) {
        STRAIGHT_TRAVERSE(source_line, v(0), v(1), v(2), v(3), v(4), v(5), v(6), v(7), v(8));
    } else {
        set_feed(line.feed);
        STRAIGHT_FEED(source_line, v(0), v(1), v(2), v(3), v(4), v(5), v(6), v(7), v(8));
    }
}

void CanonOutput::arc(const Arc& arc, int source_line) {
    set_path(arc.path);
    set_feed(arc.feed);
    PlaneAxes axes = plane_axes(arc.plane);
    auto v = [&](std::size_t i) { return program(i, arc.to[i]); };
    auto c = [&](Axis a) { return program(index(a), arc.center[a]); };
    int turns = arc.full_turns + 1;
    int rotation = arc.direction == ArcDirection::counterclockwise ? turns : -turns;
    ARC_FEED(source_line, v(index(axes.first)), v(index(axes.second)), c(axes.first), c(axes.second), rotation,
             v(index(axes.normal)), v(3), v(4), v(5), v(6), v(7), v(8));
}

void CanonOutput::sync(const SyncMove& move, int source_line) {
    set_path(PathControl{});
    auto v = [&](std::size_t i) { return program(i, move.to[i]); };
    // As LinuxCNC's own G33: synchronised for this one move, the lead in program units per turn.
    START_SPEED_FEED_SYNCH(0, move.feed.mm_per_rev / *length_factor_mm_, false);
    STRAIGHT_FEED(source_line, v(0), v(1), v(2), v(3), v(4), v(5), v(6), v(7), v(8));
    STOP_SPEED_FEED_SYNCH();
    // Stopping the synchronisation also ends G95's: the next feed move sets its rate again.
    feed_rate_.reset();
}

void CanonOutput::spindle_speed(double value, bool constant_surface_speed, double rpm_clamp) {
    double css_max = constant_surface_speed ? (rpm_clamp > 0 ? rpm_clamp : unlimited_css_rpm) : 0.0;
    if (css_maximum_rpm_ != css_max) {
        SET_SPINDLE_MODE(0, css_max);
        css_maximum_rpm_ = css_max;
        spindle_value_.reset();
    }
    // Surface speed goes in the program's units: m/min, or ft/min under G20.
    double speed = constant_surface_speed && *length_factor_mm_ == mm_per_inch ? value / m_per_foot : value;
    if (spindle_value_ != speed) {
        SET_SPINDLE_SPEED(0, speed);
        spindle_value_ = speed;
    }
}

void CanonOutput::message(const std::string& text) {
    std::string copy = text;  // MESSAGE takes a char*, not a const one
    MESSAGE(copy.data());
}

AfterMove CanonOutput::io(const Io& io) {
    switch (io.kind) {
        case IoKind::spindle_speed:
            spindle_speed(io.value, io.constant_surface_speed, io.rpm_clamp);
            return AfterMove::go_on;
        case IoKind::tool_select:
            tool_ = io.number;
            SELECT_TOOL(io.number);
            return AfterMove::go_on;
        case IoKind::mcode:
            break;
    }
    switch (io.number) {
        case 0:
            PROGRAM_STOP();
            break;
        case 1:
            OPTIONAL_PROGRAM_STOP();
            break;
        case 2:
        case 30:
            break;  // the program end that follows issues the calls
        case 3:
        case 4:
            spindle_speed(io.value, io.constant_surface_speed, io.rpm_clamp);
            if (io.number == 3) {
                START_SPINDLE_CLOCKWISE(0);
            } else {
                START_SPINDLE_COUNTERCLOCKWISE(0);
            }
            spindle_direction_ = io.number == 3 ? 1 : -1;
            break;
        case 5:
            STOP_SPINDLE_TURNING(0);
            spindle_direction_ = 0;
            break;
        case 6:
            CHANGE_TOOL(tool_);
            return AfterMove::wait_for_motion;
        case 7:
            MIST_ON();
            mist_ = true;
            break;
        case 8:
            FLOOD_ON();
            flood_ = true;
            break;
        case 9:
            MIST_OFF();
            FLOOD_OFF();
            mist_ = flood_ = false;
            break;
        case 48:
            ENABLE_FEED_OVERRIDE();
            ENABLE_SPEED_OVERRIDE(0);
            break;
        case 49:
            DISABLE_FEED_OVERRIDE();
            DISABLE_SPEED_OVERRIDE(0);
            break;
        case 60:
            PALLET_SHUTTLE();
            PROGRAM_STOP();
            break;
        default:
            // A machine's own M-code (laser, clamp...) has no canonical call: it is left visible.
            COMMENT(fmt::format("nckit: M{} has no LinuxCNC canonical call", io.number).c_str());
            break;
    }
    return AfterMove::go_on;
}

AfterMove CanonOutput::emit(const Move& move, const ModalView& view) {
    set_frame(view);
    mark_line(move);
    const int line = static_cast<int>(move.where.line);
    return std::visit(
        [&](const auto& what) {
            using T = std::decay_t<decltype(what)>;
            if constexpr (std::is_same_v<T, Line>) {
                straight(what, line);
            } else if constexpr (std::is_same_v<T, Arc>) {
                arc(what, line);
            } else if constexpr (std::is_same_v<T, SyncMove>) {
                sync(what, line);
            } else if constexpr (std::is_same_v<T, Dwell>) {
                DWELL(what.seconds);
            } else {
                return io(what);
            }
            return AfterMove::go_on;
        },
        move.what);
}

void CanonOutput::emit_program_end() {
    // As LinuxCNC's M2: the machine is left with the spindle and coolant off, feed per minute.
    if (feed_mode_ == FeedMode::per_revolution) SET_FEED_MODE(0, 0);
    STOP_SPINDLE_TURNING(0);
    MIST_OFF();
    FLOOD_OFF();
    PROGRAM_END();
    spindle_direction_ = 0;
    mist_ = flood_ = false;
}

}  // namespace nckit::lcnc
