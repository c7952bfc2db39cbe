#pragma once
// The expression grammar of Custom Macro B (Fanuc's precedence) and the character tests the
// statement parser shares with it. Internal to the block parser.
#include <cstdint>
#include <optional>
#include <string>

#include "macro_syntax.hpp"

namespace nckit::gcode {

inline bool is_blank(char c) {
    return c == ' ' || c == '\t' || c == '\r';
}
inline bool is_digit(char c) {
    return c >= '0' && c <= '9';
}
inline char upper(char c) {
    return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c;
}
inline bool starts_number(char c) {
    return is_digit(c) || c == '#' || c == '[' || c == '.';
}

//! An abbreviation that stands for a statement keyword only when followed by `next_ok`.
template <typename Next>
inline bool accept_abbreviation(Cursor& cursor, std::string_view abbreviation, Next next_ok) {
    Cursor look = cursor;
    if (!look.accept_keyword(abbreviation) || !next_ok(look.peek())) return false;
    cursor = look;
    return true;
}

struct FunctionName;

//! Recursive descent over Fanuc's precedence: functions and brackets; * / AND MOD; + - OR XOR;
//! comparisons. Each node goes into `block.exprs`; `out` receives the root's index.
class ExpressionParser {
public:
    ExpressionParser(Cursor& cursor, Block& block) : c_(cursor), block_(block) {}

    std::optional<Diagnostic> comparison(std::int32_t& out);
    std::optional<Diagnostic> unary(std::int32_t& out);
    std::optional<Diagnostic> variable(std::int32_t& out);
    std::optional<Diagnostic> format_error(std::uint32_t column, std::string message) const;

private:
    std::optional<Diagnostic> sum(std::int32_t& out);
    std::optional<Diagnostic> term(std::int32_t& out);
    std::optional<Diagnostic> primary(std::int32_t& out);
    std::optional<Diagnostic> bracketed(std::int32_t& out);
    std::optional<Diagnostic> function(const FunctionName& f, std::uint32_t column, std::int32_t& out);
    std::optional<Diagnostic> number(std::int32_t& out);
    std::int32_t add(const ExprNode& node);

    Cursor& c_;
    Block& block_;
    int depth_ = 0;
};

}  // namespace nckit::gcode
