// LinuxCNC's meanings of words the Executor reads the Fanuc way, turned into blocks it runs as
// LinuxCNC would: P in seconds, G4 beside a move, I/O M-codes' words, the tool table's rules for
// T, M61 Q, G43 and G41/G42, and the move to where the tool stands under a bare G0/G1.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "ngc_block_words.hpp"
#include "ngc_runner.hpp"

namespace nckit::interp::ngc {

std::optional<Diagnostic> NgcRunner::translate_block() {
    run_list_.clear();
    if (auto error = check_tool_numbers()) return error;
    // G4 P and a drilling cycle's P are seconds in LinuxCNC; the Executor reads Fanuc's
    // milliseconds for P and seconds for G4 X.
    Word* p = find_word(block_, 'P');
    const bool dwell = has_g(block_, 4);
    int m_io = 0;
    for (const Word& w : block_.words) {
        if (w.letter == 'M' && ((w.value >= 50 && w.value <= 53) || (w.value >= 61 && w.value <= 68))) {
            m_io = static_cast<int>(w.value);
        }
    }
    const bool orient = std::any_of(block_.words.begin(), block_.words.end(),
                                    [](const Word& w) { return w.letter == 'M' && w.value == 19; });
    if (orient) {
        // M19 R (angle) Q (time-out) P (direction): a spindle orientation, no motion of the axes.
        std::erase_if(block_.words,
                      [](const Word& w) { return w.letter == 'R' || w.letter == 'Q' || w.letter == 'P'; });
        p = nullptr;
    }
    if (m_io != 0) {
        // Override switches (M50-M53 P), M61 Q (set the loaded tool), digital and analog I/O
        // (M62-M65 P, M66 P E L Q, M67/M68 E Q): events without motion; their pin, value and
        // wait words are LinuxCNC's and have no meaning for the planner.
        std::erase_if(block_.words, [](const Word& w) {
            return w.letter == 'P' || w.letter == 'E' || w.letter == 'L' || w.letter == 'Q';
        });
        p = nullptr;
    }
    if (p != nullptr && dwell) {
        split_dwell(*p);
    } else if (p != nullptr && !has_g(block_, 10) && !has_g(block_, 64)) {
        bool cycle = false;
        for (double code : {82.0, 86.0, 88.0, 89.0}) cycle = cycle || has_g(block_, code);
        int modal = executor_.modal_view().motion_code;
        cycle = cycle || modal == 820 || modal == 860 || modal == 880 || modal == 890;
        if (cycle) p->value *= 1000.0;
    }
    if (has_g(block_, 43) && find_word(block_, 'H') == nullptr) {
        // LinuxCNC's G43 without H takes the loaded tool's length.
        std::uint32_t column = 1;
        for (const Word& w : block_.words) {
            if (w.letter == 'G' && w.value == 43) column = w.column;
        }
        // A tool change in the same block comes first: G43 then takes the new tool.
        double tool = static_cast<double>(executor_.modal_view().tool);
        const bool changes = std::any_of(block_.words.begin(), block_.words.end(),
                                         [](const Word& w) { return w.letter == 'M' && w.value == 6; });
        if (const Word* t = find_word(block_, 'T'); t != nullptr && changes) tool = t->value;
        block_.words.push_back(Word{'H', tool, true, column, -1});
    }
    comp_from_loaded_tool();
    for (Word& w : block_.words) {
        if (w.letter == 'G' && std::abs(w.value - 61.1) < 1e-9) w.value = 61;  // exact path: as G61 here
    }
    std::vector<Block> repeats;
    if (auto error = translate_polar(repeats)) return error;
    add_motion_to_here();
    run_list_.push_back(block_);
    repeats_from_ = run_list_.size();
    for (Block& b : repeats) run_list_.push_back(std::move(b));
    return std::nullopt;
}

std::optional<Diagnostic> NgcRunner::check_tool_numbers() const {
    // LinuxCNC looks every T and M61 Q up in its tool table and stops on a tool it lacks
    // (tool 0, the empty spindle, is always there). With no table given nckit cannot know.
    if (machine_.tools.empty()) return std::nullopt;
    const bool m61 = std::any_of(block_.words.begin(), block_.words.end(),
                                 [](const Word& w) { return w.letter == 'M' && w.value == 61; });
    for (const Word& w : block_.words) {
        if (w.letter != 'T' && !(m61 && w.letter == 'Q')) continue;
        if (w.value < 1 || w.value != std::floor(w.value) || w.value > 1e9) continue;  // the Executor's checks
        const int number = static_cast<int>(w.value);
        if (machine_.tools.find(number) == nullptr) {
            return fail(w.column, fmt::format("requested tool {} not found in the tool table", number));
        }
    }
    return std::nullopt;
}

void NgcRunner::split_dwell(Word& p) {
    // G4 beside a move (`G4 P.001 G0 X1 Y1`): LinuxCNC dwells first, then moves. The dwell
    // runs as a block of its own, since the Executor would read X as the dwell time.
    const bool moves = std::any_of(block_.words.begin(), block_.words.end(), [](const Word& w) {
        return is_axis_letter(w.letter) || w.letter == '@' || w.letter == '^';
    });
    if (!moves) {
        p.letter = 'X';
        return;
    }
    Block pause;
    pause.location = block_.location;
    for (const Word& w : block_.words) {
        if (w.letter == 'G' && w.value == 4) pause.words.push_back(w);
    }
    pause.words.push_back(Word{'X', p.value, true, p.column, -1});
    run_list_.push_back(std::move(pause));
    std::erase_if(block_.words, [](const Word& w) { return w.letter == 'P' || (w.letter == 'G' && w.value == 4); });
}

void NgcRunner::comp_from_loaded_tool() {
    // G41/G42 without D, or with D0, take the radius of the tool in the spindle (LinuxCNC's tool
    // table row 0); with the spindle empty that is a radius of 0, as G41.1 D0 says.
    for (Word& w : block_.words) {
        if (w.letter != 'G' || (w.value != 41 && w.value != 42)) continue;
        Word* d = find_word(block_, 'D');
        if (d != nullptr && d->value != 0) return;
        const int loaded = executor_.modal_view().tool_in_spindle;
        if (loaded == 0) w.value = w.value == 41 ? 41.1 : 42.1;
        if (d != nullptr) {
            d->value = loaded;
        } else {
            block_.words.push_back(Word{'D', static_cast<double>(loaded), true, w.column, -1});
        }
        return;
    }
}

void NgcRunner::add_motion_to_here() {
    // LinuxCNC moves to where it is when a block names G0 or G1 without an axis word (`G0 S1000`,
    // `G1 F100`): a zero-length move, which ends blending there. The Executor moves only for axis
    // words, so the block gets the current X.
    const Word* motion = nullptr;
    for (const Word& w : block_.words) {
        if (w.letter == 'G' && (w.value == 0 || w.value == 1)) motion = &w;
        if (w.letter == 'G' && (w.value == 4 || w.value == 10 || w.value == 28 || w.value == 30 || w.value == 52 ||
                                w.value == 53 || w.value == 92)) {
            return;  // those take axis words for themselves
        }
        if (axis_from_letter(w.letter).has_value()) return;
    }
    if (motion == nullptr || machine_.axes.empty()) return;
    const char axis_char = letter(machine_.axes.front().axis);
    const bool incremental = executor_.modal_view().incremental;
    const double here = incremental ? 0.0 : axis_position(axis_char).value_or(0.0);
    block_.words.push_back(Word{axis_char, here, true, motion->column, -1});
}

}  // namespace nckit::interp::ngc
