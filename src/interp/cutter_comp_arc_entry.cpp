// LinuxCNC's start of cutter compensation on an arc (the LinuxCNC dialect): the arc runs from
// where the tool stands to its end point moved r along the radius (toward the centre when the
// tool is inside the arc, away from it outside), about a new centre on the line from that end
// to the programmed centre, as far from the start as from the end.
#include <cmath>

#include <fmt/format.h>

#include "cutter_comp_geometry.hpp"
#include "nckit/interp/arc_geometry.hpp"
#include "nckit/interp/cutter_comp.hpp"

namespace nckit {

using interp::comp::in_plane;
using interp::comp::set_in_plane;
using interp::comp::turn_of;

std::optional<CompError> CutterCompensator::start_up_on_arc(Move move) {
    auto& arc = std::get<Arc>(move.what);
    const PlaneAxes p = plane_axes(plane_);
    const Vec2 from = in_plane(arc.from, p);
    const Vec2 end = in_plane(arc.to, p);
    const Vec2 center = in_plane(arc.center, p);
    const int turn = turn_of(arc);
    // As for a straight start-up, one radius long (to rounding) runs: see start_up().
    if (nckit::length(end - from) < radius_mm_ - 1e-9) {
        return error(move.where, "cutter-comp",
                     fmt::format("the start-up arc's chord is {:.4f} mm, not longer than the tool radius {:.4f} mm",
                                 nckit::length(end - from), radius_mm_));
    }
    const bool inside = side_ == turn;  // G41 on a counter-clockwise arc: the tool is inside it
    const Vec2 out_dir = nckit::unit(inside ? center - end : end - center);
    const Vec2 new_end = end + radius_mm_ * out_dir;
    const double half_chord = nckit::length(from - new_end) / 2.0;
    const double to_center = std::atan2(center.y - new_end.y, center.x - new_end.x);
    const double corner = std::atan2(from.y - new_end.y, from.x - new_end.x) - to_center;
    if (std::abs(std::cos(corner)) < 1e-6) {
        return error(
            move.where, "cutter-gouge",
            fmt::format("the tool radius {:.4f} mm is not less than the radius of this start-up arc", radius_mm_));
    }
    const double reach = half_chord / std::cos(corner);
    const Vec2 new_center = new_end + reach * Vec2{std::cos(to_center), std::sin(to_center)};

    programmed_ = Programmed{};
    programmed_.arc = true;
    programmed_.start[0] = from.x;
    programmed_.start[1] = from.y;
    programmed_.end[0] = end.x;
    programmed_.end[1] = end.y;
    programmed_.center[0] = center.x;
    programmed_.center[1] = center.y;
    programmed_.turn = turn;
    programmed_.sweep_rad = arc_sweep_rad(arc);
    set_in_plane(arc.to, p, new_end);
    set_in_plane(arc.center, p, new_center);
    tool_ = arc.to;
    held_.clear();
    held_.push_back(std::move(move));
    held_start_up_ = false;  // held as a contour arc: the next corner settles its end
    held_restart_ = false;
    has_before_ = false;
    endpoint_valid_ = false;  // LinuxCNC does not check a start-up arc at its first corner
    held_from_radius_mm_ = radius_mm_;
    mode_ = Mode::on;
    return std::nullopt;
}

}  // namespace nckit
