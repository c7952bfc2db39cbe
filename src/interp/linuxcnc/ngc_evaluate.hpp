#pragma once
#include <cstdint>
#include <optional>

#include "ngc_line.hpp"
#include "ngc_parameters.hpp"

namespace nckit::interp::ngc {

//! The value of the expression rooted at `root`, or LinuxCNC's error at its column.
[[nodiscard]] std::optional<Diagnostic> evaluate(const NgcLine& line, std::int32_t root,
                                                 const NgcParameters& parameters, double& out);

//! The number a parameter node names (`#5`, `#[#1+2]`), checked against 1-5601.
[[nodiscard]] std::optional<Diagnostic> parameter_number(const NgcLine& line, std::int32_t node,
                                                         const NgcParameters& parameters, std::int64_t& out);

}  // namespace nckit::interp::ngc
