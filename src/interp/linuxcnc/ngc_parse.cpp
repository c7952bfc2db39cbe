// Reading one RS-274/NGC line the way LinuxCNC does: blanks and case are dropped outside
// comments first, then words, parameter settings, an O-word and expressions are read from what
// is left. Nothing is evaluated here.
#include "ngc_reader.hpp"

#include <array>
#include <utility>

#include <fmt/format.h>

namespace nckit::interp::ngc {

namespace {

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

}  // namespace

//! Blanks and case out, comments aside; columns kept for messages.
std::optional<Diagnostic> Reader::normalise(std::string_view text) {
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

std::optional<Diagnostic> Reader::line() {
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

void Reader::add_comment(std::string_view body, std::uint32_t col) {
    Comment comment;
    comment.column = col;
    std::string head;
    for (std::size_t i = 0; i < body.size() && i < 8; ++i) {
        if (body[i] != ' ' && body[i] != '\t') head += lower(body[i]);
    }
    static constexpr std::array<std::pair<std::string_view, CommentKind>, 4> kinds{{{"msg,", CommentKind::msg},
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

std::optional<Diagnostic> Reader::oword() {
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

std::optional<Diagnostic> Reader::setting() {
    Setting s;
    s.column = column();
    if (auto e = parameter(s.target)) return e;
    if (peek() != '=') return error(column(), "equal sign missing in parameter setting");
    ++pos_;
    if (auto e = value(s.value)) return e;
    line_.settings.push_back(s);
    return std::nullopt;
}

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
