#pragma once
// Evaluates Macro B expressions with Fanuc's rules: degrees for angles, vacant as 0 in
// arithmetic but distinct in EQ/NE, integer bitwise AND/OR/XOR, alarms for bad arguments.
#include <cstdint>
#include <optional>

#include "macro_value.hpp"
#include "nckit/core/diagnostic.hpp"
#include "nckit/gcode/block.hpp"
#include "variables.hpp"

namespace nckit::interp {

struct EvalSettings {
    //! ADP[x] undoes least-increment scaling only on machines that read numbers that way.
    bool least_increment_input = false;
    //! Comparisons treat values closer than this as equal, so that a loop counter stepped by 0.1
    //! still meets its bound (binary fractions drift by ~1e-16 a step).
    double comparison_tolerance = 1e-9;
};

//! The value of the expression rooted at `root`, or an alarm at its column.
[[nodiscard]] std::optional<Diagnostic> evaluate(const Block& block, std::int32_t root, const Variables& variables,
                                                 const EvalSettings& settings, MacroValue& out);

//! The variable number a variable node names (`#5` or `#[#1+2]`), or an alarm.
[[nodiscard]] std::optional<Diagnostic> variable_number(const Block& block, std::int32_t node,
                                                        const Variables& variables, const EvalSettings& settings,
                                                        std::int64_t& out);

//! Rounds half away from zero, as Fanuc's ROUND and address rounding do.
[[nodiscard]] double round_half_away(double value);

}  // namespace nckit::interp
