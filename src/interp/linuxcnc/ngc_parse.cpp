// Reading one RS-274/NGC line the way LinuxCNC does: blanks and case are dropped outside
// comments first, then words, parameter settings, an O-word and expressions are read from what
// is left. Nothing is evaluated here.
#include <array>
#include <cstring>

#include <fmt/format.h>

#include "../../gcode/decimal.hpp"
#include "ngc_line.hpp"

namespace nckit::interp::ngc {

namespace {

bool is_digit(char c) {
    return c >= '0' && c <= '9';
}
bool is_lower(char c) {
    return c >= 'a' && c <= 'z';
}
char lower(char c) {
    return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
}

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

struct OKeyword {
    std::string_view name;
    OKind kind;
};
constexpr std::array<OKeyword, 15> o_keywords{{
    {"sub", OKind::sub},
    {"endsub", OKind::endsub},
    {"call", OKind::call},
    {"return", OKind::return_},
    {"do", OKind::do_},
    {"while", OKind::while_},
    {"endwhile", OKind::endwhile},
    {"repeat", OKind::repeat},
    {"endrepeat", OKind::endrepeat},
    {"if", OKind::if_},
    {"elseif", OKind::elseif},
    {"else", OKind::else_},
    {"endif", OKind::endif},
    {"break", OKind::break_},
    {"continue", OKind::continue_},
}};

class Reader {
public:
    explicit Reader(NgcLine& line) : line_(line) {}

    //! Blanks and case out, comments aside; columns kept for messages.
    std::optional<Diagnostic> normalise(std::string_view text) {
        for (std::size_t i = 0; i < text.size(); ++i) {
            char c = text[i];
            if (c == ' ' || c == '\t' || c == '\r') continue;
            if (c == ';') {
                add_comment(text.substr(i + 1), static_cast<std::uint32_t>(i + 1));
                break;
            }
            if (c == '(') {
                std::size_t close = i + 1;
                while (close < text.size() && text[close] != ')') {
                    if (text[close] == '(') return error(static_cast<std::uint32_t>(close + 1), "nested comment found");
                    ++close;
                }
                if (close >= text.size()) return error(static_cast<std::uint32_t>(i + 1), "unclosed comment found");
                add_comment(text.substr(i + 1, close - i - 1), static_cast<std::uint32_t>(i + 1));
                i = close;
                continue;
            }
            buffer_ += lower(c);
            columns_.push_back(static_cast<std::uint32_t>(i + 1));
        }
        columns_.push_back(static_cast<std::uint32_t>(text.size() + 1));
        return std::nullopt;
    }

    std::optional<Diagnostic> line() {
        if (peek() == '/') {
            line_.block_delete = true;
            ++pos_;
        }
        if (peek() == '%') {
            line_.percent = true;
            return std::nullopt;
        }
        if (peek() == 'n') {
            ++pos_;
            std::size_t start = pos_;
            while (is_digit(peek()) || peek() == '.') ++pos_;
            if (pos_ == start) return error(column(), "bad number format after n");
        }
        if (peek() == 'o') return oword();
        while (pos_ < buffer_.size()) {
            char c = peek();
            if (c == '#') {
                if (auto e = setting()) return e;
            } else if ((is_lower(c) && c != 'n' && c != 'o') || c == '@' || c == '^') {
                NgcWord word;  // `@` and `^`: polar radius and angle
                word.letter = is_lower(c) ? static_cast<char>(c - 'a' + 'A') : c;
                word.column = column();
                ++pos_;
                if (auto e = value(word.expr)) return e;
                line_.words.push_back(word);
            } else if (c == 'n') {
                return error(column(), "line number not at the start of the line (n word)");
            } else if (c == 'o') {
                return error(column(), "an O-word must start its line");
            } else {
                return error(column(), fmt::format("bad character '{}' used", c));
            }
        }
        return std::nullopt;
    }

private:
    [[nodiscard]] char peek(std::size_t ahead = 0) const {
        return pos_ + ahead < buffer_.size() ? buffer_[pos_ + ahead] : '\0';
    }
    [[nodiscard]] std::uint32_t column() const { return columns_[std::min(pos_, columns_.size() - 1)]; }
    [[nodiscard]] bool accept(std::string_view token) {
        if (buffer_.compare(pos_, token.size(), token) != 0) return false;
        pos_ += token.size();
        return true;
    }

    Diagnostic error(std::uint32_t col, std::string message) const {
        return error_at(line_.at(col), "ngc-syntax", std::move(message));
    }

