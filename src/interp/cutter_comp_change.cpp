// A new cutter radius in offset mode (the Fanuc dialect): G41/G42 given again on the same side,
// or a D word alone, with no G40 between. Fanuc's manuals describe both: a new offset value
// takes effect at the end point of the block that brings it (the block starts where the old
// radius left the tool), and G41/G42 given again in offset mode ends the block before it square
// to its own direction, whatever the corner, before the next block runs on.
#include <cmath>

#include "cutter_comp_geometry.hpp"
#include "nckit/interp/arc_geometry.hpp"
#include "nckit/interp/cutter_comp.hpp"

namespace nckit {

using interp::comp::in_plane;
using interp::comp::set_in_plane;

std::optional<CompError> CutterCompensator::next_with_new_offset(Move move, std::vector<Move>& out) {
    const double new_radius_mm = *pending_radius_mm_;
    const bool restart = pending_restart_;
    pending_radius_mm_.reset();
    pending_restart_ = false;
    if (std::holds_alternative<Arc>(move.what)) {
        // The offset would change along the arc (a spiral): neither end point is defined by it.
        return error(move.where, "cutter-comp",
                     restart ? "the first move in the plane after G41/G42 in offset mode must be a straight line "
                               "(G0/G1), not an arc"
                             : "the cutter radius offset changes on an arc: give the new D on a straight line "
                               "(G0/G1) move");
    }
    if (restart) {
        // The held move keeps the end its own direction gave it, r beside its end point.
        if (auto e = release(out)) return e;
        radius_mm_ = new_radius_mm;
        hold_restarted(std::move(move));
        return std::nullopt;
    }
    // The corner before the move is made with the old radius, its end with the new one.
    const double old_radius_mm = radius_mm_;
    if (auto e = next_planar(std::move(move), out)) return e;
    radius_mm_ = new_radius_mm;
    held_from_radius_mm_ = old_radius_mm;
    PlaneAxes p = plane_axes(plane_);
    auto& line = std::get<Line>(held_.front().what);
    const Vec2 start{programmed_.start[0], programmed_.start[1]};
    const Vec2 end{programmed_.end[0], programmed_.end[1]};
    const Vec2 normal = static_cast<double>(side_) * nckit::left_normal(nckit::unit(end - start));
    set_in_plane(line.to, p, end + new_radius_mm * normal);
    tool_ = line.to;
    return std::nullopt;
}

void CutterCompensator::hold_restarted(Move move) {
    PlaneAxes p = plane_axes(plane_);
    auto& line = std::get<Line>(move.what);
    const Vec2 start = in_plane(line.from, p);
    const Vec2 end = in_plane(line.to, p);
    before_ = programmed_;
    has_before_ = false;  // no corner joins the two: nothing to keep clear of behind
    programmed_ = Programmed::straight(start, end, line.rapid);
    line.from = tool_;
    const Vec2 normal = static_cast<double>(side_) * nckit::left_normal(nckit::unit(end - start));
    set_in_plane(line.to, p, end + radius_mm_ * normal);
    tool_ = line.to;
    held_.clear();
    held_.push_back(std::move(move));
    held_start_up_ = false;
    held_restart_ = true;
    held_from_radius_mm_ = radius_mm_;
}

}  // namespace nckit
