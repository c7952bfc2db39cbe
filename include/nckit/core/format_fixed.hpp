#pragma once
#include <string>

namespace nckit {

//! Appends `value` with exactly 4 decimals, as `{:.4f}` prints it (the exact binary value
//! rounded), fast: long programs print millions of these.
void append_fixed4(std::string& out, double value);

}  // namespace nckit