    void add_comment(std::string_view body, std::uint32_t col) {
        Comment comment;
        comment.column = col;
        std::string head;
        for (std::size_t i = 0; i < body.size() && i < 8; ++i) {
            if (body[i] != ' ' && body[i] != '\t') head += lower(body[i]);
        }
        static constexpr std::array<std::pair<std::string_view, CommentKind>, 4> kinds{
            {{"msg,", CommentKind::msg},
             {"debug,", CommentKind::debug},
             {"print,", CommentKind::print},
             {"abort,", CommentKind::abort}}};
        comment.text = std::string(body);
        for (const auto& [prefix, kind] : kinds) {
            if (head.starts_with(prefix)) {
                comment.kind = kind;
                comment.text = std::string(body.substr(body.find(',') + 1));
                break;
            }
        }
        line_.comments.push_back(std::move(comment));
    }

    std::int32_t add(Node node) {
        line_.nodes.push_back(node);
        return static_cast<std::int32_t>(line_.nodes.size() - 1);
    }

    std::optional<Diagnostic> oword() {
        OWord& o = line_.oword;
        o.column = column();
        ++pos_;  // 'o'
        if (peek() == '<') {
            std::size_t close = buffer_.find('>', pos_);
            if (close == std::string::npos) return error(column(), "named O-word has no closing '>'");
            o.label = buffer_.substr(pos_ + 1, close - pos_ - 1);
            if (o.label.empty()) return error(column(), "empty O-word name");
            pos_ = close + 1;
            o.named = true;
        } else if (is_digit(peek())) {
            std::size_t start = pos_;
            while (is_digit(peek())) ++pos_;
            // o0100 and o100 name the same label, as LinuxCNC reads the number.
            std::size_t first = buffer_.find_first_not_of('0', start);
            o.label = first < pos_ ? buffer_.substr(first, pos_ - first) : "0";
        } else if (peek() == '[' || peek() == '#') {
            if (auto e = value(o.label_expr)) return e;  // o[#2 * 10]: the number is computed
        } else {
            return error(column(), "O-word needs a number, a <name> or a [value]");
        }
        std::size_t start = pos_;
        while (is_lower(peek())) ++pos_;
        std::string_view keyword(buffer_.data() + start, pos_ - start);
        o.kind = OKind::none;
        for (const OKeyword& k : o_keywords) {
            if (k.name == keyword) o.kind = k.kind;
        }
        if (keyword.empty() && pos_ >= buffer_.size()) o.kind = OKind::bare;
        if (o.kind == OKind::none) {
            return error(columns_[start], fmt::format("unknown command in O-word line: '{}'", keyword));
        }
        switch (o.kind) {
            case OKind::call:
                while (peek() == '[') {
                    std::int32_t arg = -1;
                    if (auto e = expression(arg)) return e;
                    o.args.push_back(arg);
                }
                break;
            case OKind::while_:
            case OKind::if_:
            case OKind::elseif:
            case OKind::repeat:
                if (peek() != '[') {
                    return error(column(), fmt::format("left bracket missing after '{}'", keyword));
                }
                if (auto e = expression(o.expr)) return e;
                break;
            case OKind::return_:
            case OKind::endsub:
                if (peek() == '[') {
                    if (auto e = expression(o.expr)) return e;
                }
                break;
            default:
                break;
        }
        if (pos_ < buffer_.size()) return error(column(), "unexpected character after O-word");
        return std::nullopt;
    }

    std::optional<Diagnostic> setting() {
        Setting s;
        s.column = column();
        if (auto e = parameter(s.target)) return e;
        if (peek() != '=') return error(column(), "equal sign missing in parameter setting");
        ++pos_;
        if (auto e = value(s.value)) return e;
        line_.settings.push_back(s);
        return std::nullopt;
    }

    std::optional<Diagnostic> parameter(std::int32_t& out) {
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
    std::optional<Diagnostic> value(std::int32_t& out) {
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

    std::optional<Diagnostic> number(std::int32_t& out) {
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

    std::optional<Diagnostic> function(std::int32_t& out) {
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
                if (peek() != '/' || peek(1) != '[')
                    return error(column(), "ATAN needs a second argument: ATAN[y]/[x]");
                ++pos_;
                if (auto e = expression(b)) return e;
            }
            out = add(Node{Op::function, f.function, a, b, 0, -1, col});
            return std::nullopt;
        }
        return error(col, "unknown word or function starting with " + std::string(1, peek()));
    }

    std::optional<Diagnostic> expression(std::int32_t& out) {
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
    std::optional<Diagnostic> climb(std::int32_t& out, int min_precedence) {
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

    static constexpr int max_depth = 64;
    NgcLine& line_;
    std::string buffer_;
    std::vector<std::uint32_t> columns_;
    std::size_t pos_ = 0;
    int depth_ = 0;
};

}  // namespace

std::string normal_name(std::string_view name) {
    std::string out;
    for (char c : name) {
        if (c != ' ' && c != '\t') out += lower(c);
    }
    return out;
}

std::optional<Diagnostic> parse_ngc_line(std::string_view text, NgcLine& line) {
    line.clear();
    Reader reader(line);
    if (auto e = reader.normalise(text)) return e;
    return reader.line();
}

}  // namespace nckit::interp::ngc
