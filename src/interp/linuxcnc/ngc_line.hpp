#pragma once
// One line of a LinuxCNC RS-274/NGC program as read, before any value is known: its words and
// parameter settings hold expression trees, its O-word its label and keyword. Evaluation and
// control flow belong to NgcRunner; this file only says what a line holds.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "nckit/core/diagnostic.hpp"
#include "nckit/core/source_location.hpp"

namespace nckit::interp::ngc {

enum class Op : std::uint8_t {
    number,     //!< literal `value`
    parameter,  //!< `#n` (n in `value`) or `#[expr]` / `##n` (index from child `a`)
    named,      //!< `#<name>`: `name` indexes NgcLine::names
    exists,     //!< `EXISTS[#<name>]`
    negate,
    power,  //!< `**`
    multiply,
    divide,
    mod,
    add,
    subtract,
    eq,
    ne,
    gt,
    ge,
    lt,
    le,
    logical_and,
    logical_or,
    logical_xor,
    function  //!< `function` of a (ATAN of a and b)
};

enum class Function : std::uint8_t { abs, acos, asin, atan, cos, exp, fix, fup, ln, round, sin, sqrt, tan };

struct Node {
    Op op = Op::number;
    Function function = Function::abs;
    std::int32_t a = -1;
    std::int32_t b = -1;
    double value = 0;
    std::int32_t name = -1;
    std::uint32_t column = 0;  //!< 1-based column in the original line
};

//! A letter and the expression giving its value (`X[#1*2]`, `G1`).
struct NgcWord {
    char letter = 0;  //!< upper case
    std::int32_t expr = -1;
    std::uint32_t column = 0;
};

//! `#target = value`; all of a line's settings happen together, after the line is read.
struct Setting {
    std::int32_t target = -1;  //!< a parameter or named node
    std::int32_t value = -1;
    std::uint32_t column = 0;
};

enum class OKind : std::uint8_t {
    none,
    sub,
    endsub,
    call,
    return_,
    do_,
    while_,
    endwhile,
    repeat,
    endrepeat,
    if_,
    elseif,
    else_,
    endif,
    break_,
    continue_,
    bare  //!< `O1000` alone: a Fanuc-style program number
};

struct OWord {
    OKind kind = OKind::none;
    std::string label;               //!< `name` of o<name>, or the digits of o100
    std::int32_t expr = -1;          //!< condition, repeat count or return value
    std::int32_t label_expr = -1;    //!< o[expr] and o#1: the number, known when the line runs
    std::vector<std::int32_t> args;  //!< call arguments
    std::uint32_t column = 0;
    bool named = false;  //!< o<name>, not o100

    //! As written, for messages: `o<name>` or `o100`.
    [[nodiscard]] std::string shown() const { return named ? "o<" + label + ">" : "o" + label; }
};

enum class CommentKind : std::uint8_t { plain, msg, debug, print, abort };

struct Comment {
    CommentKind kind = CommentKind::plain;
    std::string text;  //!< after the `msg,` etc.
    std::uint32_t column = 0;
};

struct NgcLine {
    SourceLocation location;
    bool block_delete = false;
    bool percent = false;  //!< a `%` line
    std::vector<Node> nodes;
    std::vector<std::string> names;
    std::vector<NgcWord> words;  //!< N words are dropped
    std::vector<Setting> settings;
    OWord oword;
    std::vector<Comment> comments;

    void clear() {
        block_delete = false;
        percent = false;
        nodes.clear();
        names.clear();
        words.clear();
        settings.clear();
        oword = OWord{};
        comments.clear();
    }
    [[nodiscard]] bool empty() const {
        return words.empty() && settings.empty() && oword.kind == OKind::none && comments.empty();
    }
    [[nodiscard]] SourceLocation at(std::uint32_t column) const {
        SourceLocation where = location;
        where.column = column == 0 ? 1 : column;
        return where;
    }
};

//! Reads `text` into `line` (whose location must name the line). LinuxCNC's rules: case and
//! blanks do not matter outside comments; `;` and `( )` are comments.
[[nodiscard]] std::optional<Diagnostic> parse_ngc_line(std::string_view text, NgcLine& line);

//! Named parameters are spelled without case and blanks: `#<Tool Dia>` is `#<tooldia>`.
[[nodiscard]] std::string normal_name(std::string_view name);

}  // namespace nckit::interp::ngc
