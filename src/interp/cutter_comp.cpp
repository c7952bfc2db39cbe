// The compensation state machine: off → waiting (G41/G42 given, no move in the plane yet) →
// on (one planar move held) → exiting (G40 given, the next move leaves the contour) → off.
#include "nckit/interp/cutter_comp.hpp"

#include <cmath>

#include <fmt/format.h>

#include "cutter_comp_geometry.hpp"
#include "nckit/interp/arc_geometry.hpp"

namespace nckit {

using interp::comp::in_plane;
using interp::comp::set_in_plane;

using interp::comp::Segment;

namespace {

// Events and off-plane moves held behind one planar move; a program that piles up more than
// this while compensation is on has lost its contour.
constexpr std::size_t max_held = 100000;

}  // namespace

CompError CutterCompensator::error(const SourceLocation& where, std::string code, std::string message) const {
    return CompError{where, std::move(code), std::move(message)};
}

void CutterCompensator::start(CompSide side, double radius_mm, Plane plane, const AxisVector& tip_shift) {
    // G41 again before the exit move: the tool is still beside the old contour, and the next
    // move leaves from there.
    leave_from_tool_ = mode_ == Mode::exiting;
    if (leave_from_tool_) tool_ = tool_ + tip_shift_;  // where the tool really stands
    tip_shift_ = tip_shift;
    mode_ = Mode::waiting;
    side_ = side == CompSide::left ? 1 : -1;
    radius_mm_ = radius_mm;
    held_from_radius_mm_ = radius_mm;
    plane_ = plane;
    held_.clear();
    held_start_up_ = false;
    held_restart_ = false;
    has_before_ = false;
    endpoint_valid_ = false;
    pending_radius_mm_.reset();
    pending_restart_ = false;
}

void CutterCompensator::change_offset(double radius_mm, bool restart) {
    if (mode_ == Mode::waiting) {
        // No move in the plane yet: the start-up move takes the new radius.
        radius_mm_ = radius_mm;
        held_from_radius_mm_ = radius_mm;
        return;
    }
    pending_radius_mm_ = radius_mm;
    // A restart stays asked for when a D word alone follows it before the next planar move.
    pending_restart_ = pending_restart_ || restart;
}

bool CutterCompensator::moves_in_plane(const Move& move) const {
    if (std::holds_alternative<Arc>(move.what)) return true;
    const auto* line = std::get_if<Line>(&move.what);
    if (line == nullptr) return false;
    PlaneAxes p = plane_axes(plane_);
    // Exact comparison, as LinuxCNC: any plane motion at all makes a corner.
    return line->from[p.first] != line->to[p.first] || line->from[p.second] != line->to[p.second];
}

std::optional<CompError> CutterCompensator::add(Move move, std::vector<Move>& out) {
    const bool is_line = std::holds_alternative<Line>(move.what);
    const bool is_arc = std::holds_alternative<Arc>(move.what);
    if ((mode_ == Mode::waiting || mode_ == Mode::on) && std::holds_alternative<SyncMove>(move.what)) {
        return error(move.where, "cutter-comp", "threading (G32/G33) is not allowed with cutter compensation on");
    }
    switch (mode_) {
        case Mode::off:
            out.push_back(std::move(move));
            return std::nullopt;
        case Mode::exiting:
            if (is_arc) {
                return error(move.where, "cutter-comp",
                             "the move after G40 must be a straight line (G0/G1), not an arc");
            }
            if (auto* line = std::get_if<Line>(&move.what)) {
                line->from = tool_ + tip_shift_;  // from r beside the contour to the programmed point
                mode_ = Mode::off;
            } else if (auto* sync = std::get_if<SyncMove>(&move.what)) {
                sync->from = tool_ + tip_shift_;
                mode_ = Mode::off;
            }
            out.push_back(std::move(move));
            return std::nullopt;
        case Mode::waiting:
            if (is_arc && linuxcnc_) return start_up_on_arc(std::move(move));
            if (is_arc) {
                return error(move.where, "cutter-comp",
                             "cutter compensation cannot start on an arc: start it with a G0/G1 move in the plane");
            }
            // LinuxCNC takes the first straight move after G41/G42 as the start-up move even
            // when it does not move in the plane (a Z plunge): too short, an error there.
            if (is_line && (moves_in_plane(move) || linuxcnc_)) return start_up(std::move(move), out);
            if (leave_from_tool_) {
                if (auto* line = std::get_if<Line>(&move.what)) {
                    line->from = tool_;
                    leave_from_tool_ = false;
                }
            }
            out.push_back(std::move(move));
            return std::nullopt;
        case Mode::on:
            if (held_.size() >= max_held) {
                return error(move.where, "cutter-comp",
                             fmt::format("more than {} blocks without a move in the plane while cutter "
                                         "compensation is on",
                                         max_held));
            }
            if (moves_in_plane(move)) {
                if (pending_radius_mm_) return next_with_new_offset(std::move(move), out);
                return next_planar(std::move(move), out);
            }
            if (is_line) {
                hold_off_plane(std::move(move));
            } else {
                held_.push_back(std::move(move));
            }
            return std::nullopt;
    }
    return std::nullopt;
}

std::optional<CompError> CutterCompensator::start_up(Move move, std::vector<Move>& out) {
    (void)out;
    auto& line = std::get<Line>(move.what);
    PlaneAxes p = plane_axes(plane_);
    Vec2 from = in_plane(line.from, p);
    Vec2 to = in_plane(line.to, p);
    double distance = nckit::length(to - from);
    // LinuxCNC refuses a start-up move not longer than r, but compares against a radius that
    // has been through its units' round trip: a move exactly r long (to rounding) runs there.
    const bool too_short = linuxcnc_ ? distance < radius_mm_ - 1e-9 : distance <= radius_mm_;
    if (too_short) {
        return error(move.where, "cutter-comp",
                     fmt::format("the start-up move is {:.4f} mm long in the plane, not longer than the tool "
                                 "radius {:.4f} mm",
                                 distance, radius_mm_));
    }
    programmed_ = Programmed::straight(from, to, line.rapid);
    Vec2 normal = static_cast<double>(side_) * nckit::left_normal(nckit::unit(to - from));
    set_in_plane(line.to, p, to + radius_mm_ * normal);
    if (leave_from_tool_) line.from = tool_;  // the geometry stays the programmed one, as LinuxCNC
    leave_from_tool_ = false;
    tool_ = line.to;
    // LinuxCNC checks the start-up move later against its start and the direction square to it.
    endpoint_ = from;
    endpoint_valid_ = true;
    held_direction_ = normal;
    held_.clear();
    held_.push_back(std::move(move));
    held_start_up_ = true;
    held_restart_ = false;
    held_from_radius_mm_ = radius_mm_;
    mode_ = Mode::on;
    return std::nullopt;
}

void CutterCompensator::hold_off_plane(Move move) {
    auto& line = std::get<Line>(move.what);
    PlaneAxes p = plane_axes(plane_);
    Vec2 at = in_plane(tool_, p);
    set_in_plane(line.from, p, at);
    set_in_plane(line.to, p, at);
    tool_ = line.to;
    held_.push_back(std::move(move));
}

std::optional<CompError> CutterCompensator::check_held(const SourceLocation& next) const {
    const Move& held = held_.front();
    PlaneAxes p = plane_axes(plane_);
    auto near_line = [&] { return next.line != 0 ? fmt::format(" (corner with line {})", next.line) : std::string(); };
    if (const auto* line = std::get_if<Line>(&held.what)) {
        Vec2 programmed{programmed_.end[0] - programmed_.start[0], programmed_.end[1] - programmed_.start[1]};
        Vec2 actual = in_plane(line->to, p) - in_plane(line->from, p);
        if (nckit::dot(programmed, actual) < 0) {
            return error(held.where, "cutter-gouge",
                         fmt::format("cutter compensation would gouge: the tool radius {:.4f} mm is too large "
                                     "for this move, the compensated path runs backwards{}",
                                     radius_mm_, near_line()));
        }
        return std::nullopt;
    }
    const auto& arc = std::get<Arc>(held.what);
    double sweep = arc_sweep_rad(arc);
    if (sweep > programmed_.sweep_rad + interp::comp::corner_tolerance_rad) {
        return error(held.where, "cutter-gouge",
                     fmt::format("cutter compensation would gouge: the tool radius {:.4f} mm is too large "
                                 "for this arc, its compensated path runs past its end{}",
                                 radius_mm_, near_line()));
    }
    return std::nullopt;
}

std::optional<CompError> CutterCompensator::release(std::vector<Move>& out) {
    if (held_.empty()) return std::nullopt;
    if (linuxcnc_) {
        // LinuxCNC settles the held move where it is, with its checks, and forgets its start.
        auto e = settle_linuxcnc(in_plane(tool_, plane_axes(plane_)), SourceLocation{}, out);
        endpoint_valid_ = false;
        return e;
    }
    if (auto e = check_held(SourceLocation{})) return e;
    if (has_before_ && !held_start_up_) {
        if (auto e = check_clearance(before_.segment(), held_.front().where, "the block before it")) return e;
    }
    emit_held(out);
    held_start_up_ = false;
    held_restart_ = false;
    return std::nullopt;
}

void CutterCompensator::emit_held(std::vector<Move>& out) {
    for (std::size_t i = 0; i < held_.size(); ++i) emit(std::move(held_[i]), i == 0 && held_start_up_, out);
    held_.clear();
}

void CutterCompensator::emit(Move move, bool keep_start, std::vector<Move>& out) const {
    if (auto* line = std::get_if<Line>(&move.what)) {
        if (!keep_start) line->from = line->from + tip_shift_;
        line->to = line->to + tip_shift_;
    } else if (auto* arc = std::get_if<Arc>(&move.what)) {
        arc->from = arc->from + tip_shift_;
        arc->to = arc->to + tip_shift_;
        arc->center = arc->center + tip_shift_;
    }
    out.push_back(std::move(move));
}

std::optional<CompError> CutterCompensator::cancel(std::vector<Move>& out) {
    pending_radius_mm_.reset();  // the exit move leaves from where the held move ends
    pending_restart_ = false;
    if (mode_ == Mode::waiting) {
        mode_ = Mode::off;
        return std::nullopt;
    }
    if (mode_ != Mode::on) return std::nullopt;
    if (auto e = release(out)) return e;
    mode_ = Mode::exiting;
    return std::nullopt;
}

std::optional<AxisVector> CutterCompensator::take_exit_position() {
    if (mode_ != Mode::exiting) return std::nullopt;
    mode_ = Mode::off;
    return tool_ + tip_shift_;
}

std::optional<CompError> CutterCompensator::finish(std::vector<Move>& out) {
    pending_radius_mm_.reset();
    pending_restart_ = false;
    if (mode_ == Mode::on) {
        if (auto e = release(out)) return e;
    }
    mode_ = Mode::off;
    return std::nullopt;
}

}  // namespace nckit
