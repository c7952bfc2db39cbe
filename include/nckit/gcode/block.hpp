#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "nckit/core/source_location.hpp"
#include "nckit/gcode/expression.hpp"

namespace nckit {

//! One address word as written: `X-12.5` is {'X', -12.5, true}.
struct Word {
    char letter = 0;                 //!< upper case
    double value = 0;                //!< as written, before unit or least-increment scaling
    bool has_decimal_point = false;  //!< `X10` and `X10.` mean different things on some controls
    std::uint32_t column = 0;        //!< 1-based column of the letter
    std::int32_t expr = -1;          //!< root in Block::exprs when the value is an expression
};

enum class StatementKind : std::uint8_t {
    none,
    assign,    //!< `#target = value`
    go_to,     //!< `GOTO value`
    if_goto,   //!< `IF [condition] GOTO value`
    if_then,   //!< `IF [condition] THEN #target = value`
    while_do,  //!< `WHILE [condition] DOm`
    do_loop,   //!< `DOm` without WHILE: loops for ever (until a GOTO leaves)
    end_loop   //!< `ENDm`
};

//! The macro statement of a block, if it has one (a block holds one statement at most).
struct MacroStatement {
    StatementKind kind = StatementKind::none;
    std::int32_t target = -1;     //!< variable node assigned to
    std::int32_t value = -1;      //!< assigned value, or GOTO's sequence number
    std::int32_t condition = -1;  //!< IF / WHILE condition
    int loop = 0;                 //!< m of DOm / ENDm
    std::uint32_t column = 0;     //!< where the statement starts
};

//! One line of a program, parsed but not yet understood: no modal state, no semantics.
struct Block {
    SourceLocation location;    //!< the line; column 1
    bool block_delete = false;  //!< the line starts with '/'
    bool tape_mark = false;     //!< a '%' line
    std::vector<Word> words;    //!< in the order written, N and O included
    ExprArena exprs;            //!< nodes of every expression in the block
    MacroStatement statement;
    std::string comment;  //!< text of the block's first ( ) comment
    //! Fanuc's corner word: `,R5` (letter 'R', round the corner after this move) or `,C2`
    //! (letter 'C', chamfer it); letter 0 when the block has none. Kept apart from `words`, whose
    //! R and C mean other things.
    Word corner;

    void clear() {
        block_delete = false;
        tape_mark = false;
        words.clear();
        exprs.clear();
        statement = MacroStatement{};
        comment.clear();
        corner = Word{};
    }

    [[nodiscard]] SourceLocation at_column(std::uint32_t column) const {
        SourceLocation where = location;
        where.column = column;
        return where;
    }
};

}  // namespace nckit
