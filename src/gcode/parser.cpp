#include "nckit/gcode/parser.hpp"

#include <cstdint>
#include <vector>

#include <fmt/format.h>

#include "decimal.hpp"
#include "macro_syntax.hpp"
#include "nckit/gcode/macro_alarms.hpp"

namespace nckit {

namespace {

bool is_blank(char c) {
    return c == ' ' || c == '\t' || c == '\r';
}
bool is_digit(char c) {
    return c >= '0' && c <= '9';
}
bool is_letter(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
}
char upper(char c) {
    return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c;
}

//! A cursor over one line that skips the blanks the syntax allows anywhere.
class LineParser {
public:
    LineParser(std::string_view line, Block& block) : line_(line), block_(block) {}

    std::optional<Diagnostic> run() {
        skip_blanks();
        if (pos_ < line_.size() && line_[pos_] == '/') {
            block_.block_delete = true;
            ++pos_;
        }
        if (is_tape_mark()) {
            block_.tape_mark = true;
            return std::nullopt;
        }
        while (true) {
            skip_blanks();
            if (pos_ >= line_.size()) return std::nullopt;
            char c = line_[pos_];
            if (c == ';') return std::nullopt;
            if (c == '(') {
                if (auto error = skip_comment()) return error;
                continue;
            }
            if (c == '#' || (is_letter(c) && letter_follows() && gcode::at_statement(gcode::Cursor{line_, pos_}))) {
                if (auto error = parse_statement()) return error;
                continue;
            }
            if (is_letter(c)) {
                if (block_.statement.kind != StatementKind::none) return statement_not_alone(column());
                if (auto error = parse_word()) return error;
                continue;
            }
            if (c == ',' && block_.statement.kind == StatementKind::none) {
                if (auto error = parse_corner_word()) return error;
                continue;
            }
            if (c == ':' && block_.words.empty() && block_.statement.kind == StatementKind::none) {
                // ISO 6983's program number: `:1234` is O1234.
                if (auto error = parse_word('O')) return error;
                continue;
            }
            return unexpected(c);
        }
    }

private:
    void skip_blanks() {
        while (pos_ < line_.size() && is_blank(line_[pos_])) ++pos_;
    }

    [[nodiscard]] std::uint32_t column() const { return static_cast<std::uint32_t>(pos_ + 1); }

    Diagnostic error(std::uint32_t col, std::string code, std::string message) const {
        return error_at(block_.at_column(col), std::move(code), std::move(message));
    }

    bool is_tape_mark() {
        std::size_t p = pos_;
        if (p >= line_.size() || line_[p] != '%') return false;
        // Whatever follows on the line is the tape's label (`%MPF100`, `% part 7`), not blocks:
        // Fanuc's tape reader and CAM posts alike treat it so.
        return true;
    }

    //! A comment runs to the ')' that closes its '(': parentheses inside it come in pairs and
    //! nest, as in the example programs of Haas's mill operator's manual (`(0.01" finish pass
    //! (K) on sides)`). One pass over the line bounds it.
    std::optional<Diagnostic> skip_comment() {
        std::size_t text_start = pos_ + 1;
        std::vector<std::uint32_t> open_columns{column()};  // the '(' not closed yet, outermost first
        for (++pos_; pos_ < line_.size(); ++pos_) {
            if (line_[pos_] == '(') {
                open_columns.push_back(column());
            } else if (line_[pos_] == ')') {
                open_columns.pop_back();
                if (!open_columns.empty()) continue;
                // The first comment is kept: `#3000=1 (MESSAGE)` shows it with the alarm.
                if (block_.comment.empty()) block_.comment.assign(line_.substr(text_start, pos_ - text_start));
                ++pos_;
                return std::nullopt;
            }
        }
        if (open_columns.size() > 1) {
            return error(open_columns.back(), "syntax",
                         fmt::format("comment is not closed: the '(' here, inside the comment opened at column {}, "
                                     "has no ')' (parentheses inside a comment come in pairs)",
                                     open_columns.front()));
        }
        return error(open_columns.front(), "syntax", "comment is not closed: '(' without ')'");
    }

    //! `,R5` or `,C2` (blanks allowed after the comma, as in `Y 0, C 8`): Fanuc's corner
    //! rounding and chamfer. A plain number only; one per block.
    std::optional<Diagnostic> parse_corner_word() {
        const std::uint32_t comma = column();
        ++pos_;
        skip_blanks();
        const char letter = pos_ < line_.size() ? upper(line_[pos_]) : '\0';
        if (letter != 'R' && letter != 'C') {
            return error(comma, "syntax", "',' must be followed by R (corner rounding) or C (chamfer)");
        }
        if (block_.corner.letter != 0) return error(comma, "duplicate-word", "two corner words (,R / ,C) in one block");
        if (auto error = parse_word(letter)) return error;
        Word word = block_.words.back();
        block_.words.pop_back();
        if (word.expr >= 0) return error(comma, "syntax", fmt::format(",{} takes a number, not an expression", letter));
        word.column = comma;
        block_.corner = word;
        return std::nullopt;
    }

    Diagnostic statement_not_alone(std::uint32_t col) const {
        Diagnostic d = error(col, "macro-format", "a macro statement must stand alone in its block");
        d.alarm = alarm::format;
        return d;
    }

    //! A macro statement stands alone in its block, after the N number at most.
    std::optional<Diagnostic> parse_statement() {
        std::uint32_t start = column();
        bool only_n = block_.words.empty() || (block_.words.size() == 1 && block_.words[0].letter == 'N');
        if (!only_n || block_.statement.kind != StatementKind::none) return statement_not_alone(start);
        gcode::Cursor cursor{line_, pos_};
        if (auto error = gcode::parse_statement(cursor, block_)) return error;
        pos_ = cursor.pos;
        return std::nullopt;
    }

