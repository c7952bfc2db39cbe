#pragma once
// Small readers of a resolved block's words, shared by the LinuxCNC translations.
#include <cmath>

#include "nckit/gcode/block.hpp"

namespace nckit::interp::ngc {

inline bool has_g(const Block& block, double code) {
    for (const Word& w : block.words) {
        if (w.letter == 'G' && std::abs(w.value - code) < 1e-9) return true;
    }
    return false;
}

inline Word* find_word(Block& block, char letter) {
    for (Word& w : block.words) {
        if (w.letter == letter) return &w;
    }
    return nullptr;
}

inline bool is_axis_letter(char letter) {
    switch (letter) {
        case 'X':
        case 'Y':
        case 'Z':
        case 'A':
        case 'B':
        case 'C':
        case 'U':
        case 'V':
        case 'W':
            return true;
        default:
            return false;
    }
}

}  // namespace nckit::interp::ngc
