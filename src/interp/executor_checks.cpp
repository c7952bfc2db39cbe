// The checks a block passes before any of it runs: every word must be used by something in the
// block, and every value must make sense for its code. A word nothing uses is an error rather
// than ignored: on a machine, a mistyped program must not run.
#include <cmath>

#include <fmt/format.h>

#include "executor.hpp"

namespace nckit::interp {

namespace {

bool is_axis_letter(char c) {
    return axis_from_letter(c).has_value();
}

bool is_arc(GCode motion) {
    return motion == g(2) || motion == g(3);
}
bool is_thread(GCode motion) {
    return motion == g(32) || motion == g(33);
}

//! The centre-offset letters that belong to a plane: G17 I J, G18 I K, G19 J K.
bool offset_in_plane(char letter, Plane plane) {
    switch (plane) {
        case Plane::xy:
            return letter == 'I' || letter == 'J';
        case Plane::zx:
            return letter == 'I' || letter == 'K';
        case Plane::yz:
            return letter == 'J' || letter == 'K';
    }
    return false;
}

}  // namespace

bool Executor::block_has_axis_words() const {
    for (char c : axis_letters) {
        if (words_.has(c)) return true;
    }
    return false;
}

std::optional<Diagnostic> Executor::check_axis_letter(const Word& word) const {
    Axis axis = *axis_from_letter(words_.reads_as(word.letter));
    if (!configured_.contains(axis)) {
        return error(word.column, "unknown-axis", fmt::format("the machine has no {} axis", word.letter));
    }
    return std::nullopt;
}

std::optional<Diagnostic> Executor::check_words() {
    const GCode explicit_motion = words_.group(ModalGroup::motion);
    const GCode non_modal = words_.group(ModalGroup::non_modal);
    motion_ = explicit_motion >= 0 ? explicit_motion : modal_.motion;
    // Fanuc's G80 (group 09) alone: the axis words move in the group-01 mode of before the cycle.
    if (explicit_motion < 0 && words_.cancels_cycle && is_drilling_cycle(modal_.motion)) {
        motion_ = modal_.motion_before_cycle;
    }
    const Plane plane = [&] {
        GCode p = words_.group(ModalGroup::plane);
        if (p < 0) return modal_.plane;
        return p == g(17) ? Plane::xy : p == g(18) ? Plane::zx : Plane::yz;
    }();

    if (GCode lathe_cycle = lathe_cycle_of_block(); lathe_cycle >= 0) return check_lathe_cycle_words(lathe_cycle);
    if (is_lathe_offset_write()) return check_lathe_offset_write();
    const bool dwell = non_modal == g(4);
    const bool length_setting = words_.group(ModalGroup::length_comp) == g(43, 1);
    const bool homing = non_modal == g(28) || non_modal == g(30);
    const bool axes_for_setting = non_modal == g(10) || homing || non_modal == g(52) || non_modal == g(92) ||
                                  non_modal == g(50) || length_setting || ProgramTransform::sets_transform(words_);
    const bool transform = ProgramTransform::sets_transform(words_);
    // `G0 G28 G91 Z0` (Fanuc, Haas): the motion code only sets the mode, G28 takes the axes.
    const bool motion_only_sets_mode = homing && (explicit_motion == g(0) || explicit_motion == g(1));
    if (axes_for_setting && explicit_motion >= 0 && !motion_only_sets_mode && block_has_axis_words()) {
        return error(words_.group_column(ModalGroup::motion), "modal-conflict",
                     "two G codes in this block both use the axis words");
    }
    if (non_modal == g(53)) {
        if (explicit_motion >= 0 && explicit_motion != g(0) && explicit_motion != g(1)) {
            return error(words_.group_column(ModalGroup::non_modal), "bad-combination", "G53 moves only with G0 or G1");
        }
        // A Fanuc control positions at rapid whatever the modal motion (G1, G2, a cycle); G1 in
        // the block itself feeds, as LinuxCNC does. The axis words are machine coordinates,
        // absolute even under G91.
        if (explicit_motion < 0) motion_ = g(0);
    }
    if ((non_modal == g(92) || non_modal == g(52) ||
         (non_modal == g(10) && words_.has('L') && (words_.word('L')->value == 2 || words_.word('L')->value == 20))) &&
        !block_has_axis_words()) {
        // RS-274/NGC and LinuxCNC refuse it too: usually a word was lost.
        return error(words_.group_column(ModalGroup::non_modal), "missing-word",
                     fmt::format("G{} needs at least one axis word", non_modal / 10));
    }
    const bool moves = !dwell && !axes_for_setting && motion_ != g(80);
    const bool cycle = moves && is_drilling_cycle(motion_);
    const bool tool_table_write =
        non_modal == g(10) && words_.has('L') && words_.word('L')->value != 2 && words_.word('L')->value != 20;

    for (const Word& word : block_->words) {
        char c = words_.reads_as(word.letter);
        auto unused = [&](std::string why) { return error(word.column, "unused-word", std::move(why)); };
        if (c == 'G' || c == 'M' || c == 'F' || c == 'S' || c == 'T') continue;
        if (c == 'N' || c == 'O') {
            if (&word != &block_->words.front()) {
                return error(word.column, "syntax", fmt::format("{} word must start the block", c));
            }
            continue;
        }
        if (is_axis_letter(c)) {
            if (dwell) {
                if (c == 'X' && !words_.has('P')) continue;
                return unused(fmt::format("G4 takes no axis words ({} given)", c));
            }
            if (auto e = check_axis_letter(word)) return e;
            if (!moves && !axes_for_setting && non_modal != g(53)) {
                return unused(fmt::format("{} word with no motion mode to use it (G80 is active)", c));
            }
            continue;
        }
        switch (c) {
            case 'I':
            case 'J':
            case 'K':
                if (transform && words_.group(ModalGroup::scaling) == g(51)) continue;
                if (is_arc(motion_) && moves) {
                    if (!offset_in_plane(c, plane)) {
                        return error(word.column, "bad-arc",
                                     fmt::format("{} is not a centre offset in the active plane", c));
                    }
                    if (words_.has('R')) return error(word.column, "bad-arc", "arc with both R and I/J/K");
                    continue;
                }
                if (c == 'K' && is_thread(motion_) && moves) continue;
                if (c == 'K' && cycle) continue;  // Fanuc's repeat count
                return unused(fmt::format("{} word with no G2/G3 to use it", c));
            case 'R':
                if ((is_arc(motion_) && moves) || cycle || tool_table_write) continue;
                if (words_.group(ModalGroup::rotation) == g(68)) continue;
                return unused("R word with no G2/G3, drilling cycle or G10 L1-L13 to use it");
            case 'E':
                if (is_thread(motion_) && moves) continue;
                return unused("E word with no G32/G33 to use it");
            case 'D':
            case 'H':
                // D: LinuxCNC's spindle clamp beside G96 (G96 D<rpm> S<speed>), else the modal
                // cutter radius offset number; H: the tool length offset number.
                continue;
            case 'P':
                if (dwell || non_modal == g(10) || words_.group(ModalGroup::path_control) == g(64) || cycle) continue;
                if (words_.group(ModalGroup::scaling) == g(51)) continue;
                return unused("P word with no G4, G10, G64 or drilling cycle to use it");
            case 'Q':
                // LinuxCNC's G64 Q (naive CAM tolerance) is accepted; nckit's planner needs only P.
                // G32/G33 Q: the thread's start angle past the index (thread_start_angle.cpp).
                if (words_.group(ModalGroup::path_control) == g(64) || cycle || is_thread(motion_)) continue;
                return unused("Q word with no G64, thread or drilling cycle to use it");
            case 'L':
                if (non_modal == g(10) || cycle) continue;
                return unused("L word with no G10 or drilling cycle to use it");
            default:
                return error(word.column, "unsupported-word", fmt::format("{} word is not supported", c));
        }
    }

    if (tool_table_write) {
        const double l = words_.word('L')->value;
        if (l != 1 && l != 10 && l != 11 && l != 12 && l != 13) {
            return error(words_.group_column(ModalGroup::non_modal), "bad-g10", "G10 needs L1, L2, L10-L13 or L20");
        }
        if (auto e = check_tool_table_write()) return e;
    } else if (non_modal == g(10)) {
        const Word* l = words_.word('L');
        const Word* p = words_.word('P');
        if (l == nullptr || (l->value != 2 && l->value != 20)) {
            return error(words_.group_column(ModalGroup::non_modal), "bad-g10", "G10 needs L1, L2, L10-L13 or L20");
        }
        if (p == nullptr || p->value != std::floor(p->value) || p->value < 0 || p->value > 6) {
            return error(p ? p->column : words_.group_column(ModalGroup::non_modal), "bad-g10",
                         "G10 needs P0 (active system) or P1 to P6 (G54 to G59)");
        }
    }
    // `G20 F10` could mean 10 in/min or (LinuxCNC, which reads F before the units) 10 mm/min:
    // a factor of 25.4 either way. Fanuc wants G20/G21 alone in its block; nckit refuses F
    // beside a G20/G21 that changes the units.
    if (const GCode units = words_.group(ModalGroup::units);
        units >= 0 && words_.has('F') && (units == g(20)) != (modal_.length_factor_mm != 1.0)) {
        return error(words_.word('F')->column, "bad-combination",
                     fmt::format("F beside G{} that changes the units is ambiguous: give G{} in a block of its own",
                                 units / 10, units / 10));
    }
    // A negative F is a wrong value, not a missing one: say so before the feed check below.
    // Under G32/G33 F is the lead, which sync() checks.
    if (const Word* f = words_.word('F'); f != nullptr && f->value < 0 && !is_thread(motion_)) {
        return error(f->column, "bad-value", "feed rate F must not be negative");
    }
    const bool arc_offsets = words_.has('I') || words_.has('J') || words_.has('K') || words_.has('R');
    const bool cuts = motion_ == g(1) || (is_arc(motion_) && arc_offsets) || is_drilling_cycle(motion_);
    if (moves && cuts && (block_has_axis_words() || is_arc(motion_))) {
        bool feed_now = words_.has('F') || modal_.feed_set;
        double feed = words_.has('F') ? words_.word('F')->value : modal_.feed;
        if (!feed_now || feed <= 0) {
            return error(motion_column(), "no-feed", "cutting move with no feed rate (F)");
        }
    }
    if (cycle && block_has_axis_words()) return check_cycle_words();
    return std::nullopt;
}

}  // namespace nckit::interp
