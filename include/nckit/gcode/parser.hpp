#pragma once
#include <optional>
#include <string_view>

#include "nckit/core/diagnostic.hpp"
#include "nckit/gcode/block.hpp"

namespace nckit {

//! Parses one line into `block` (reusing its storage, so long programs allocate nothing per
//! line). `block.location` must already name the line. Returns the first syntax error, if any.
//!
//! Syntax (RS-274 / ISO 6983 with Fanuc's habits): letters in either case; spaces and tabs are
//! ignored anywhere, also inside numbers (`X 1 0.5`); `( ... )` and `;` to the end of the line are
//! comments; a leading `/` marks block delete; a line holding only `%` is a tape mark. Numbers
//! are `[+|-]digits[.digits]`, `.5` and `5.` included.
[[nodiscard]] std::optional<Diagnostic> parse_block(std::string_view line, Block& block);

}  // namespace nckit
