#pragma once
// Reads the decimal numbers of G-code ("12", "-0.5", "3.", ".25") into doubles, exactly as
// std::from_chars does, but without its general machinery for the common short numbers.
#include <charconv>
#include <cstdint>
#include <optional>

namespace nckit::gcode {

//! `digits` holds only '0'-'9' and at most one '.'. Correctly rounded, like from_chars.
[[nodiscard]] inline std::optional<double> parse_decimal(const char* digits, std::size_t n) {
    // Clinger's fast path: an integer mantissa below 2^53 divided by an exact power of ten is
    // one correctly rounded IEEE operation.
    static constexpr double powers_of_ten[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                               1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
    std::uint64_t mantissa = 0;
    int significant = 0;
    int fraction_digits = 0;
    bool after_point = false;
    for (std::size_t i = 0; i < n; ++i) {
        char c = digits[i];
        if (c == '.') {
            after_point = true;
            continue;
        }
        mantissa = mantissa * 10 + static_cast<std::uint64_t>(c - '0');
        if (mantissa != 0) ++significant;
        if (after_point) ++fraction_digits;
    }
    if (significant <= 15 && fraction_digits <= 22) {
        return static_cast<double>(mantissa) / powers_of_ten[fraction_digits];
    }
    double value = 0;
    auto [end, ec] = std::from_chars(digits, digits + n, value);
    if (ec != std::errc{} || end != digits + n) return std::nullopt;
    return value;
}

}  // namespace nckit::gcode
