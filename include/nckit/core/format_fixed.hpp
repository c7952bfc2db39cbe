#pragma once
#include <cstddef>
#include <string>

namespace nckit {

//! Appends `value` with exactly 4 decimals, as `{:.4f}` prints it (the exact binary value
//! rounded, and a negative value that rounds to zero as "-0.0000", as fmt does), fast: long
//! programs print millions of these. Callers that want no "-0.0000" clear the sign first.
void append_fixed4(std::string& out, double value);

inline constexpr std::size_t max_fast_fixed4_chars = 24;
//! Writes `value` with 4 decimals into `buffer` (max_fast_fixed4_chars at least) and returns the
//! length, or 0 for the rare values only the general formatter gets right (near a rounding tie,
//! huge, not finite).
std::size_t format_fixed4_fast(double value, char* buffer);

}  // namespace nckit
