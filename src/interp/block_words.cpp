#include "block_words.hpp"
#include "lathe_codes.hpp"

#include <cmath>

#include <fmt/format.h>

namespace nckit::interp {

namespace {

constexpr double largest_code_number = 99999999;

std::string g_name(GCode code, GCodeSystem system) {
    return lathe_code_name(system, code);
}

//! M7 and M8 may run together (mist and flood); any other pair of one group conflicts.
bool m_conflict(int a, int b) {
    if (a == b) return true;
    MGroup group = m_group_of(a);
    if (group != m_group_of(b) || group == MGroup::other) return false;
    if (group == MGroup::coolant) return a == 9 || b == 9;
    return true;
}

//! Fanuc's group 09: the drilling cycles and G80, which cancels them.
bool is_group_09(GCode code) {
    return code == g(80) || is_drilling_cycle(code);
}

//! Places a group-01 or group-09 code of the Fanuc dialect. In one group the last code written is
//! valid. A group-01 code (G0 G1 G2 G3 ...) beside a cycle code runs and the cycle code is
//! ignored (a group-01 code cancels the cycle); beside G80 both count.
void place_fanuc_motion(BlockWords& out, GWord code) {
    GWord& slot = out.gcodes[static_cast<std::size_t>(ModalGroup::motion)];
    if (code.code == g(80)) {
        if (slot.code >= 0 && is_drilling_cycle(slot.code)) {
            out.overridden.push_back(OverriddenGCode{slot.code, code.code, slot.column});
            slot = GWord{};
        }
        out.cancels_cycle = true;
        return;
    }
    if (slot.code < 0) {
        if (is_drilling_cycle(code.code) && out.cancels_cycle) {
            out.overridden.push_back(OverriddenGCode{g(80), code.code, code.column});
            out.cancels_cycle = false;
        }
        slot = code;
        return;
    }
    const bool same_group = is_group_09(slot.code) == is_group_09(code.code);
    if (same_group) {
        out.overridden.push_back(OverriddenGCode{slot.code, code.code, slot.column});
        slot = code;
    } else if (is_drilling_cycle(code.code)) {
        out.overridden.push_back(OverriddenGCode{code.code, slot.code, code.column});
    } else {
        out.overridden.push_back(OverriddenGCode{slot.code, code.code, slot.column});
        slot = code;
    }
}

}  // namespace

MGroup m_group_of(int code) {
    switch (code) {
        case 0:
        case 1:
        case 2:
        case 30:
        case 60:
            return MGroup::stopping;
        case 6:
            return MGroup::tool_change;
        case 3:
        case 4:
        case 5:
            return MGroup::spindle;
        case 7:
        case 8:
        case 9:
            return MGroup::coolant;
        default:
            return MGroup::other;
    }
}

std::optional<ModalGroup> group_of(GCode code) {
    switch (code) {
        case g(4):
        case g(10):
        case g(28):
        case g(30):
        case g(31):
        case g(50):
        case g(52):
        case g(53):
        case g(92):
        case g(92, 1):
            return ModalGroup::non_modal;
        case g(9):
            return ModalGroup::exact_stop;
        case g(0):
        case g(1):
        case g(2):
        case g(3):
        case g(32):
        case g(33):
        case g(80):
        case g(73):
        case g(74):
        case g(76):
        case g(81):
        case g(82):
        case g(83):
        case g(84):
        case g(85):
        case g(86):
        case g(87):
        case g(88):
        case g(89):
            return ModalGroup::motion;
        case g(17):
        case g(18):
        case g(19):
            return ModalGroup::plane;
        case g(90):
        case g(91):
            return ModalGroup::distance;
        case g(94):
        case g(95):
            return ModalGroup::feed_mode;
        case g(20):
        case g(21):
            return ModalGroup::units;
        case g(40):
        case g(41):
        case g(42):
        case g(41, 1):
        case g(42, 1):
            return ModalGroup::cutter_comp;
        case g(43):
        case g(44):
        case g(43, 1):
        case g(49):
            return ModalGroup::length_comp;
        case g(98):
        case g(99):
            return ModalGroup::return_mode;
        case g(90, 1):
        case g(91, 1):
            return ModalGroup::arc_distance;
        case g(96):
        case g(97):
            return ModalGroup::spindle_mode;
        case g(54):
        case g(55):
        case g(56):
        case g(57):
        case g(58):
        case g(59):
            return ModalGroup::work_system;
        case g(61):
        case g(64):
            return ModalGroup::path_control;
        case g(7):
        case g(8):
            return ModalGroup::diameter;
        case g(51):
            return ModalGroup::scaling;
        case g(50, 1):
        case g(51, 1):
            return ModalGroup::mirror;
        case g(68):
        case g(69):
            return ModalGroup::rotation;
        default:
            if (is_lathe_single_cycle(code)) return ModalGroup::motion;         // modal, as G1
            if (is_lathe_repetitive_cycle(code)) return ModalGroup::non_modal;  // one block
            return std::nullopt;
    }
}

bool BlockWords::has_m(int code) const {
    for (std::size_t i = 0; i < mcode_count; ++i) {
        if (mcodes[i].code == code) return true;
    }
    return false;
}

namespace {
//! Code words (M N O T) hold whole numbers of at most 8 digits; checked before any cast to int.
bool is_code_number(double value) {
    return value >= 0 && value <= largest_code_number && value == std::floor(value);
}
}  // namespace

std::optional<Diagnostic> collect_words(const Block& block, BlockWords& out, GCodeSystem system, Dialect dialect) {
    out = BlockWords{};
    const bool fanuc = dialect == Dialect::fanuc;
    out.lathe_increments = system == GCodeSystem::a;
    bool polar_cancel_seen = false;
    for (const Word& word : block.words) {
        auto at = [&] { return block.at_column(word.column); };
        bool code_letter = word.letter == 'M' || word.letter == 'N' || word.letter == 'O' || word.letter == 'T';
        if (code_letter && !is_code_number(word.value)) {
            return error_at(at(), "bad-value",
                            fmt::format("{} must be a whole number from 0 to {}", word.letter,
                                        static_cast<long>(largest_code_number)));
        }
        if (word.letter == 'G') {
            if (word.value < 0 || word.value >= 1000) {
                return error_at(at(), "unknown-gcode", fmt::format("G{} is not a G code", word.value));
            }
            double tenths = word.value * 10.0;
            auto code = static_cast<GCode>(std::lround(tenths));
            if (std::abs(tenths - code) > 1e-6) {
                return error_at(at(), "unknown-gcode", fmt::format("G{} is not a G code", word.value));
            }
            LatheCode read = read_lathe_code(system, code);
            if (!read.refusal.empty()) return error_at(at(), "unsupported-gcode", read.refusal);
            code = read.code;
            if (code == g(15)) {
                // Shop programs' safe-start lines write G15 (polar coordinates off) beside G40
                // G49 G80: with G16 unsupported polar mode is never on, so G15 changes nothing.
                if (polar_cancel_seen) {
                    return error_at(at(), "modal-conflict", "G15 and G15 are in the same modal group");
                }
                polar_cancel_seen = true;
                continue;
            }
            auto group = group_of(code);
            if (!group) {
                return error_at(at(), "unsupported-gcode", fmt::format("{} is not supported", g_name(code, system)));
            }
            GWord& slot = out.gcodes[static_cast<std::size_t>(*group)];
            if (fanuc && *group == ModalGroup::motion) {
                place_fanuc_motion(out, GWord{code, word.column});
                continue;
            }
            // G80 beside a motion code (`G0 G80 Z50`, as CAM posts write it) cancels the cycle
            // and the motion code then moves: only two motion codes conflict.
            if (*group == ModalGroup::motion && slot.code >= 0 && (slot.code == g(80)) != (code == g(80))) {
                if (slot.code == g(80)) slot = GWord{code, word.column};
                continue;
            }
            if (fanuc && slot.code >= 0 && *group != ModalGroup::non_modal) {
                // Fanuc: of two codes of one group the last one written is valid. One-shot codes
                // (group 00) each do something different, so two of them stay an error.
                out.overridden.push_back(OverriddenGCode{slot.code, code, slot.column});
                slot = GWord{code, word.column};
                continue;
            }
            if (slot.code >= 0) {
                return error_at(at(), "modal-conflict",
                                fmt::format("{} and {} are in the same modal group", g_name(slot.code, system),
                                            g_name(code, system)));
            }
            slot = GWord{code, word.column};
        } else if (word.letter == 'M') {
            auto code = static_cast<int>(word.value);
            for (std::size_t i = 0; i < out.mcode_count; ++i) {
                if (m_conflict(out.mcodes[i].code, code)) {
                    return error_at(at(), "modal-conflict",
                                    fmt::format("M{} and M{} cannot be in one block", out.mcodes[i].code, code));
                }
            }
            if (out.mcode_count == out.mcodes.size()) {
                return error_at(at(), "too-many-mcodes",
                                fmt::format("more than {} M codes in one block", out.mcodes.size()));
            }
            out.mcodes[out.mcode_count++] = MWord{code, word.column};
        } else {
            const char reads_as = out.reads_as(word.letter);
            const Word*& slot = out.letters[reads_as - 'A'];
            if (slot != nullptr) {
                if (slot->letter != word.letter) {
                    return error_at(
                        at(), "duplicate-word",
                        fmt::format("{} and {} both give {} in one block", slot->letter, word.letter, reads_as));
                }
                return error_at(at(), "duplicate-word", fmt::format("{} appears twice in one block", word.letter));
            }
            slot = &word;
            out.incremental_letter[reads_as - 'A'] = reads_as != word.letter;
        }
    }
    return std::nullopt;
}

}  // namespace nckit::interp
