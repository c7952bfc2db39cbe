#include "macro_expression.hpp"

#include "decimal.hpp"
#include "nckit/gcode/macro_alarms.hpp"

#include <array>
#include <utility>

#include <fmt/format.h>

namespace nckit::gcode {

constexpr int max_bracket_depth = 5;

struct FunctionName {
    std::string_view name;
    std::string_view abbreviation;  // Fanuc's first two letters; empty where none is accepted
    ExprFunction function;
    int arguments;  // 1, or 2 for POW (ATAN takes 1 or 2)
};

// Full names are tried before any abbreviation, so `SI` never shadows `SQRT`. POW has no
// abbreviation (Fanuc accepts none for it).
constexpr std::array<FunctionName, 17> functions{{
    {"ASIN", "AS", ExprFunction::asin, 1},
    {"ACOS", "AC", ExprFunction::acos, 1},
    {"ATAN", "AT", ExprFunction::atan, 1},
    {"SIN", "SI", ExprFunction::sin, 1},
    {"COS", "CO", ExprFunction::cos, 1},
    {"TAN", "TA", ExprFunction::tan, 1},
    {"SQRT", "SQ", ExprFunction::sqrt, 1},
    {"ABS", "AB", ExprFunction::abs, 1},
    {"ROUND", "RO", ExprFunction::round, 1},
    {"FIX", "FI", ExprFunction::fix, 1},
    {"FUP", "FU", ExprFunction::fup, 1},
    {"LN", "", ExprFunction::ln, 1},
    {"EXP", "EX", ExprFunction::exp, 1},
    {"POW", "", ExprFunction::pow, 2},
    {"ADP", "AD", ExprFunction::adp, 1},
    {"BIN", "BI", ExprFunction::bin, 1},
    {"BCD", "BC", ExprFunction::bcd, 1},
}};

namespace {

//! A keyword or its two-letter abbreviation (Fanuc reads `GO` as GOTO, `AN` as AND ...).
bool accept_keyword_or(Cursor& cursor, std::string_view keyword, std::string_view abbreviation) {
    return cursor.accept_keyword(keyword) || cursor.accept_keyword(abbreviation);
}

}  // namespace

std::optional<Diagnostic> ExpressionParser::comparison(std::int32_t& out) {
    if (auto e = sum(out)) return e;
    static constexpr std::array<std::pair<std::string_view, ExprOp>, 6> ops{{
        {"EQ", ExprOp::eq},
        {"NE", ExprOp::ne},
        {"GT", ExprOp::gt},
        {"GE", ExprOp::ge},
        {"LT", ExprOp::lt},
        {"LE", ExprOp::le},
    }};
    for (const auto& [name, op] : ops) {
        std::uint32_t column = (c_.skip_blanks(), c_.column());
        if (!c_.accept_keyword(name)) continue;
        std::int32_t right = -1;
        if (auto e = sum(right)) return e;
        out = add(ExprNode{op, ExprFunction::sin, out, right, 0, column});
        return std::nullopt;
    }
    return std::nullopt;
}

std::optional<Diagnostic> ExpressionParser::sum(std::int32_t& out) {
    if (auto e = term(out)) return e;
    for (;;) {
        std::uint32_t column = (c_.skip_blanks(), c_.column());
        ExprOp op;
        char next = c_.peek();
        if (next == '+' || next == '-') {
            ++c_.pos;
            op = next == '+' ? ExprOp::add : ExprOp::subtract;
        } else if (c_.accept_keyword("OR")) {
            op = ExprOp::bit_or;
        } else if (accept_keyword_or(c_, "XOR", "XO")) {
            op = ExprOp::bit_xor;
        } else {
            return std::nullopt;
        }
        std::int32_t right = -1;
        if (auto e = term(right)) return e;
        out = add(ExprNode{op, ExprFunction::sin, out, right, 0, column});
    }
}

std::optional<Diagnostic> ExpressionParser::term(std::int32_t& out) {
    if (auto e = unary(out)) return e;
    for (;;) {
        std::uint32_t column = (c_.skip_blanks(), c_.column());
        ExprOp op;
        char next = c_.peek();
        if (next == '*') {
            ++c_.pos;
            op = ExprOp::multiply;
        } else if (next == '/') {
            ++c_.pos;
            op = ExprOp::divide;
        } else if (accept_keyword_or(c_, "AND", "AN")) {
            op = ExprOp::bit_and;
        } else if (accept_keyword_or(c_, "MOD", "MO")) {
            op = ExprOp::mod;
        } else {
            return std::nullopt;
        }
        std::int32_t right = -1;
        if (auto e = unary(right)) return e;
        out = add(ExprNode{op, ExprFunction::sin, out, right, 0, column});
    }
}

std::optional<Diagnostic> ExpressionParser::unary(std::int32_t& out) {
    std::uint32_t column = (c_.skip_blanks(), c_.column());
    char next = c_.peek();
    if (next == '-' || next == '+') {
        ++c_.pos;
        std::int32_t operand = -1;
        if (auto e = primary(operand)) return e;
        out = next == '-' ? add(ExprNode{ExprOp::negate, ExprFunction::sin, operand, -1, 0, column}) : operand;
        return std::nullopt;
    }
    return primary(out);
}

std::optional<Diagnostic> ExpressionParser::primary(std::int32_t& out) {
    c_.skip_blanks();
    std::uint32_t column = c_.column();
    char next = c_.peek();
    if (next == '#') return variable(out);
    if (next == '[') return bracketed(out);
    if (is_digit(next) || next == '.') return number(out);
    for (const FunctionName& f : functions) {
        if (c_.accept_keyword(f.name)) return function(f, column, out);
    }
    for (const FunctionName& f : functions) {
        if (!f.abbreviation.empty() && accept_abbreviation(c_, f.abbreviation, [](char c) { return c == '['; })) {
            return function(f, column, out);
        }
    }
    if (c_.at_end()) return format_error(column, "expression ends too early");
    return format_error(column, fmt::format("unexpected '{}' in an expression", c_.line[c_.pos]));
}

std::optional<Diagnostic> ExpressionParser::variable(std::int32_t& out) {
    std::uint32_t column = c_.column();
    ++c_.pos;  // '#'
    c_.skip_blanks();
    char next = c_.peek();
    if (next == '[') {
        std::int32_t index = -1;
        if (auto e = bracketed(index)) return e;
        out = add(ExprNode{ExprOp::variable, ExprFunction::sin, index, -1, 0, column});
        return std::nullopt;
    }
    if (!is_digit(next)) {
        return format_error(column, "'#' must be followed by a variable number or '['");
    }
    std::int32_t literal = -1;
    if (auto e = number(literal)) return e;
    double n = block_.exprs[literal].value;
    block_.exprs.pop_back();
    // floor, not a cast to an integer: a literal above 2^63 is whole (and alarm 115 later says
    // it is no variable); casting it would be undefined.
    if (n != std::floor(n)) {
        return format_error(column, "variable number must be a whole number");
    }
    out = add(ExprNode{ExprOp::variable, ExprFunction::sin, -1, -1, n, column});
    return std::nullopt;
}

std::optional<Diagnostic> ExpressionParser::bracketed(std::int32_t& out) {
    std::uint32_t column = c_.column();
    ++c_.pos;  // '['
    if (++depth_ > max_bracket_depth) {
        Diagnostic d = error_at(block_.at_column(column), "bracket-nesting",
                                fmt::format("brackets nested deeper than {}", max_bracket_depth));
        d.alarm = alarm::bracket_nesting;
        return d;
    }
    if (auto e = comparison(out)) return e;
    if (c_.peek() != ']') return format_error(c_.column(), "']' expected");
    ++c_.pos;
    --depth_;
    return std::nullopt;
}

std::optional<Diagnostic> ExpressionParser::function(const FunctionName& f, std::uint32_t column, std::int32_t& out) {
    if (c_.peek() != '[') return format_error(c_.column(), fmt::format("'[' expected after {}", f.name));
    std::uint32_t open = c_.column();
    ++c_.pos;
    if (++depth_ > max_bracket_depth) {
        Diagnostic d = error_at(block_.at_column(open), "bracket-nesting",
                                fmt::format("brackets nested deeper than {}", max_bracket_depth));
        d.alarm = alarm::bracket_nesting;
        return d;
    }
    std::int32_t first = -1;
    std::int32_t second = -1;
    if (auto e = comparison(first)) return e;
    bool two_arguments = f.arguments == 2 || f.function == ExprFunction::atan;
    if (two_arguments && c_.peek() == ',') {
        ++c_.pos;
        if (auto e = comparison(second)) return e;
    }
    if (c_.peek() != ']') return format_error(c_.column(), "']' expected");
    ++c_.pos;
    --depth_;
    if (f.function == ExprFunction::atan && second < 0) {
        // The 0i form ATAN[a]/[b]: a '/' directly followed by '[' is the second argument.
        Cursor look = c_;
        if (look.peek() == '/') {
            ++look.pos;
            if (look.peek() == '[') {
                c_ = look;
                if (auto e = bracketed(second)) return e;
            }
        }
    }
    if (f.arguments == 2 && second < 0) {
        return format_error(column, fmt::format("{} takes two arguments: {}[a,b]", f.name, f.name));
    }
    out = add(ExprNode{ExprOp::function, f.function, first, second, 0, column});
    return std::nullopt;
}

std::optional<Diagnostic> ExpressionParser::number(std::int32_t& out) {
    std::uint32_t column = c_.column();
    char digits[64];
    std::size_t n = 0;
    bool point = false;
    for (; c_.pos < c_.line.size(); ++c_.pos) {
        char ch = c_.line[c_.pos];
        if (is_blank(ch)) continue;
        if (ch == '.') {
            if (point) return format_error(c_.column(), "number has two decimal points");
            point = true;
        } else if (!is_digit(ch)) {
            break;
        }
        if (n + 1 >= sizeof digits) return format_error(column, "number has too many digits");
        digits[n++] = ch;
    }
    if (n == 0) return format_error(column, "number expected");
    std::optional<double> value = parse_decimal(digits, n);
    if (!value) return format_error(column, "bad number");
    out = add(ExprNode{ExprOp::number, ExprFunction::sin, -1, -1, *value, column});
    return std::nullopt;
}

std::optional<Diagnostic> ExpressionParser::format_error(std::uint32_t column, std::string message) const {
    Diagnostic d = error_at(block_.at_column(column), "macro-format", std::move(message));
    d.alarm = alarm::format;
    return d;
}

std::int32_t ExpressionParser::add(const ExprNode& node) {
    block_.exprs.push_back(node);
    return static_cast<std::int32_t>(block_.exprs.size() - 1);
}

}  // namespace nckit::gcode
