#pragma once
// The JSON report of `nckit eccentric --json`, as a value: the keys and their nesting are a
// contract (docs/cli.md); a speed limit the X axis does not have is null.
#include <nlohmann/json.hpp>

#include "nckit/process/eccentric/eccentric.hpp"

namespace nckit {

//! The report, keys in the order the command prints them.
[[nodiscard]] nlohmann::ordered_json to_json(const EccentricReport& report);

}  // namespace nckit
