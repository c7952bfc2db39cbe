#pragma once
// The JSON report of `nckit piston --json`, as a value: the keys and their nesting are a
// contract (docs/cli.md); a number that does not exist (no rpm limit on a round section) is null.
#include <nlohmann/json.hpp>

#include "nckit/process/piston/piston.hpp"

namespace nckit {

//! The report, keys in the order the command prints them.
[[nodiscard]] nlohmann::ordered_json to_json(const PistonSimulation& simulation);

}  // namespace nckit
