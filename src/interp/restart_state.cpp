#include "nckit/interp/restart_state.hpp"

#include <cmath>

#include <fmt/format.h>

#include "nckit/interp/arc_geometry.hpp"
#include "restart_preamble.hpp"

namespace nckit {

using namespace restart_detail;

namespace {

constexpr double takeup_mm = 1.0;     // more than any backlash a machine file may hold today
constexpr double clearance_mm = 2.0;  // the last stretch onto the point is fed, not rapid

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

}  // namespace

void RestartState::note(const Move& move, const ModalView& view) {
    modes_ = view;
    compensating_ = view.cutter_compensation;
    if (const auto* io = std::get_if<Io>(&move.what)) note_io(*io, *machine_, io_);
    if (const AxisVector* end = end_of(move)) {
        position_ = *end;
        note_directions(move, side_);
        if (std::holds_alternative<SyncMove>(move.what)) {
            if (!thread_start_) thread_start_ = move;
        } else {
            thread_start_.reset();
        }
    }
}

std::optional<Diagnostic> RestartState::refuse(const Move& target, const ModalView& view) const {
    if (view.cutter_compensation && compensating_) {
        return error_at(target.where, "restart-cutter-comp",
                        "the block lies inside cutter compensation (G41/G42): its start depends on the "
                        "blocks before it; restart at the block that switches compensation on or after G40");
    }
    if (std::holds_alternative<SyncMove>(target.what) && thread_start_) {
        return error_at(
            target.where, "restart-mid-thread",
            fmt::format("the block is in the middle of a thread pass; restart at the pass's "
                        "start, {}{}",
                        location_text(thread_start_->where),
                        thread_start_->sequence_number >= 0 ? fmt::format(" (N{})", thread_start_->sequence_number)
                                                            : std::string()));
    }
    return std::nullopt;
}

RestartApproach RestartState::approach(const Move& target) const {
    RestartApproach a;
    a.retract_axis = retract_axis_of(*machine_);
    if (const AxisConfig* axis = machine_->find(a.retract_axis)) a.safe_mm = axis->max;
    if (machine_->restart_safe_mm) a.safe_mm = *machine_->restart_safe_mm;
    // Moves are continuous: the target starts where the last motion before it ended.
    const AxisVector* start = start_of(target);
    a.moves = position_.has_value() || start != nullptr;
    a.point = position_ ? *position_ : start != nullptr ? *start : AxisVector{};
    a.side = side_;
    a.takeup_mm = takeup_mm;
    a.clearance_mm = clearance_mm;
    a.feed_mm_min = machine_->restart_feed_mm_min;
    return a;
}

std::vector<ApproachStep> approach_steps(const RestartApproach& a, const MachineConfig& machine,
                                         const AxisVector& from) {
    std::vector<ApproachStep> steps;
    AxisVector at = from;
    auto go = [&](const AxisVector& to, bool rapid, bool retract_only) {
        Line line;
        line.from = at;
        line.to = to;
        line.rapid = rapid;
        line.feed.mm_per_min = a.feed_mm_min;
        // Each step ends at rest: the retract is complete before the other axes move.
        line.path.exact_stop = true;
        steps.push_back(ApproachStep{line, retract_only});
        at = to;
    };
    const Axis r = a.retract_axis;
    const double away = a.safe_mm >= a.point[r] ? 1.0 : -1.0;
    AxisVector to = at;
    to[r] = a.safe_mm;
    go(to, true, true);
    bool others = false;
    for (const AxisConfig& axis : machine.axes) {
        if (axis.axis == r) continue;
        others = true;
        to[axis.axis] = a.point[axis.axis] - a.side[index(axis.axis)] * a.takeup_mm;
    }
    if (others) {
        go(to, true, false);
        for (const AxisConfig& axis : machine.axes) {
            if (axis.axis != r) to[axis.axis] = a.point[axis.axis];
        }
        go(to, true, false);
    }
    const double near = a.point[r] + away * a.clearance_mm;
    if (away * (a.safe_mm - near) > 0) {
        to[r] = near;
        go(to, true, true);
    }
    to[r] = a.point[r];
    go(to, false, true);
    return steps;
}

}  // namespace nckit
