#include "nckit/core/format_exact.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <iterator>

#include <fmt/format.h>

namespace nckit {

void append_exact(std::string& out, double value) {
    if (!std::isfinite(value)) {
        fmt::format_to(std::back_inserter(out), "{}", value);
        return;
    }
    if (value == 0) value = 0.0;  // -0.0 reads the same as 0.0; "-0.0" would only puzzle
    // std::to_chars in fixed format without a precision is the shortest fixed-notation text
    // that std::from_chars (and so nckit's reader and strtod) maps back to `value`. The largest
    // double needs 309 integer digits; a 1e-300 needs 300 fraction digits plus the digits.
    std::array<char, 340> text{};
    auto [end, error] = std::to_chars(text.data(), text.data() + text.size(), value, std::chars_format::fixed);
    if (error != std::errc{}) {
        fmt::format_to(std::back_inserter(out), "{:.17f}", value);  // cannot happen with 340 chars
        return;
    }
    out.append(text.data(), end);
    if (std::find(text.data(), end, '.') == end) out += ".0";
}

double append_rounded(std::string& out, double value, int decimals) {
    if (!std::isfinite(value)) {
        fmt::format_to(std::back_inserter(out), "{}", value);
        return 0;
    }
    decimals = std::clamp(decimals, 0, 17);
    std::string text = fmt::format("{:.{}f}", value, decimals);
    double written = 0;
    std::from_chars(text.data(), text.data() + text.size(), written);
    if (written == 0 && text.front() == '-') text.erase(0, 1);
    if (decimals == 0) text += '.';  // a decimal point keeps "X5." in mm on any control
    out += text;
    return std::abs(written - value);
}

std::string comment_text(std::string text) {
    for (char& c : text) {
        if (c == '(') c = '[';
        if (c == ')') c = ']';
        if (c == '\n' || c == '\r') c = ' ';
    }
    return text;
}

}  // namespace nckit