    std::optional<Diagnostic> unexpected(char c) const {
        if (c == '[' || c == ']') {
            Diagnostic d = error(column(), "macro-format", fmt::format("'{}' out of place", c));
            d.alarm = alarm::format;
            return d;
        }
        // An address takes one operand: X#1+2 is a macro format error that brackets fix.
        bool after_expression = !block_.words.empty() && block_.words.back().expr >= 0;
        if (after_expression && (c == '+' || c == '-' || c == '*' || c == '/')) {
            const Word& w = block_.words.back();
            Diagnostic d = error(column(), "macro-format",
                                 fmt::format("an operation in an address needs brackets: {}[...]", w.letter));
            d.alarm = alarm::format;
            return d;
        }
        auto byte = static_cast<unsigned char>(c);
        if (byte < 0x20 || byte >= 0x7f) {
            return error(column(), "syntax", fmt::format("unexpected byte 0x{:02x}", byte));
        }
        return error(column(), "syntax", fmt::format("unexpected character '{}'", c));
    }

    std::optional<Diagnostic> parse_word(char letter = 0) {
        Word word;
        word.letter = letter != 0 ? letter : upper(line_[pos_]);
        word.column = column();
        ++pos_;
        skip_blanks();
        if (starts_expression()) {
            gcode::Cursor cursor{line_, pos_};
            if (auto error = gcode::parse_word_expression(cursor, block_, word)) return error;
            pos_ = cursor.pos;
            block_.words.push_back(word);
            return std::nullopt;
        }
        if (parse_plain_number(word)) {
            block_.words.push_back(word);
            return std::nullopt;
        }
        // Gather sign, digits and point, dropping blanks, into a small buffer.
        char digits[64];
        std::size_t n = 0;
        bool negative = false;
        if (pos_ < line_.size() && (line_[pos_] == '-' || line_[pos_] == '+')) {
            negative = line_[pos_] == '-';
            ++pos_;
            skip_blanks();
        }
        bool any_digit = false;
        for (; pos_ < line_.size(); ++pos_) {
            char c = line_[pos_];
            if (is_blank(c)) continue;
            if (is_digit(c)) {
                any_digit = true;
            } else if (c == '.') {
                if (word.has_decimal_point) {
                    return error(column(), "syntax", "number has two decimal points");
                }
                word.has_decimal_point = true;
            } else {
                break;
            }
            if (n + 1 >= sizeof digits) {
                return error(word.column, "syntax", "number has too many digits");
            }
            digits[n++] = c;
        }
        if (!any_digit) {
            return error(word.column, "syntax", fmt::format("address {} has no number after it", word.letter));
        }
        std::optional<double> value = gcode::parse_decimal(digits, n);
        if (!value) return error(word.column, "syntax", "number out of range");
        word.value = negative ? -*value : *value;
        block_.words.push_back(word);
        return std::nullopt;
    }

    //! The common case, `-12.345` with no blank inside: read straight from the line. False (and
    //! nothing consumed) when the number needs the general path: blanks inside, many digits,
    //! no digits, or a second point.
    bool parse_plain_number(Word& word) {
        static constexpr double powers_of_ten[] = {1e0, 1e1, 1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                                   1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
        std::size_t p = pos_;
        bool negative = false;
        if (p < line_.size() && (line_[p] == '-' || line_[p] == '+')) negative = line_[p++] == '-';
        std::uint64_t mantissa = 0;
        int significant = 0;
        int fraction_digits = 0;
        bool point = false;
        bool any_digit = false;
        for (; p < line_.size(); ++p) {
            char c = line_[p];
            if (is_digit(c)) {
                mantissa = mantissa * 10 + static_cast<std::uint64_t>(c - '0');
                any_digit = true;
                if (mantissa != 0) ++significant;
                if (point) ++fraction_digits;
            } else if (c == '.' && !point) {
                point = true;
            } else {
                break;
            }
        }
        std::size_t after = p;
        while (after < line_.size() && is_blank(line_[after])) ++after;
        bool continues = after < line_.size() && (is_digit(line_[after]) || line_[after] == '.');
        if (!any_digit || continues || significant > 15 || fraction_digits > 15) return false;
        double value = static_cast<double>(mantissa) / powers_of_ten[fraction_digits];
        word.value = negative ? -value : value;
        word.has_decimal_point = point;
        pos_ = p;
        return true;
    }

    //! Keywords (IF, GOTO, WHILE, DO, END) are the only places where a letter follows a letter:
    //! a cheap test that spares ordinary words the keyword search.
    bool letter_follows() const {
        std::size_t p = pos_ + 1;
        while (p < line_.size() && is_blank(line_[p])) ++p;
        return p < line_.size() && is_letter(line_[p]);
    }

    //! After an address: `#`, `[`, or a sign before either, makes the value an expression.
    bool starts_expression() const {
        std::size_t p = pos_;
        if (p < line_.size() && (line_[p] == '-' || line_[p] == '+')) {
            ++p;
            while (p < line_.size() && is_blank(line_[p])) ++p;
        }
        return p < line_.size() && (line_[p] == '#' || line_[p] == '[');
    }

    std::string_view line_;
    Block& block_;
    std::size_t pos_ = 0;
};

}  // namespace

std::optional<Diagnostic> parse_block(std::string_view line, Block& block) {
    block.clear();
    return LineParser(line, block).run();
}

}  // namespace nckit
