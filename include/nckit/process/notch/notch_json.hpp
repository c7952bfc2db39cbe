#pragma once
// The JSON of one cut of `nckit notch --json`, as a value: the keys and their nesting are a
// contract (docs/cli.md). The command streams the cuts as they are measured, one value each,
// inside {"cuts":[...]}, so a long program never holds its report.
#include <nlohmann/json.hpp>

#include "nckit/process/notch/notch.hpp"

namespace nckit {

//! The speed along a cut: min, max, mean, covered length and the [coordinate, speed] profile.
[[nodiscard]] nlohmann::ordered_json to_json(const CutSpeed& speed);

//! One cut, keys in the order the command prints them.
[[nodiscard]] nlohmann::ordered_json to_json(const NotchCut& cut);

}  // namespace nckit
