// The corner between the held planar move and the next one: it settles where the held move ends
// and where the next one starts (and, on an outside corner, adds the path around it).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <fmt/format.h>

#include "cutter_comp_geometry.hpp"
#include "nckit/interp/arc_geometry.hpp"
#include "nckit/interp/cutter_comp.hpp"

namespace nckit {

using interp::comp::in_plane;
using interp::comp::set_in_plane;
using interp::comp::turn_of;

using interp::comp::Corner;
using interp::comp::Segment;

namespace {

constexpr double two_pi = 2.0 * std::numbers::pi;

//! The planar element a Line or Arc draws.
Segment segment_of(const Move& move, PlaneAxes p) {
    Segment s;
    if (const auto* arc = std::get_if<Arc>(&move.what)) {
        s.arc = true;
        s.start = in_plane(arc->from, p);
        s.end = in_plane(arc->to, p);
        s.center = in_plane(arc->center, p);
        s.turn = turn_of(*arc);
        return s;
    }
    const auto& line = std::get<Line>(move.what);
    s.start = in_plane(line.from, p);
    s.end = in_plane(line.to, p);
    return s;
}

//! Moves `move` to run from `from` to `to` in the plane, keeping its other axes. An arc keeps
//! its centre and takes the whole turns that bring its sweep closest to `programmed_sweep_rad`
//! (a full circle whose start moved a little is still a full circle).
void place(Move& move, PlaneAxes p, const AxisVector& from, Vec2 to, double programmed_sweep_rad) {
    if (auto* line = std::get_if<Line>(&move.what)) {
        line->from = from;
        set_in_plane(line->to, p, to);
        return;
    }
    auto& arc = std::get<Arc>(move.what);
    Vec2 center = in_plane(arc.center, p);
    arc.from = from;
    set_in_plane(arc.to, p, to);
    arc.center = from;
    set_in_plane(arc.center, p, center);
    arc.full_turns = 0;
    double sweep = arc_sweep_rad(arc);
    arc.full_turns = std::max(0, static_cast<int>(std::lround((programmed_sweep_rad - sweep) / two_pi)));
}

//! Points along a settled move in the plane, ends included.
std::vector<Vec2> samples_of(const Move& move, PlaneAxes p) {
    constexpr int n = 16;
    std::vector<Vec2> out;
    if (const auto* line = std::get_if<Line>(&move.what)) {
        Vec2 a = in_plane(line->from, p);
        Vec2 b = in_plane(line->to, p);
        for (int i = 0; i <= n; ++i) out.push_back(a + (static_cast<double>(i) / n) * (b - a));
        return out;
    }
    const auto& arc = std::get<Arc>(move.what);
    Vec2 c = in_plane(arc.center, p);
    Vec2 a = in_plane(arc.from, p);
    double r = nckit::length(a - c);
    double a0 = std::atan2(a.y - c.y, a.x - c.x);
    double sweep = std::min(arc_sweep_rad(arc), two_pi) * turn_of(arc);
    for (int i = 0; i <= n; ++i) {
        double angle = a0 + sweep * i / n;
        out.push_back({c.x + r * std::cos(angle), c.y + r * std::sin(angle)});
    }
    return out;
}

}  // namespace

std::optional<CompError> CutterCompensator::check_clearance(const Segment& element, const SourceLocation& where,
                                                            const char* which) const {
    // LinuxCNC checks only the corner itself: an element farther on may come nearer than r.
    if (linuxcnc_) return std::nullopt;
    // Interference beyond the corner: an arc cut from outside may bulge back toward the offset
    // of its neighbour. The settled move must keep r from both neighbouring contour elements.
    PlaneAxes p = plane_axes(plane_);
    // Corners within the tangent tolerance leave the next move's start up to r(1 - cos 0.05)
    // nearer than r: that much is allowed.
    // A move whose offset changed in it starts at the old radius: the smaller of the two holds.
    double limit = std::min(radius_mm_, held_from_radius_mm_) * std::cos(interp::comp::corner_tolerance_rad) - 1e-7;
    for (Vec2 point : samples_of(held_.front(), p)) {
        if (interp::comp::distance_to(point, element) < limit) {
            return error(where, "cutter-gouge",
                         fmt::format("cutter compensation would gouge: the tool (radius {:.4f} mm) on line {} "
                                     "comes closer than its radius to the contour of {}",
                                     radius_mm_, held_.front().where.line, which));
        }
    }
    return std::nullopt;
}

Segment CutterCompensator::Programmed::segment() const {
    Segment s;
    s.arc = arc;
    s.start = {start[0], start[1]};
    s.end = {end[0], end[1]};
    s.center = {center[0], center[1]};
    s.turn = turn;
    return s;
}

CutterCompensator::Programmed CutterCompensator::Programmed::straight(Vec2 start, Vec2 end, bool rapid) {
    Programmed p;
    p.start[0] = start.x;
    p.start[1] = start.y;
    p.end[0] = end.x;
    p.end[1] = end.y;
    p.rapid = rapid;
    return p;
}

std::optional<CompError> CutterCompensator::next_planar(Move move, std::vector<Move>& out) {
    if (linuxcnc_) return next_planar_linuxcnc(std::move(move), out);
    PlaneAxes p = plane_axes(plane_);
    const Segment a = programmed_.segment();
    Segment b = segment_of(move, p);
    const Vec2 corner = a.end;

    auto b_off = interp::comp::offset(b, side_, radius_mm_);
    if (!b_off) {
        return error(move.where, "cutter-gouge",
                     fmt::format("the tool radius {:.4f} mm is larger than the radius {:.4f} mm of this arc, "
                                 "which the tool cuts from inside",
                                 radius_mm_, nckit::length(b.start - b.center)));
    }
    auto a_off = interp::comp::offset(a, side_, radius_mm_);  // was checked when a came in
    Corner kind = interp::comp::classify(a, b, side_);
    Move& held = held_.front();
    Vec2 a_end =
        held.what.index() == 0 ? in_plane(std::get<Line>(held.what).to, p) : in_plane(std::get<Arc>(held.what).to, p);
    Vec2 b_start = b_off->start;
    bool around = false;
    if (held_start_up_ && startup_ == CompStartup::type_a && kind != Corner::inside) {
        a_end = b_off->start;  // type A: the start-up block ends where the next one's offset starts
    } else if (kind == Corner::tangent) {
        b_start = a_end;
    } else if (kind == Corner::outside) {
        around = true;
    } else {
        // After an arc shrunk to its centre the tool cannot turn further in: no crossing.
        auto meet = a_off && !interp::comp::shrunk_to_center(*a_off)
                        ? interp::comp::inside_corner(*a_off, *b_off, corner)
                        : std::nullopt;
        if (!meet) {
            return error(move.where, "cutter-gouge",
                         fmt::format("the tool (radius {:.4f} mm) cannot reach into the inside corner between "
                                     "line {} and this block without cutting the contour",
                                     radius_mm_, held.where.line));
        }
        a_end = *meet;
        b_start = *meet;
    }

    // Settle the held move and what followed it at the corner, then check it still runs forward.
    if (auto* line = std::get_if<Line>(&held.what)) {
        set_in_plane(line->to, p, a_end);
    } else {
        auto& arc = std::get<Arc>(held.what);
        place(held, p, arc.from, a_end, programmed_.sweep_rad);
    }
    if (auto e = check_held(move.where)) return e;
    if (!held_start_up_ && !held_restart_) {
        if (auto e = check_clearance(b, move.where, "this block")) return e;
    }
    if (has_before_ && !held_start_up_) {
        if (auto e = check_clearance(before_.segment(), move.where, "the block before it")) return e;
    }
    for (std::size_t i = 1; i < held_.size(); ++i) {
        if (auto* line = std::get_if<Line>(&held_[i].what)) {
            set_in_plane(line->from, p, a_end);
            set_in_plane(line->to, p, a_end);
        }
    }
    set_in_plane(tool_, p, a_end);
    emit_held(out);

    if (around) {
        // The tool rolls around the programmed corner point: an arc of radius r, or for a
        // rapid a straight traverse (there is no rapid arc), as LinuxCNC does.
        Move turn{Line{}, move.where, move.sequence_number};
        if (const auto* next_line = std::get_if<Line>(&move.what); next_line != nullptr && next_line->rapid) {
            Line rapid{tool_, tool_, Feed{}, true, next_line->path};
            set_in_plane(rapid.to, p, b_start);
            turn.what = rapid;
        } else {
            Arc arc;
            arc.from = tool_;
            arc.to = tool_;
            set_in_plane(arc.to, p, b_start);
            arc.center = tool_;
            set_in_plane(arc.center, p, corner);
            arc.plane = plane_;
            arc.direction = side_ > 0 ? ArcDirection::clockwise : ArcDirection::counterclockwise;
            if (const auto* line = std::get_if<Line>(&move.what)) {
                arc.feed = line->feed;
                arc.path = line->path;
            } else {
                arc.feed = std::get<Arc>(move.what).feed;
                arc.path = std::get<Arc>(move.what).path;
            }
            turn.what = arc;
        }
        emit(std::move(turn), false, out);
        set_in_plane(tool_, p, b_start);
    }

    // The new move is held with its provisional end r beside the contour.
    before_ = programmed_;
    has_before_ = !held_start_up_;
    const auto* programmed_arc = std::get_if<Arc>(&move.what);
    programmed_ = Programmed::straight(b.start, b.end, programmed_arc == nullptr && std::get<Line>(move.what).rapid);
    if (programmed_arc != nullptr) {
        programmed_.arc = true;
        programmed_.center[0] = b.center.x;
        programmed_.center[1] = b.center.y;
        programmed_.turn = b.turn;
        programmed_.sweep_rad = arc_sweep_rad(*programmed_arc);
    }
    AxisVector from = tool_;
    if (interp::comp::shrunk_to_center(*b_off)) {
        // The tool pivots at the arc's centre: what is left is the straight move of the other
        // axes (a helix's Z), or nothing.
        const Arc& arc = std::get<Arc>(move.what);
        move.what = Line{arc.from, arc.to, arc.feed, false, arc.path};
    }
    place(move, p, from, b_off->end, programmed_.sweep_rad);
    tool_ = move.what.index() == 0 ? std::get<Line>(move.what).to : std::get<Arc>(move.what).to;
    held_.push_back(std::move(move));
    held_start_up_ = false;
    held_restart_ = false;
    held_from_radius_mm_ = radius_mm_;
    return std::nullopt;
}

}  // namespace nckit
