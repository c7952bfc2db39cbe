// The expressions of an RS-274/NGC line as LinuxCNC reads them: numbers, parameters (#1,
// #<name>, ##1), functions and binary operators by LinuxCNC's precedence.
#include "ngc_reader.hpp"

#include <array>
#include <cstring>

#include <fmt/format.h>

#include "../../gcode/decimal.hpp"

namespace nckit::interp::ngc {

namespace {

struct FunctionName {
    std::string_view name;
    Function function;
};
// Longer names first where one starts another (asin before abs is not needed; exists apart).
constexpr std::array<FunctionName, 13> functions{{
    {"abs", Function::abs},
    {"acos", Function::acos},
    {"asin", Function::asin},
    {"atan", Function::atan},
    {"cos", Function::cos},
    {"exp", Function::exp},
    {"fix", Function::fix},
    {"fup", Function::fup},
    {"ln", Function::ln},
    {"round", Function::round},
    {"sin", Function::sin},
    {"sqrt", Function::sqrt},
    {"tan", Function::tan},
}};

struct BinaryOp {
    std::string_view token;
    Op op;
    int precedence;  // LinuxCNC's: logic 2, comparison 3, + - 4, * / mod 5, ** 6
};
constexpr std::array<BinaryOp, 15> binary_ops{{
    {"**", Op::power, 6},
    {"*", Op::multiply, 5},
    {"/", Op::divide, 5},
    {"mod", Op::mod, 5},
    {"+", Op::add, 4},
    {"-", Op::subtract, 4},
    {"eq", Op::eq, 3},
    {"ne", Op::ne, 3},
    {"gt", Op::gt, 3},
    {"ge", Op::ge, 3},
    {"lt", Op::lt, 3},
    {"le", Op::le, 3},
    {"and", Op::logical_and, 2},
    {"or", Op::logical_or, 2},
    {"xor", Op::logical_xor, 2},
}};

}  // namespace

std::optional<Diagnostic> Reader::parameter(std::int32_t& out) {
    std::uint32_t col = column();
    ++pos_;  // '#'
    if (peek() == '<') {
        std::size_t close = buffer_.find('>', pos_);
        if (close == std::string::npos) return error(col, "named parameter has no closing '>'");
        std::string name = buffer_.substr(pos_ + 1, close - pos_ - 1);
        if (name.empty()) return error(col, "empty named parameter #<>");
        pos_ = close + 1;
        line_.names.push_back(std::move(name));
        Node node{Op::named};
        node.name = static_cast<std::int32_t>(line_.names.size() - 1);
        node.column = col;
        out = add(node);
        return std::nullopt;
    }
    std::int32_t index = -1;
    if (auto e = value(index)) return e;
    Node node{Op::parameter};
    node.column = col;
    const Node& inner = line_.nodes[static_cast<std::size_t>(index)];
    if (inner.op == Op::number) {
        node.value = inner.value;
        line_.nodes.pop_back();
    } else {
        node.a = index;
    }
    out = add(node);
    return std::nullopt;
}

//! LinuxCNC's "real value": a number, a parameter, a bracketed expression, a function, or a
//! sign before any of these.
std::optional<Diagnostic> Reader::value(std::int32_t& out) {
    std::uint32_t col = column();
    char c = peek();
    if (++depth_ > max_depth) return error(col, "expression nested too deeply");
    std::optional<Diagnostic> result;
    if (c == '[') {
        result = expression(out);
    } else if (c == '#') {
        result = parameter(out);
    } else if (c == '-' || c == '+') {
        ++pos_;
        std::int32_t operand = -1;
        result = value(operand);
        if (!result) out = c == '-' ? add(Node{Op::negate, Function::abs, operand, -1, 0, -1, col}) : operand;
    } else if (is_lower(c)) {
        result = function(out);
    } else {
        result = number(out);
    }
    --depth_;
    return result;
}

std::optional<Diagnostic> Reader::number(std::int32_t& out) {
    std::uint32_t col = column();
    std::size_t start = pos_;
    bool point = false;
    while (is_digit(peek()) || (peek() == '.' && !point)) {
        point = point || peek() == '.';
        ++pos_;
    }
    std::size_t n = pos_ - start;
    if (n == 0 || (n == 1 && point)) {
        if (pos_ >= buffer_.size()) return error(col, "missing value at the end of the line");
        return error(col, fmt::format("bad number format ('{}')", buffer_[pos_]));
    }
    if (n >= 64) return error(col, "number has too many digits");
    std::optional<double> v = gcode::parse_decimal(buffer_.data() + start, n);
    if (!v) return error(col, "number out of range");
    out = add(Node{Op::number, Function::abs, -1, -1, *v, -1, col});
    return std::nullopt;
}

std::optional<Diagnostic> Reader::function(std::int32_t& out) {
    std::uint32_t col = column();
    if (accept("exists")) {
        // EXISTS[#<name>]: defined or not; EXISTS[#n]: n is a parameter number (1-5601).
        if (peek() != '[' || peek(1) != '#') return error(col, "EXISTS takes a parameter: EXISTS[#<name>]");
        ++pos_;
        std::int32_t param = -1;
        if (auto e = parameter(param)) return e;
        if (peek() != ']') return error(column(), "expected ']' after the parameter of EXISTS");
        ++pos_;
        out = add(Node{Op::exists, Function::abs, param, -1, 0, -1, col});
        return std::nullopt;
    }
    for (const FunctionName& f : functions) {
        if (buffer_.compare(pos_, f.name.size(), f.name) != 0 || buffer_[pos_ + f.name.size()] != '[') continue;
        pos_ += f.name.size();
        std::int32_t a = -1;
        std::int32_t b = -1;
        if (auto e = expression(a)) return e;
        if (f.function == Function::atan) {
            if (peek() != '/' || peek(1) != '[') return error(column(), "ATAN needs a second argument: ATAN[y]/[x]");
            ++pos_;
            if (auto e = expression(b)) return e;
        }
        out = add(Node{Op::function, f.function, a, b, 0, -1, col});
        return std::nullopt;
    }
    return error(col, "unknown word or function starting with " + std::string(1, peek()));
}

std::optional<Diagnostic> Reader::expression(std::int32_t& out) {
    std::uint32_t open = column();
    ++pos_;  // '['
    if (auto e = climb(out, 1)) return e;
    if (peek() != ']') {
        if (pos_ >= buffer_.size()) return error(open, "unclosed expression: ']' missing");
        return error(column(), "unknown operation or ']' missing");
    }
    ++pos_;
    return std::nullopt;
}

//! Binary operators by precedence climbing; all of LinuxCNC's are left-associative.
std::optional<Diagnostic> Reader::climb(std::int32_t& out, int min_precedence) {
    if (auto e = value(out)) return e;
    for (;;) {
        const BinaryOp* found = nullptr;
        for (const BinaryOp& op : binary_ops) {
            if (buffer_.compare(pos_, op.token.size(), op.token) == 0) {
                found = &op;
                break;
            }
        }
        if (found == nullptr || found->precedence < min_precedence) return std::nullopt;
        std::uint32_t col = column();
        pos_ += found->token.size();
        std::int32_t right = -1;
        if (auto e = climb(right, found->precedence + 1)) return e;
        out = add(Node{found->op, Function::abs, out, right, 0, -1, col});
    }
}

}  // namespace nckit::interp::ngc
