// G31 skip (Fanuc): a straight feed toward the programmed point that stops where the skip signal
// fires. In simulation the signal fires where the tool first reaches one of the machine file's
// probe surfaces ([probe] surfaces: a plane per axis, machine coordinates); the point is kept for
// #5061-#5066. A G31 that reaches its end point without meeting a surface is an error: a probing
// macro would go on with a position that was never measured.
#include <cmath>

#include <fmt/format.h>

#include "executor.hpp"

namespace nckit::interp {

std::optional<Diagnostic> Executor::probe(std::vector<Move>& out) {
    const std::uint32_t column = words_.group_column(ModalGroup::non_modal);
    const GCode motion = words_.group(ModalGroup::motion);
    if (motion >= 0 && motion != g(1)) {
        return error(words_.group_column(ModalGroup::motion), "bad-combination",
                     "G31 feeds in a straight line: no other motion code in its block");
    }
    if (!block_has_axis_words()) return error(column, "missing-word", "G31 needs an axis word: where to probe toward");
    const bool feed_given = words_.has('F') || modal_.feed_set;
    if (!feed_given || modal_.feed <= 0 || modal_.feed_mode != FeedMode::per_minute) {
        return error(column, "no-feed", "G31 needs a feed per minute (F under G94)");
    }
    const AxisVector target = target_from_words(false);
    // The first surface the straight move reaches, as a fraction of the move (0, 1].
    double first_hit = 2.0;
    for (const ProbeSurface& surface : machine_.probe_surfaces) {
        const double from = position_[surface.axis];
        const double to = target[surface.axis];
        if (from == to) continue;
        const double t = (surface.at_mm - from) / (to - from);
        if (t > 0 && t <= 1.0 + 1e-12) first_hit = std::min(first_hit, std::min(t, 1.0));
    }
    if (first_hit > 1.0) {
        return error(column, "skip-not-reached",
                     machine_.probe_surfaces.empty()
                         ? std::string("G31: the skip signal never fires: the machine file has no [probe] surfaces")
                         : std::string("G31: the skip signal never fired: the move meets no [probe] surface before "
                                       "its end point"));
    }
    AxisVector skip = position_;
    for (std::size_t i = 0; i < axis_count; ++i) skip[i] = position_[i] + (target[i] - position_[i]) * first_hit;
    if (auto e = check_line_travel(skip)) return e;
    Line line{position_, skip, current_feed(), false, modal_.path};
    line.path.exact_stop = true;  // the axes stop where the signal came
    push(out, line);
    position_ = skip;
    skip_position_ = skip;
    return std::nullopt;
}

}  // namespace nckit::interp
