#pragma once
// Fanuc Custom Macro B expressions as the parser leaves them: a small tree stored flat in the
// block, so parsing a line allocates nothing once the block's vectors have grown.
#include <cstdint>
#include <vector>

namespace nckit {

enum class ExprOp : std::uint8_t {
    number,    //!< literal `value`
    variable,  //!< `#n` (index in `value`) or `#[expr]` (index from child `a`)
    negate,    //!< -a
    add,
    subtract,
    multiply,
    divide,
    mod,
    bit_and,
    bit_or,
    bit_xor,  //!< AND OR XOR: bitwise on integer values
    eq,
    ne,
    gt,
    ge,
    lt,
    le,       //!< comparisons, in IF and WHILE conditions
    function  //!< `function` applied to a (and b for two-argument forms)
};

enum class ExprFunction : std::uint8_t {
    sin,
    cos,
    tan,
    asin,
    acos,
    atan,
    sqrt,
    abs,
    round,
    fix,
    fup,
    ln,
    exp,
    pow,
    adp,
    bin,
    bcd
};

struct ExprNode {
    ExprOp op = ExprOp::number;
    ExprFunction function = ExprFunction::sin;
    std::int32_t a = -1;       //!< first operand (node index), -1 when none
    std::int32_t b = -1;       //!< second operand (node index), -1 when none
    double value = 0;          //!< literal, or the variable number for a direct `#n`
    std::uint32_t column = 0;  //!< 1-based column where the node starts, for alarms
};

//! The nodes of every expression in one block; an expression is named by its root's index.
using ExprArena = std::vector<ExprNode>;

}  // namespace nckit
