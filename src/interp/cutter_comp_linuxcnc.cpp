// The corners of cutter compensation as LinuxCNC makes them (the LinuxCNC dialect). Its
// interpreter holds the last compensated move and, at the next planar move, either leaves its
// end where it is (a tangent or outside corner, with an arc around an outside one) or moves it
// back to a point of an inside corner and checks that the move still runs forward. Which
// crossing of two offsets it takes, and the radii it reads, follow its own construction:
// - the corner's kind comes from the angle between the direction the held move ends in (read
//   from the tool's position beside its programmed end) and the next move's start direction,
//   with a tolerance of 0.05 rad; beside an arc cut from outside, a reversal is an inside
//   corner (the tool stays above an "h" shape instead of looping around);
// - an inside corner's point is one branch of the crossing chosen by the arcs' directions, not
//   the crossing nearest the programmed corner, and radii are taken at arcs' end points (the
//   held arc's compensated end, the next arc's programmed end);
// - the held move may not turn back: a line whose settled end lies behind its start (along its
//   programmed direction), an arc that would sweep more than programmed plus 0.0254 rad (mm
//   programs) or 0.001 rad (inch programs), are gouges.
// The Fanuc dialect keeps nckit's own corners and stricter checks (cutter_comp_corner.cpp).
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "cutter_comp_geometry.hpp"
#include "nckit/interp/arc_geometry.hpp"
#include "nckit/interp/cutter_comp.hpp"

