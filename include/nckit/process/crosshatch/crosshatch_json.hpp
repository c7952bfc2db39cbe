#pragma once
// The JSON report of `nckit crosshatch --json`, as a value: the keys and their nesting are a
// contract (docs/cli.md).
#include <nlohmann/json.hpp>

#include "nckit/process/crosshatch/crosshatch.hpp"
#include "nckit/process/crosshatch/crosshatch_scan.hpp"

namespace nckit {

//! The report of a planned scan, keys in the order the command prints them.
[[nodiscard]] nlohmann::ordered_json to_json(const CrosshatchPlan& plan, const CrosshatchScan& scan);

//! "one_time_base" or "free_running_timers", as the job key spells it.
[[nodiscard]] const char* timing_name(CrosshatchTiming timing);

}  // namespace nckit
