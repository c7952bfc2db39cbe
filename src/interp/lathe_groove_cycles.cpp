// G74 (face grooving, pecking along Z) and G75 (grooving, pecking along X), the 0i's two-block
// form:
//   G74 R(retract)
//   G74 X(U) Z(W) P(step across, X) Q(peck, Z) F       (G75: P the peck in X, Q the step in Z)
// From the start point A each column pecks towards the end point by the peck depth, backing off
// by R after each peck, feeds to the bottom, returns to A's level at rapid and steps across
// (never past the end point) for the next column. R in the second block (the 0i's Δd, the travel
// of the tool at the bottom of the cut) moves the tool back along the step axis, against the step
// direction, at the bottom of every column but the first before it returns: into the column cut
// before, where the material is gone, so the tool's side leaves the groove wall it was cutting.
// P and Q without a decimal point count least increments (P2000 = 2 mm); X is a diameter on a
// diameter lathe, P and R radii. The one-block form of older controls (`G75 X Z I(peck in X)
// K(step in Z) F`, G74 with K the peck in Z and I the step in X) takes the back-off from the last
// `G74/G75 R` block, none if there was none.
#include <cmath>

#include <fmt/format.h>

#include "executor.hpp"
#include "lathe_codes.hpp"

namespace nckit::interp {

namespace {
constexpr int max_groove_moves = 100000;
}  // namespace

std::optional<Diagnostic> Executor::groove_cycle(std::vector<Move>& out) {
    const GCode cycle = words_.group(ModalGroup::non_modal);
    const std::string name = lathe_code_name(machine_.gcode_system, cycle);
    const std::uint32_t column = words_.group_column(ModalGroup::non_modal);
    LatheCycleSettings& settings = modal_.lathe.settings;
    const bool moves = words_.has('X') || words_.has('Z');
    if (!moves) {
        if (words_.has('P') || words_.has('Q')) {
            return error(column, "missing-word",
                         fmt::format("{} with P or Q needs its end point X (U) or Z (W)", name));
        }
        if (const Word* r = words_.word('R')) {
            if (r->value < 0)
                return error(r->column, "bad-value", fmt::format("{} R (retract) must not be negative", name));
            settings.groove_retract_mm = offset_value(*r);
        }
        return std::nullopt;
    }
    const bool inch = modal_.length_factor_mm != 1.0;
    auto increments = [&](const Word* w) {
        if (w == nullptr) return 0.0;
        return w->has_decimal_point ? offset_value(*w) : w->value * (inch ? 0.0001 * 25.4 : 0.001);
    };
    for (char letter : {'P', 'Q', 'I', 'K'}) {
        if (const Word* w = words_.word(letter); w != nullptr && w->value < 0) {
            return error(w->column, "bad-value", fmt::format("{} {} must not be negative", name, letter));
        }
    }
    if (!modal_.feed_set && !words_.has('F')) return error(column, "no-feed", "cutting move with no feed rate (F)");
    const bool face = cycle == lathe_face_grooving;
    const Axis peck_axis = face ? Axis::Z : Axis::X;
    const Axis step_axis = face ? Axis::X : Axis::Z;
    // The one-block form of older controls names the peck and the step I (X) and K (Z).
    const bool one_block = words_.has('I') || words_.has('K');
    const char peck_letter = one_block ? (face ? 'K' : 'I') : (face ? 'Q' : 'P');
    const char step_letter = one_block ? (face ? 'I' : 'K') : (face ? 'P' : 'Q');
    if (one_block && (words_.has('P') || words_.has('Q'))) {
        return error(column_of(words_.has('P') ? 'P' : 'Q'), "bad-combination",
                     fmt::format("{}: give the peck and step as P Q or as I K, not both", name));
    }
    const double peck = increments(words_.word(peck_letter));
    const double step = increments(words_.word(step_letter));
    const AxisVector start = position_;
    const AxisVector end = target_from_words(false);
    const double peck_dir = end[peck_axis] < start[peck_axis] ? -1.0 : 1.0;
    const double step_dir = end[step_axis] < start[step_axis] ? -1.0 : 1.0;
    const double depth = std::abs(end[peck_axis] - start[peck_axis]);
    const double across = std::abs(end[step_axis] - start[step_axis]);
    if (across > 1e-9 && step <= 0) {
        return error(column, "missing-word",
                     fmt::format("{} needs the step across ({}) to reach the end point", name, step_letter));
    }
    double relief = 0;
    if (const Word* r = words_.word('R'); r != nullptr && r->value != 0) {
        if (one_block) {
            return error(r->column, "bad-combination",
                         fmt::format("{}: R (relief at the bottom) belongs to the P Q form, not to I K", name));
        }
        if (r->value < 0) {
            return error(r->column, "bad-value", fmt::format("{} R (relief at the bottom) must not be negative", name));
        }
        // The relief goes against the step direction; with no step across there is none, and
        // the control makes none (it runs the cycle without it).
        if (across <= 1e-9) {
            warn(r->column, "ignored-word",
                 fmt::format("{} R (relief at the bottom) has no effect: the end point is not across the start "
                             "({}), so there is no step to relieve against",
                             name, face ? "X (U)" : "Z (W)"));
        } else {
            relief = offset_value(*r);
        }
    }
    const double pecks = peck > 0 ? depth / peck : 1.0;
    const double columns = across > 1e-9 ? across / step + 1.0 : 1.0;
    if (pecks * columns * 2.0 > max_groove_moves) {
        return error(column, "bad-value",
                     fmt::format("{}: the peck and step need more than {} moves", name, max_groove_moves));
    }
    auto at = [&](double peck_mm, double step_mm) {
        AxisVector p = start;
        p[peck_axis] = start[peck_axis] + peck_dir * peck_mm;
        p[step_axis] = start[step_axis] + step_dir * step_mm;
        return p;
    };
    for (double shift = 0;; shift = std::min(shift + step, across)) {
        if (shift > 0) {
            if (auto e = straight(g(0), at(0, shift), out)) return e;
        }
        double reached = 0;
        while (reached < depth - 1e-9) {
            reached = peck > 0 ? std::min(reached + peck, depth) : depth;
            if (auto e = straight(g(1), at(reached, shift), out)) return e;
            if (reached < depth - 1e-9 && settings.groove_retract_mm > 0) {
                if (auto e = straight(g(0), at(std::max(0.0, reached - settings.groove_retract_mm), shift), out))
                    return e;
            }
        }
        // No relief in the first column: behind it is the groove's wall, not a column cut before.
        const double back = shift > 0 ? relief : 0.0;
        if (back > 0) {
            if (auto e = straight(g(0), at(depth, shift - back), out)) return e;
        }
        if (auto e = straight(g(0), at(0, shift - back), out)) return e;
        if (shift >= across - 1e-9) break;
    }
    if (position_ != start) return straight(g(0), start, out);
    return std::nullopt;
}

}  // namespace nckit::interp