namespace nckit {

using interp::comp::in_plane;
using interp::comp::set_in_plane;
using interp::comp::turn_of;

namespace {

constexpr double pi = std::numbers::pi;
constexpr double half_pi = pi / 2;
// Corners closer than this to tangent, or to a reversal, are taken as such (rad).
constexpr double corner_rad = 0.05;
// An inside arc of the tool's radius (to rounding) leaves the tool on its centre (mm): LinuxCNC
// runs it because its radius has been through a unit round trip a little under the arc's.
constexpr double same_radius_mm = 1e-9;

double angle_of(Vec2 v) {
    return std::atan2(v.y, v.x);
}

Vec2 direction(double angle_rad) {
    return {std::cos(angle_rad), std::sin(angle_rad)};
}

//! The tool (side +1 left, -1 right) runs inside an arc turning `turn`.
bool inside(int side, int turn) {
    return side * turn > 0;
}

}  // namespace

std::optional<CompError> CutterCompensator::next_planar_linuxcnc(Move move, std::vector<Move>& out) {
    if (std::holds_alternative<Arc>(move.what)) return next_arc_linuxcnc(std::move(move), out);
    return next_line_linuxcnc(std::move(move), out);
}

std::optional<CompError> CutterCompensator::next_line_linuxcnc(Move move, std::vector<Move>& out) {
    const PlaneAxes p = plane_axes(plane_);
    const Line& line = std::get<Line>(move.what);
    const Vec2 op{programmed_.end[0], programmed_.end[1]};  // the programmed corner
    const Vec2 tool = in_plane(tool_, p);
    const Vec2 target = in_plane(line.to, p);
    const double r = radius_mm_;
    const bool left = side_ > 0;
    const Arc* before = std::get_if<Arc>(&held_.front().what);

    // theta: the tool's direction from the corner, square to the held move's end; alpha: the
    // line's direction. beta is the turn away from the tool's side, in [-π/2, 3π/2).
    double theta = angle_of(tool - op);
    double alpha = angle_of(target - op);
    double beta = 0;
    if (left) {
        if (theta < alpha) theta += 2 * pi;
        beta = theta - alpha - half_pi;
    } else {
        if (alpha < theta) alpha += 2 * pi;
        beta = alpha - theta - half_pi;
    }
    const double gamma = left ? half_pi : -half_pi;
    const Vec2 end = target + r * direction(alpha + gamma);
    const Vec2 around_to = op + r * direction(alpha + gamma);
    const bool outside_before = before != nullptr && !inside(side_, turn_of(*before));
    const bool concave = beta < -corner_rad || beta > pi + corner_rad || (beta > pi - corner_rad && outside_before);

    if (!concave && beta > corner_rad) {
        if (auto e = settle_linuxcnc(tool, move.where, out)) return e;
        go_around(move, op, around_to, out);
    } else if (concave && before == nullptr) {
        // Line to line: back along the held line by r over the tangent of half the inside angle.
        const double half_corner = (beta + pi) / 2;
        if (half_corner == 0)
            return error(move.where, "cutter-gouge", "a zero degree inside corner is invalid for cutter compensation");
        const Vec2 meet = tool + (r / std::tan(half_corner)) * direction(theta + gamma);
        if (auto e = settle_linuxcnc(meet, move.where, out)) return e;
    } else if (concave) {
        // Arc to line: where the line's offset meets the held arc's offset circle, whose radius
        // is read at the arc's compensated end.
        const Vec2 center = in_plane(before->center, p);
        const int turn = turn_of(*before);
        const double old_radius = nckit::length(center - tool);
        const double across = angle_of(target - op) + (turn > 0 ? half_pi : -half_pi);
        const bool was_inside = inside(side_, turn);
        const double programmed_radius = was_inside ? old_radius + r : old_radius - r;
        const double d = programmed_radius * std::cos(across - angle_of(center - op));
        const double l = old_radius == 0 ? 2.0 : (was_inside ? d - r : d + r) / old_radius;
        if (l > 1.0 || l < -1.0) {
            return error(move.where, "cutter-gouge",
                         fmt::format("the arc to straight motion makes a corner the tool (radius {:.4f} mm) cannot "
                                     "fit in without gouging",
                                     r));
        }
        const double sign = (was_inside == (turn > 0)) ? -1.0 : 1.0;
        const Vec2 meet = center + old_radius * direction(sign * std::acos(l) + across + pi);
        if (auto e = settle_linuxcnc(meet, move.where, out)) return e;
    } else {
        pass_linuxcnc(out);
    }
    held_direction_ = target - op;
    hold_linuxcnc(std::move(move), end);
    return std::nullopt;
}

std::optional<CompError> CutterCompensator::next_arc_linuxcnc(Move move, std::vector<Move>& out) {
    const PlaneAxes p = plane_axes(plane_);
    const Arc& arc = std::get<Arc>(move.what);
    const Vec2 op{programmed_.end[0], programmed_.end[1]};
    const Vec2 tool = in_plane(tool_, p);
    const Vec2 e = in_plane(arc.to, p);  // the programmed end
    const Vec2 center = in_plane(arc.center, p);
    const int turn = turn_of(arc);
    const double r = radius_mm_;
    const bool left = side_ > 0;
    const bool tool_inside = inside(side_, turn);
    const Arc* before = std::get_if<Arc>(&held_.front().what);

    // The arc's radius at its end; theta the held move's direction at the corner, alpha the
    // arc's at its start, beta the turn away from the tool's side, in (-π/2, 3π/2].
    const double arc_radius = nckit::length(center - e);
    const double theta = angle_of(tool - op) + (left ? -half_pi : half_pi);
    double delta = angle_of(center - op);
    const double alpha = turn > 0 ? delta - half_pi : delta + half_pi;
    double beta = left ? theta - alpha : alpha - theta;
    if (beta > 1.5 * pi) {
        beta -= 2 * pi;
    } else if (beta < -half_pi) {
        beta += 2 * pi;
    }
    double gamma = 0;
    if (tool_inside) {
        if (arc_radius < r - same_radius_mm) {
            return error(move.where, "cutter-gouge",
                         fmt::format("the tool radius {:.4f} mm is not less than the radius {:.4f} mm of this arc, "
                                     "which the tool cuts from inside",
                                     r, arc_radius));
        }
        gamma = angle_of(center - e);
    } else {
        gamma = angle_of(e - center);
        delta += pi;
    }
    const Vec2 end = e + r * direction(gamma);
    const bool concave =
        beta < -corner_rad || beta > pi + corner_rad || (std::abs(beta - pi) < corner_rad && !tool_inside);

    if (concave && before == nullptr) {
        // Line to arc: where the line's offset meets the arc's offset circle.
        const double offset = arc_radius * std::sin(beta - half_pi);
        const double reach = tool_inside ? arc_radius - r : arc_radius + r;
        const double l = reach <= 0 ? 2.0 : (tool_inside ? offset + r : offset - r) / reach;
        if (l > 1.0 || l < -1.0) {
            return error(move.where, "cutter-gouge",
                         fmt::format("the arc in this concave corner cannot be reached by the tool (radius {:.4f} "
                                     "mm) without gouging",
                                     r));
        }
        double angle = 0;
        if (tool_inside) {
            angle = turn > 0 ? theta + std::asin(l) : theta - std::asin(l);
        } else {
            angle = turn > 0 ? theta + pi - std::asin(l) : theta + pi + std::asin(l);
        }
        if (auto err = settle_linuxcnc(center + reach * direction(angle), move.where, out)) return err;
    } else if (concave) {
        // Arc to arc: the crossing of the two offset circles, the held one's radius read at its
        // compensated end, the next one's at its programmed end.
        const Vec2 before_center = in_plane(before->center, p);
        const double old_radius = nckit::length(before_center - tool);
        const double new_radius = tool_inside ? arc_radius - r : arc_radius + r;
        const double apart = nckit::length(before_center - center);
        if (old_radius == 0 || apart == 0) {
            return error(move.where, "cutter-comp",
                         "arc to arc motion is invalid because the arcs have the same center");
        }
        const double a = (old_radius * old_radius + apart * apart - new_radius * new_radius) / (2 * old_radius * apart);
        if (a > 1.0 || a < -1.0) {
            return error(move.where, "cutter-gouge",
                         fmt::format("the arc to arc motion makes a corner the tool (radius {:.4f} mm) cannot fit in "
                                     "without gouging",
                                     r));
        }
        const double pullback = std::acos(a);
        const bool was_inside = inside(side_, turn_of(*before));
        const double sign = (was_inside == (turn > 0)) ? 1.0 : -1.0;
        const Vec2 meet = before_center + old_radius * direction(angle_of(center - before_center) + sign * pullback);
        if (auto err = settle_linuxcnc(meet, move.where, out)) return err;
    } else if (beta > corner_rad) {
        pass_linuxcnc(out);
        go_around(move, op, op + r * direction(delta), out);
    } else {
        pass_linuxcnc(out);
    }
    // An arc of the tool's radius cut from inside: the tool stays on its centre, where it
    // stands, as an arc of radius 0 (a straight move of the other axes, a helix's Z, in space).
    if (tool_inside && arc_radius - r <= same_radius_mm) {
        const Vec2 at = in_plane(tool_, p);
        hold_linuxcnc(std::move(move), at);
        set_in_plane(std::get<Arc>(held_.back().what).center, p, at);
        return std::nullopt;
    }
    hold_linuxcnc(std::move(move), end);
    return std::nullopt;
}

std::optional<CompError> CutterCompensator::settle_linuxcnc(Vec2 to, const SourceLocation& where,
                                                            std::vector<Move>& out) {
    const PlaneAxes p = plane_axes(plane_);
    Move& held = held_.front();
    const SourceLocation& at = where.line != 0 ? where : held.where;
    const double unit_mm = inch_ ? 25.4 : 1.0;
    if (auto* arc = std::get_if<Arc>(&held.what)) {
        const Vec2 center = in_plane(arc->center, p);
        const double before_mm = nckit::length(in_plane(arc->to, p) - center);
        if (std::abs(before_mm - nckit::length(to - center)) > 0.01 * unit_mm) {
            return error(
                at, "cutter-comp",
                fmt::format("cutter compensation would change the radius of the arc of line {}", held.where.line));
        }
        if (endpoint_valid_ && programmed_.sweep_rad != 0) {
            const double sweep = interp::comp::sweep_rad(endpoint_, to, center, turn_of(*arc)) +
                                 2 * pi * static_cast<double>(arc->full_turns);
            const double tolerance_rad = inch_ ? 0.001 : 0.0254;
            if (sweep > programmed_.sweep_rad + tolerance_rad) {
                return error(at, "cutter-gouge",
                             fmt::format("cutter compensation would gouge: the arc of line {} in this concave corner "
                                         "cannot be reached by the tool (radius {:.4f} mm)",
                                         held.where.line, radius_mm_));
            }
        }
        set_in_plane(arc->to, p, to);
    } else {
        auto& line = std::get<Line>(held.what);
        if (endpoint_valid_ && nckit::dot(held_direction_, to - endpoint_) < 0) {
            return error(at, "cutter-gouge",
                         fmt::format("cutter compensation would gouge: the straight move of line {} in this concave "
                                     "corner cannot be reached by the tool (radius {:.4f} mm), it would run backwards",
                                     held.where.line, radius_mm_));
        }
        set_in_plane(line.to, p, to);
    }
    for (std::size_t i = 1; i < held_.size(); ++i) {
        if (auto* line = std::get_if<Line>(&held_[i].what)) {
            set_in_plane(line->from, p, to);
            set_in_plane(line->to, p, to);
        }
    }
    set_in_plane(tool_, p, to);
    emit_held(out);
    held_start_up_ = false;
    endpoint_ = to;
    endpoint_valid_ = true;
    return std::nullopt;
}

void CutterCompensator::pass_linuxcnc(std::vector<Move>& out) {
    emit_held(out);
    held_start_up_ = false;
    endpoint_ = in_plane(tool_, plane_axes(plane_));
    endpoint_valid_ = true;
}

void CutterCompensator::go_around(const Move& next, Vec2 corner, Vec2 to, std::vector<Move>& out) {
    const PlaneAxes p = plane_axes(plane_);
    // The corner move carries the block's other axes (A, B, C ...) to their end, as LinuxCNC's;
    // the axis normal to the plane stays.
    AxisVector until = tool_;
    const AxisVector& next_to = next.what.index() == 0 ? std::get<Line>(next.what).to : std::get<Arc>(next.what).to;
    for (std::size_t i = 0; i < axis_count; ++i) {
        const Axis axis = static_cast<Axis>(i);
        if (axis != p.first && axis != p.second && axis != p.normal) until[i] = next_to[i];
    }
    set_in_plane(until, p, to);
    Move turn{Line{}, next.where, next.sequence_number};
    const auto* next_line = std::get_if<Line>(&next.what);
    if (next_line != nullptr && next_line->rapid) {
        turn.what = Line{tool_, until, Feed{}, true, next_line->path};
    } else {
        Arc arc;
        arc.from = tool_;
        arc.to = until;
        arc.center = tool_;
        set_in_plane(arc.center, p, corner);
        arc.plane = plane_;
        arc.direction = side_ > 0 ? ArcDirection::clockwise : ArcDirection::counterclockwise;
        arc.feed = next_line != nullptr ? next_line->feed : std::get<Arc>(next.what).feed;
        arc.path = next_line != nullptr ? next_line->path : std::get<Arc>(next.what).path;
        turn.what = arc;
    }
    emit(std::move(turn), false, out);
    tool_ = until;
    endpoint_ = to;
    endpoint_valid_ = true;
}

void CutterCompensator::hold_linuxcnc(Move move, Vec2 end) {
    const PlaneAxes p = plane_axes(plane_);
    before_ = programmed_;
    has_before_ = !held_start_up_;
    programmed_ = Programmed{};
    if (auto* arc = std::get_if<Arc>(&move.what)) {
        const Vec2 start = in_plane(arc->from, p);
        programmed_ = Programmed::straight(start, in_plane(arc->to, p), false);
        programmed_.arc = true;
        const Vec2 center = in_plane(arc->center, p);
        programmed_.center[0] = center.x;
        programmed_.center[1] = center.y;
        programmed_.turn = turn_of(*arc);
        programmed_.sweep_rad = arc_sweep_rad(*arc);
        // The compensated arc keeps its centre and its turns, from where the tool is.
        const Vec2 held_center = in_plane(arc->center, p);
        arc->from = tool_;
        set_in_plane(arc->to, p, end);
        arc->center = tool_;
        set_in_plane(arc->center, p, held_center);
        tool_ = arc->to;
    } else {
        auto& line = std::get<Line>(move.what);
        programmed_ = Programmed::straight(in_plane(line.from, p), in_plane(line.to, p), line.rapid);
        line.from = tool_;
        set_in_plane(line.to, p, end);
        tool_ = line.to;
    }
    held_.push_back(std::move(move));
    held_start_up_ = false;
    held_restart_ = false;
    held_from_radius_mm_ = radius_mm_;
}

}  // namespace nckit
