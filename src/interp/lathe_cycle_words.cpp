// The words a lathe cycle block may hold. A cycle's letters mean their own things (G71 U is a
// depth of cut, not a move), so these blocks are checked here instead of by check_words.
#include <cmath>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "executor.hpp"
#include "lathe_codes.hpp"

namespace nckit::interp {

namespace {

//! Letters each cycle reads besides G M F S T N O.
std::string_view cycle_letters(GCode code) {
    if (code == lathe_turning_cycle || code == lathe_facing_cycle) return "XZUWR";
    if (code == lathe_threading_cycle) return "XZUWRQ";
    if (code == lathe_finish) return "PQ";
    if (code == lathe_rough_turning || code == lathe_rough_facing) return "PQUWRD";
    if (code == lathe_pattern_repeat) return "PQUWRDIK";  // I K D: the one-block form
    if (code == lathe_face_grooving || code == lathe_od_grooving) return "XZUWPQRIK";
    if (code == lathe_thread_repeat) return "XZUWPQRIKDA";
    return "";
}

}  // namespace

GCode Executor::lathe_cycle_of_block() const {
    const GCode non_modal = words_.group(ModalGroup::non_modal);
    if (is_lathe_repetitive_cycle(non_modal)) return non_modal;
    if (is_lathe_single_cycle(motion_)) return motion_;
    return -1;
}

const Word* Executor::cycle_word(char written) const {
    const Word* word = words_.word(words_.reads_as(written));
    return word != nullptr && word->letter == written ? word : nullptr;
}

std::optional<Diagnostic> Executor::check_lathe_cycle_words(GCode cycle) const {
    const std::string name = lathe_code_name(machine_.gcode_system, cycle);
    const std::string_view allowed = cycle_letters(cycle);
    const bool haas = machine_.lathe_control == LatheControl::haas;
    std::string ignored;  // G71's words on a Haas G70, read and not used
    std::uint32_t ignored_column = 0;
    for (const Word& word : block_->words) {
        const char c = word.letter;
        if (c == 'G' || c == 'M' || c == 'F' || c == 'S' || c == 'T') continue;
        if (c == 'N' || c == 'O') {
            if (&word != &block_->words.front()) {
                return error(word.column, "syntax", fmt::format("{} word must start the block", c));
            }
            continue;
        }
        if (allowed.find(c) == std::string_view::npos) {
            const bool roughing_word = std::string_view("UWDIK").find(c) != std::string_view::npos;
            if (cycle == lathe_finish && roughing_word && haas) {
                // Programs for Haas lathes copy G71's one-block words onto G70. No Haas manual
                // gives G70 an allowance or a depth; the finish follows the P-Q blocks either
                // way, so on a Haas machine the words are read, not used, and reported.
                if (ignored.empty()) ignored_column = word.column;
                if (ignored.find(c) == std::string::npos)
                    ignored += ignored.empty() ? std::string(1, c) : fmt::format(" {}", c);
                continue;
            }
            if (cycle == lathe_finish && roughing_word) {
                // Neither Fanuc nor Haas gives G70 an allowance or a depth: on a Fanuc control the
                // words have no meaning to run.
                return error(word.column, "unused-word",
                             fmt::format("{} takes no {} word: {} P Q finishes the shape as programmed ({} is a "
                                         "word of the roughing cycles)",
                                         name, c, name, c));
            }
            return error(word.column, "unused-word", fmt::format("{} takes no {} word", name, c));
        }
        if (c == 'X' || c == 'Z' || ((c == 'U' || c == 'W') && words_.lathe_increments)) {
            if (is_lathe_single_cycle(cycle) || cycle == lathe_face_grooving || cycle == lathe_od_grooving ||
                cycle == lathe_thread_repeat) {
                if (auto e = check_axis_letter(word)) return e;
            }
        }
    }
    if (!ignored.empty()) {
        warn(ignored_column, "ignored-word",
             fmt::format("{} does not use {} (words of the roughing cycles): on this Haas lathe "
                         "they are read and ignored; {} P Q finishes the shape as programmed",
                         name, ignored, name));
    }
    if (const Word* f = words_.word('F'); f != nullptr && f->value <= 0) {
        return error(f->column, "bad-value", fmt::format("{} needs a positive F", name));
    }
    if (is_lathe_single_cycle(cycle)) {
        const bool fresh = modal_.lathe.single.mode != cycle;
        const bool has_x = words_.has('X');
        const bool has_z = words_.has('Z');
        if (fresh && (!has_x || !has_z) && (has_x || has_z)) {
            return error(motion_column(), "missing-word",
                         fmt::format("{} needs both X (U) and Z (W) in its first block", name));
        }
        const bool threading = cycle == lathe_threading_cycle;
        if (fresh && (has_x || has_z)) {
            const bool feed = threading ? words_.has('F') : (words_.has('F') || modal_.feed_set);
            if (!feed) {
                return error(
                    motion_column(), threading ? "missing-word" : "no-feed",
                    threading ? fmt::format("{} needs the thread lead F", name) : "cutting move with no feed rate (F)");
            }
        }
    }
    return std::nullopt;
}

}  // namespace nckit::interp
