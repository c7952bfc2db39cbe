#pragma once
// Numbers for G-code that reads back to the very double that was written. G-code has no exponent
// notation, so these are always plain decimals ("0.00000123", never "1.23e-06").
#include <string>

namespace nckit {

//! Appends the shortest plain decimal that reads back as exactly `value` (round trip), with at
//! least one decimal ("5.0": on a Fanuc control without calculator-type input "X5" is 5 µm).
//! Negative zero is written "0.0"; a value that is not finite is written as fmt prints it.
void append_exact(std::string& out, double value);

//! Appends `value` rounded to `decimals` places (0 to 17), with no "-0.000" for a value that
//! rounds to zero. Returns how far the written number lies from `value`.
double append_rounded(std::string& out, double value, int decimals);

//! Text that may stand inside a G-code comment: comments do not nest, so a '(' or ')' of a title,
//! file or machine name (`part(2).nc`) would end the comment early or be refused; they become
//! [ ], and line breaks become spaces.
std::string comment_text(std::string text);

}  // namespace nckit
