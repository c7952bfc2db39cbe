#pragma once
// The reader of one RS-274/NGC line: the line with blanks and case dropped, and a cursor in
// it. Its line-level half is in ngc_parse.cpp, its expression half in ngc_expression_read.cpp.
#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ngc_line.hpp"

namespace nckit::interp::ngc {

inline bool is_digit(char c) {
    return c >= '0' && c <= '9';
}
inline bool is_lower(char c) {
    return c >= 'a' && c <= 'z';
}
inline char lower(char c) {
    return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
}

//! Reads one line into `line`: `normalise` first, then `line`.
class Reader {
public:
    explicit Reader(NgcLine& line) : line_(line) {}

    //! Blanks and case out, comments aside; columns kept for messages.
    std::optional<Diagnostic> normalise(std::string_view text);
    std::optional<Diagnostic> line();

private:
    // The cursor in the normalised line.
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

    // The line-level half (ngc_parse.cpp).
    void add_comment(std::string_view body, std::uint32_t col);
    std::int32_t add(Node node) {
        line_.nodes.push_back(node);
        return static_cast<std::int32_t>(line_.nodes.size() - 1);
    }
    std::optional<Diagnostic> oword();
    std::optional<Diagnostic> setting();

    // The expression half (ngc_expression_read.cpp).
    std::optional<Diagnostic> parameter(std::int32_t& out);
    //! LinuxCNC's "real value": a number, a parameter, a bracketed expression, a function, or a
    //! sign before any of these.
    std::optional<Diagnostic> value(std::int32_t& out);
    std::optional<Diagnostic> number(std::int32_t& out);
    std::optional<Diagnostic> function(std::int32_t& out);
    std::optional<Diagnostic> expression(std::int32_t& out);
    //! Binary operators by precedence climbing; all of LinuxCNC's are left-associative.
    std::optional<Diagnostic> climb(std::int32_t& out, int min_precedence);

    static constexpr int max_depth = 64;
    NgcLine& line_;
    std::string buffer_;
    std::vector<std::uint32_t> columns_;
    std::size_t pos_ = 0;
    int depth_ = 0;
};

}  // namespace nckit::interp::ngc
