#pragma once
// The JSON report of one sole of `nckit pattern --json`, as a value: the keys and their nesting
// are a contract (docs/cli.md). The command adds where it wrote the program and the drawing.
#include <nlohmann/json.hpp>

#include "nckit/process/pattern/pattern_run.hpp"

namespace nckit::pattern {

//! One size's report, keys in the order the command prints them (without "program" and "svg").
[[nodiscard]] nlohmann::ordered_json to_json(const SoleRun& run);

//! The air of one order: distance, rapid time, reversals and their time.
[[nodiscard]] nlohmann::ordered_json to_json(const TourCost& cost);

}  // namespace nckit::pattern
