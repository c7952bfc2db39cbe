// Drilling cycles G73 G74 G76 G81-G89, expanded into rapids, feeds, dwells and spindle events
// here, so every stage after the interpreter (plan, steps, expand) sees ordinary moves.
//
// Levels along the drilling axis (Z under G17, Y under G18, X under G19), machine coordinates:
// the initial level (where the axis stood when the cycle mode began), the R level and the
// bottom (the Z word). G98 returns to the initial level (or R when R lies above it), G99 to R.
// Under G91, R counts from the initial level and Z from R. The sequence of each hole follows
// LinuxCNC's, so `rs274` gives the same moves: rise to R when below it, then per hole one rapid
// to the hole at the return level, a rapid down to R, the cycle's own moves, the return.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "executor.hpp"
#include "nckit/interp/arc_geometry.hpp"

namespace nckit::interp {

namespace {
// LinuxCNC's clearance above the previous peck when G83 goes back down (and G73's chip-breaking
// retract): 0.010 in. A Fanuc control takes it from a parameter (5114/5115).
constexpr double peck_clearance_mm = 0.254;
// Fanuc's K and LinuxCNC's L: repeats of the hole; 9999 on a 0i.
constexpr int max_repeats = 9999;
// A peck depth that would need more passes than this is a mistyped Q (Q0.001 for a 100 mm hole).
constexpr int max_pecks = 100000;

bool is_peck_cycle(GCode code) {
    return code == g(73) || code == g(83);
}
bool is_shift_cycle(GCode code) {
    return code == g(76) || code == g(87);
}
}  // namespace

struct HolePlan {
    PlaneAxes axes;
    double clear_mm = 0;  //!< where the drill axis ends each hole
    double r_mm = 0;
    double bottom_mm = 0;
    int repeats = 1;
};

std::optional<Diagnostic> Executor::check_cycle_words() const {
    const CycleState& cycle = modal_.cycle;
    const bool same_mode = cycle.active;
    if (!words_.has('R') && !(same_mode && cycle.r_set)) {
        return error(motion_column(), "missing-word", "drilling cycle with no R plane (R word)");
    }
    const Plane plane = [&] {
        GCode p = words_.group(ModalGroup::plane);
        if (p < 0) return modal_.plane;
        return p == g(17) ? Plane::xy : p == g(18) ? Plane::zx : Plane::yz;
    }();
    const Axis drill_axis = plane_axes(plane).normal;
    if (!configured_.contains(drill_axis)) {
        return error(motion_column(), "unknown-axis",
                     fmt::format("drilling cycle along {}, an axis the machine does not have", letter(drill_axis)));
    }
    if (!words_.has(letter(drill_axis)) && !(same_mode && cycle.z_set)) {
        return error(motion_column(), "missing-word",
                     fmt::format("drilling cycle with no hole bottom ({} word)", letter(drill_axis)));
    }
    if (is_peck_cycle(motion_)) {
        const Word* q = words_.word('Q');
        if (q != nullptr ? q->value <= 0 : cycle.q_mm <= 0) {
            return error(q ? q->column : motion_column(), "bad-value",
                         fmt::format("G{} needs a positive peck depth Q", motion_ / 10));
        }
    } else if (const Word* q = words_.word('Q')) {
        if (!is_shift_cycle(motion_)) {
            return error(q->column, "unused-word", fmt::format("Q word with no use in G{}", motion_ / 10));
        }
        if (q->value < 0) return error(q->column, "bad-value", "the shift Q must not be negative");
    }
    if (const Word* p = words_.word('P'); p != nullptr && p->value < 0) {
        return error(p->column, "bad-value", "dwell P must not be negative");
    }
    if (words_.has('K') && words_.has('L')) {
        return error(words_.word('L')->column, "duplicate-word", "give the repeat count as K or L, not both");
    }
    if (const Word* k = words_.has('K') ? words_.word('K') : words_.word('L')) {
        if (k->value < 0 || k->value > max_repeats || k->value != std::floor(k->value)) {
            return error(k->column, "bad-value",
                         fmt::format("repeat count {} must be a whole number from 0 to {}", k->letter, max_repeats));
        }
    }
    return std::nullopt;
}

std::optional<Diagnostic> Executor::drill(std::vector<Move>& out) {
    CycleState& cycle = modal_.cycle;
    HolePlan hole;
    hole.axes = plane_axes(modal_.plane);
    const Axis d = hole.axes.normal;
    const AxisVector offset = program_offset();
    if (!cycle.active) {
        cycle.initial_z_mm = position_[d];
        cycle.active = true;
    }
    // The cycle's words stay for the following blocks of the same cycle mode.
    if (const Word* r = words_.word('R')) {
        cycle.r_word = offset_value(*r);
        cycle.r_set = true;
    }
    if (const Word* z = words_.word(letter(d))) {
        cycle.z_word = axis_value(d, *z);
        cycle.z_set = true;
    }
    if (const Word* q = words_.word('Q')) cycle.q_mm = offset_value(*q);
    // P in milliseconds, as G4 P (Fanuc); LinuxCNC reads seconds.
    if (const Word* p = words_.word('P')) cycle.p_s = p->value / 1000.0;
    const Word* repeat_word = words_.has('K') ? words_.word('K') : words_.word('L');
    hole.repeats = repeat_word != nullptr ? static_cast<int>(repeat_word->value) : 1;

    if (modal_.incremental) {
        hole.r_mm = cycle.initial_z_mm + cycle.r_word;
        hole.bottom_mm = hole.r_mm + cycle.z_word;
    } else {
        hole.r_mm = cycle.r_word + offset[d];
        hole.bottom_mm = cycle.z_word + offset[d];
    }
    const bool back_boring = motion_ == g(87);
    if (!back_boring && hole.bottom_mm > hole.r_mm + 1e-9) {
        return error(column_of('R') != 1 ? column_of('R') : motion_column(), "bad-cycle",
                     fmt::format("the R plane ({:.4f}) lies below the hole bottom ({:.4f})", hole.r_mm - offset[d],
                                 hole.bottom_mm - offset[d]));
    }
    if (back_boring && hole.bottom_mm < hole.r_mm - 1e-9) {
        return error(column_of('R') != 1 ? column_of('R') : motion_column(), "bad-cycle",
                     "G87 back boring starts below the part: R must lie below Z");
    }
    if (is_peck_cycle(motion_) && (hole.r_mm - hole.bottom_mm) / cycle.q_mm > max_pecks) {
        return error(column_of('Q') != 1 ? column_of('Q') : motion_column(), "bad-value",
                     fmt::format("peck depth Q needs more than {} pecks for this hole", max_pecks));
    }
    hole.clear_mm = modal_.cycle.return_to_initial ? std::max(cycle.initial_z_mm, hole.r_mm) : hole.r_mm;
    if (back_boring) hole.clear_mm = cycle.initial_z_mm;
    if (hole.repeats == 0) return std::nullopt;  // K0: the words are kept, nothing is drilled

    // Below R: rise to it first, where the tool stands. LinuxCNC judges by the initial level,
    // so it rises again (a move of no length) on every block of a cycle begun below R.
    const bool initial_below = machine_.dialect == Dialect::linuxcnc && cycle.initial_z_mm < hole.r_mm;
    if (!back_boring && (position_[d] < hole.r_mm || initial_below)) {
        AxisVector up = position_;
        up[d] = hole.r_mm;
        if (auto e = straight(g(0), up, out)) return e;
    }
    for (int i = 0; i < hole.repeats; ++i) {
        AxisVector over = position_;
        for (Axis a : {hole.axes.first, hole.axes.second}) {
            const Word* w = words_.word(letter(a));
            if (w == nullptr || !configured_.contains(a)) continue;
            over[a] = modal_.incremental ? position_[a] + axis_value(a, *w) : axis_value(a, *w) + offset[a];
        }
        // To the hole at the return level (one rapid, as LinuxCNC: it rises as it goes when the
        // previous hole ended lower, at R under G99).
        if (!back_boring) over[d] = std::max(position_[d], hole.clear_mm);
        if (auto e = straight(g(0), over, out)) return e;
        if (auto e = drill_hole(hole, out)) return e;
    }
    return std::nullopt;
}

std::optional<Diagnostic> Executor::drill_hole(const HolePlan& hole, std::vector<Move>& out) {
    const Axis d = hole.axes.normal;
    const CycleState& cycle = modal_.cycle;
    auto go = [&](bool rapid, double level) {
        AxisVector to = position_;
        to[d] = level;
        return straight(rapid ? g(0) : g(1), to, out);
    };
    auto shift = [&](double by_mm) {
        AxisVector to = position_;
        to[hole.axes.first] += by_mm;
        return straight(g(0), to, out);
    };
    auto dwell = [&] {
        if (cycle.p_s > 0) push(out, Dwell{cycle.p_s});
    };
    auto spindle = [&](int code) {
        Io io{IoKind::mcode, code, 0};
        io.waits = true;
        if (code == 3 || code == 4) io.value = modal_.spindle.rpm;
        push(out, io);
    };
    const int turning = modal_.spindle.direction < 0 ? 4 : 3;
    // Boring past the wall (G76, G87): spindle oriented (M19), the tip moved off the wall by Q,
    // a rapid to `level`, back on centre, and the spindle turning again.
    auto oriented_rapid = [&](double level) -> std::optional<Diagnostic> {
        spindle(19);
        if (auto e = shift(cycle.q_mm)) return e;
        if (auto e = go(true, level)) return e;
        if (auto e = shift(-cycle.q_mm)) return e;
        spindle(turning);
        return std::nullopt;
    };
    if (motion_ != g(87) && position_[d] != hole.r_mm) {
        if (auto e = go(true, hole.r_mm)) return e;
    }
    switch (motion_) {
        case g(73):
        case g(83): {
            const bool full_retract = motion_ == g(83);
            for (double depth = hole.r_mm - cycle.q_mm; depth > hole.bottom_mm; depth -= cycle.q_mm) {
                if (auto e = go(false, depth)) return e;
                if (full_retract) {
                    if (auto e = go(true, hole.r_mm)) return e;
                }
                if (auto e = go(true, depth + peck_clearance_mm)) return e;
            }
            if (auto e = go(false, hole.bottom_mm)) return e;
            return go(true, hole.clear_mm);
        }
        case g(81):
        case g(82):
            if (auto e = go(false, hole.bottom_mm)) return e;
            dwell();
            return go(true, hole.clear_mm);
        case g(74):
        case g(84): {
            // Tapping: at the bottom the spindle reverses and the tap feeds back out.
            const int in = motion_ == g(74) ? 4 : 3;
            if (auto e = go(false, hole.bottom_mm)) return e;
            dwell();
            spindle(in == 3 ? 4 : 3);
            if (auto e = go(false, hole.clear_mm)) return e;
            spindle(in);
            return std::nullopt;
        }
        case g(85):
            if (auto e = go(false, hole.bottom_mm)) return e;
            if (auto e = go(false, hole.r_mm)) return e;
            return go(true, hole.clear_mm);
        case g(89):
            if (auto e = go(false, hole.bottom_mm)) return e;
            dwell();
            return go(false, hole.clear_mm);
        case g(86):
        case g(88):
            if (auto e = go(false, hole.bottom_mm)) return e;
            dwell();
            spindle(5);
            if (motion_ == g(88)) spindle(0);  // the operator retracts by hand, then restarts
            if (auto e = go(true, hole.clear_mm)) return e;
            spindle(turning);
            return std::nullopt;
        case g(76):
            // Fine boring: orient the spindle, move the tip off the wall by Q, retract, move back.
            if (auto e = go(false, hole.bottom_mm)) return e;
            dwell();
            return oriented_rapid(hole.clear_mm);
        case g(87):
            // Back boring: oriented and shifted down through the bore to R (below the part),
            // back on centre, bore upwards to Z, then out the same way to the initial level.
            if (auto e = oriented_rapid(hole.r_mm)) return e;
            if (auto e = go(false, hole.bottom_mm)) return e;
            dwell();
            return oriented_rapid(hole.clear_mm);
        default:
            return std::nullopt;
    }
}

}  // namespace nckit::interp
