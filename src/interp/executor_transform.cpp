// The executor's side of the programmable transforms (program_transform.hpp): reading the
// codes, and mapping each move the block makes from programmed to transformed coordinates.
#include <algorithm>

#include <fmt/format.h>

#include "executor.hpp"
#include "nckit/interp/arc_geometry.hpp"

namespace nckit::interp {

std::optional<Diagnostic> Executor::set_transform() {
    if (!ProgramTransform::sets_transform(words_)) return std::nullopt;
    const bool was_active = transform_.active();
    const AxisVector offset = program_offset();
    const AxisVector programmed_work = (was_active ? programmed_ : position_) - offset;
    auto value = [&](Axis axis, const Word& word) { return axis_value(axis, word); };
    if (auto e = transform_.apply(words_, modal_.plane, programmed_work, value)) {
        return error(e->column, "bad-transform", e->message);
    }
    // From here the programmed point is where the tool is; the next move goes from there to
    // the transformed target.
    if (!was_active && transform_.active()) programmed_ = position_;
    return std::nullopt;
}

std::optional<Diagnostic> Executor::transformed_move(std::vector<Move>& out) {
    if (ProgramTransform::sets_transform(words_)) return std::nullopt;  // its axis words set it
    if (!transform_.active()) return move(out);
    const GCode non_modal = words_.group(ModalGroup::non_modal);
    if ((non_modal == g(28) || non_modal == g(53)) && block_has_axis_words()) {
        return error(words_.group_column(ModalGroup::non_modal), "bad-transform",
                     "G28 and G53 need the mirror, scaling and rotation cancelled (G50.1, G50, G69)");
    }
    const std::size_t start = out.size();
    const AxisVector actual = position_;
    position_ = programmed_;
    if (auto e = move(out)) {
        position_ = actual;
        return e;
    }
    const AxisVector programmed_end = position_;
    const AxisVector offset = program_offset();
    auto to_machine = [&](const AxisVector& p) { return transform_.map(p - offset) + offset; };
    AxisVector at = actual;
    position_ = actual;  // travel checks below measure from the real position
    for (std::size_t i = start; i < out.size(); ++i) {
        std::optional<Diagnostic> problem;
        std::visit(
            [&](auto& m) {
                using T = std::decay_t<decltype(m)>;
                if constexpr (std::is_same_v<T, Line> || std::is_same_v<T, SyncMove>) {
                    m.from = at;
                    m.to = to_machine(m.to);
                    AxisVector low, high;
                    for (std::size_t k = 0; k < axis_count; ++k) {
                        low[k] = std::min(m.from[k], m.to[k]);
                        high[k] = std::max(m.from[k], m.to[k]);
                    }
                    problem = check_travel(low, high);
                    at = m.to;
                } else if constexpr (std::is_same_v<T, Arc>) {
                    if (!transform_.plane_scale(m.plane)) {
                        problem =
                            error(motion_column(), "bad-transform",
                                  "G2/G3 with unequal scaling of the arc's plane axes (the path would be an ellipse)");
                        return;
                    }
                    m.from = at;
                    m.to = to_machine(m.to);
                    m.center = to_machine(m.center);
                    const PlaneAxes axes = plane_axes(m.plane);
                    for (std::size_t k = 0; k < axis_count; ++k) {
                        if (k != index(axes.first) && k != index(axes.second)) m.center[k] = m.from[k];
                    }
                    if (transform_.reverses(m.plane)) {
                        m.direction = m.direction == ArcDirection::clockwise ? ArcDirection::counterclockwise
                                                                             : ArcDirection::clockwise;
                    }
                    const AxisBox box = arc_bounds(m);
                    problem = check_travel(box.low, box.high);
                    at = m.to;
                }
            },
            out[i].what);
        if (problem) {
            position_ = actual;
            return problem;
        }
    }
    programmed_ = programmed_end;
    position_ = at;
    return std::nullopt;
}

}  // namespace nckit::interp
