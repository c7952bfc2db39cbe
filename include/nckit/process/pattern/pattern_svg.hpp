#pragma once
// The SVG of one sole: outline, border, grooves coloured by their place in the order (blue
// first, red last), air moves dashed, the reference hole as a crossed circle.
#include <string>

#include "nckit/process/pattern/pattern_run.hpp"

namespace nckit::pattern {

[[nodiscard]] std::string pattern_svg(const SoleRun& run, const PatternJob& job, const std::string& title);

}  // namespace nckit::pattern
