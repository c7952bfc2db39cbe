#include "macro_syntax.hpp"

#include "macro_expression.hpp"
#include "nckit/gcode/macro_alarms.hpp"

#include <array>

namespace nckit::gcode {

namespace {

std::optional<Diagnostic> loop_number(Cursor& cursor, Block& block, int& loop) {
    cursor.skip_blanks();
    std::uint32_t column = cursor.column();
    int value = 0;
    int digits = 0;
    while (!cursor.at_end() && is_digit(cursor.line[cursor.pos])) {
        value = value * 10 + (cursor.line[cursor.pos] - '0');
        ++cursor.pos;
        if (++digits > 3) break;
    }
    if (digits == 0 || value < 1 || value > 3) {
        Diagnostic d = error_at(block.at_column(column), "loop-number", "loop number must be 1, 2 or 3 (DO1..DO3)");
        d.alarm = alarm::loop_number;
        return d;
    }
    loop = value;
    return std::nullopt;
}

}  // namespace

void Cursor::skip_blanks() {
    while (pos < line.size() && is_blank(line[pos])) ++pos;
}

bool Cursor::at_end() {
    skip_blanks();
    return pos >= line.size();
}

char Cursor::peek() {
    skip_blanks();
    return pos < line.size() ? upper(line[pos]) : '\0';
}

bool Cursor::accept_keyword(std::string_view keyword) {
    skip_blanks();
    std::size_t p = pos;
    for (char k : keyword) {
        while (p < line.size() && is_blank(line[p])) ++p;
        if (p >= line.size() || upper(line[p]) != k) return false;
        ++p;
    }
    pos = p;
    return true;
}

bool at_statement(Cursor cursor) {
    if (cursor.peek() == '#') return true;
    static constexpr std::array<std::string_view, 5> keywords{"IF", "GOTO", "WHILE", "DO", "END"};
    for (std::string_view keyword : keywords) {
        Cursor look = cursor;
        if (look.accept_keyword(keyword)) return true;
    }
    // Fanuc reads a keyword from its first two letters: `WH [..] DO1` is WHILE, `GO 10` GOTO,
    // `EN1` END1.
    Cursor look = cursor;
    return accept_abbreviation(look, "WH", [](char c) { return c == '['; }) ||
           accept_abbreviation(look, "GO", starts_number) || accept_abbreviation(look, "EN", is_digit);
}

std::optional<Diagnostic> parse_word_expression(Cursor& cursor, Block& block, Word& word) {
    ExpressionParser parser(cursor, block);
    std::int32_t root = -1;
    if (auto e = parser.unary(root)) return e;
    word.expr = root;
    word.has_decimal_point = true;  // a computed value is never read in least increments
    return std::nullopt;
}

std::optional<Diagnostic> parse_statement(Cursor& cursor, Block& block) {
    MacroStatement& s = block.statement;
    s.column = (cursor.skip_blanks(), cursor.column());
    ExpressionParser parser(cursor, block);
    auto assignment = [&]() -> std::optional<Diagnostic> {
        if (cursor.peek() != '#') return parser.format_error(cursor.column(), "'#' expected: an assignment");
        if (auto e = parser.variable(s.target)) return e;
        if (cursor.peek() != '=') return parser.format_error(cursor.column(), "'=' expected after the variable");
        ++cursor.pos;
        return parser.comparison(s.value);
    };
    if (cursor.peek() == '#') {
        s.kind = StatementKind::assign;
        return assignment();
    }
    if (cursor.accept_keyword("IF")) {
        if (cursor.peek() != '[') return parser.format_error(cursor.column(), "'[' expected after IF");
        if (auto e = parser.comparison(s.condition)) return e;
        if (cursor.accept_keyword("GOTO") || accept_abbreviation(cursor, "GO", starts_number)) {
            s.kind = StatementKind::if_goto;
            return parser.unary(s.value);
        }
        if (cursor.accept_keyword("THEN") || accept_abbreviation(cursor, "TH", [](char c) { return c == '#'; })) {
            s.kind = StatementKind::if_then;
            return assignment();
        }
        return parser.format_error(cursor.column(), "GOTO or THEN expected after IF [condition]");
    }
    if (cursor.accept_keyword("GOTO") || accept_abbreviation(cursor, "GO", starts_number)) {
        s.kind = StatementKind::go_to;
        return parser.unary(s.value);
    }
    if (cursor.accept_keyword("WHILE") || accept_abbreviation(cursor, "WH", [](char c) { return c == '['; })) {
        s.kind = StatementKind::while_do;
        if (cursor.peek() != '[') return parser.format_error(cursor.column(), "'[' expected after WHILE");
        if (auto e = parser.comparison(s.condition)) return e;
        if (!cursor.accept_keyword("DO"))
            return parser.format_error(cursor.column(), "DO expected after WHILE [condition]");
        return loop_number(cursor, block, s.loop);
    }
    if (cursor.accept_keyword("DO")) {
        s.kind = StatementKind::do_loop;
        return loop_number(cursor, block, s.loop);
    }
    if (cursor.accept_keyword("END") || accept_abbreviation(cursor, "EN", is_digit)) {
        s.kind = StatementKind::end_loop;
        return loop_number(cursor, block, s.loop);
    }
    return parser.format_error(cursor.column(), "unknown macro statement");
}

}  // namespace nckit::gcode
