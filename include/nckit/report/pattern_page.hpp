#pragma once
// The pattern verb's page (`nckit pattern ... --html OUT.html`): figures of the cutting order;
// the caller adds the generated program's tool path (plan_tool_path_text in the CLI).
#include <string>

#include "nckit/process/pattern/pattern_run.hpp"
#include "nckit/report/report_page.hpp"

namespace nckit {

[[nodiscard]] ReportPage pattern_page(const pattern::SoleRun& run, const std::string& title);

}  // namespace nckit
