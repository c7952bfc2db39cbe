#pragma once
#include <cstdint>
#include <vector>

#include "nckit/core/source_location.hpp"

namespace nckit {

//! One address word as written: `X-12.5` is {'X', -12.5, true}.
struct Word {
    char letter = 0;                //!< upper case
    double value = 0;               //!< as written, before unit or least-increment scaling
    bool has_decimal_point = false; //!< `X10` and `X10.` mean different things on some controls
    std::uint32_t column = 0;       //!< 1-based column of the letter
};

//! One line of a program, parsed but not yet understood: no modal state, no semantics.
struct Block {
    SourceLocation location;        //!< the line; column 1
    bool block_delete = false;      //!< the line starts with '/'
    bool tape_mark = false;         //!< a '%' line
    std::vector<Word> words;        //!< in the order written, N and O included

    void clear() {
        block_delete = false;
        tape_mark = false;
        words.clear();
    }

    [[nodiscard]] SourceLocation at_column(std::uint32_t column) const {
        SourceLocation where = location;
        where.column = column;
        return where;
    }
};

}  // namespace nckit
