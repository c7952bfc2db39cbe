#pragma once
// Parsing of Custom Macro B: expressions in words (`X#1`, `X[#1+2]`), assignments (`#1=...`)
// and the control statements IF, GOTO, WHILE/DO, END. Used by the block parser.
#include <cstdint>
#include <optional>
#include <string_view>

#include "nckit/core/diagnostic.hpp"
#include "nckit/gcode/block.hpp"

namespace nckit::gcode {

//! A position in one line; blanks are skipped between tokens, as everywhere in G-code.
struct Cursor {
    std::string_view line;
    std::size_t pos = 0;

    void skip_blanks();
    [[nodiscard]] bool at_end();
    [[nodiscard]] char peek();  //!< upper-cased next character after blanks, 0 at the end
    [[nodiscard]] std::uint32_t column() const { return static_cast<std::uint32_t>(pos + 1); }
    //! True (and consumed) when the next letters spell `keyword`, in either case.
    bool accept_keyword(std::string_view keyword);
};

//! The value of an address word from its sign on: `#1`, `-#1`, `[expr]`, `-[expr]`. Sets
//! `word.expr` to the expression's root.
[[nodiscard]] std::optional<Diagnostic> parse_word_expression(Cursor& cursor, Block& block, Word& word);

//! A whole macro statement starting at the cursor (`#`, or a keyword IF GOTO WHILE DO END).
[[nodiscard]] std::optional<Diagnostic> parse_statement(Cursor& cursor, Block& block);

//! True when the cursor stands at `#` or at a statement keyword (IF GOTO WHILE DO END).
[[nodiscard]] bool at_statement(Cursor cursor);

}  // namespace nckit::gcode
