#include "nckit/core/format_fixed.hpp"

#include <cmath>
#include <cstring>
#include <iterator>

#include <fmt/format.h>

namespace nckit {

//! Appends `value` with exactly 4 decimals. Written by hand because a move line is four of
//! these and general float formatting was most of `nckit moves`' time on long programs.
//! It must print what `{:.4f}` prints, which rounds the exact binary value: 2.00005 is stored
//! just below ...05 and prints 2.0000, though 2.00005 * 1e4 rounds to 20000.5.
std::size_t format_fixed4_fast(double value, char* buffer) {
    constexpr double scale = 1e4;
    // Below 1e8 the product is off the exact one by under 1e-4 units, so its rounding is right
    // unless it lies within 1e-3 of a tie; huge, non-finite and near-tie values are refused.
    const double scaled = value * scale;
    const double fraction = std::abs(scaled - std::trunc(scaled));
    if (!(std::abs(value) < 1e8) || std::abs(fraction - 0.5) < 1e-3) return 0;
    // Away from a tie, adding a half and truncating rounds exactly (and skips a libm call).
    // The sign is the value's, as fmt prints it: -0.00004 and -0.0 print "-0.0000".
    const bool negative = std::signbit(value);
    auto units = static_cast<long long>(std::abs(scaled) + 0.5);
    // Digits are written backwards into a small buffer, then moved to the front.
    char text[24];
    char* end = text + sizeof text;
    char* p = end;
    for (int i = 0; i < 4; ++i, units /= 10) *--p = static_cast<char>('0' + units % 10);
    *--p = '.';
    do {
        *--p = static_cast<char>('0' + units % 10);
        units /= 10;
    } while (units > 0);
    if (negative) *--p = '-';
    auto length = static_cast<std::size_t>(end - p);
    std::memcpy(buffer, p, length);
    return length;
}

void append_fixed4(std::string& out, double value) {
    char text[max_fast_fixed4_chars];
    std::size_t length = format_fixed4_fast(value, text);
    if (length == 0) {
        fmt::format_to(std::back_inserter(out), "{:.4f}", value);
        return;
    }
    out.append(text, length);
}

}  // namespace nckit
