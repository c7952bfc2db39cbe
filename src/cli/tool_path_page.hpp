#pragma once
// What `nckit report` and the process verbs' --html share: a program planned into a tool path
// section, and a page written as OUT.html only when complete.
#include <optional>
#include <string>

#include "common.hpp"
#include "nckit/report/report_page.hpp"

namespace nckit::cli {

//! Interprets and plans the program (errors are printed) and records its tool path.
[[nodiscard]] std::optional<ToolPathSection> plan_tool_path(const std::string& program, const MachineOptions& machine,
                                                            const ToolPathOptions& options = {});

//! The same for a program held as text (a rewritten program), shown under `name`.
[[nodiscard]] std::optional<ToolPathSection> plan_tool_path_text(const std::string& text, const std::string& name,
                                                                 const MachineConfig& machine,
                                                                 const ToolPathOptions& options = {});

//! Renders the page to `path` (through NAME.partial); false, with the error printed, if it
//! cannot be written.
[[nodiscard]] bool write_page(const ReportPage& page, const std::string& path);

}  // namespace nckit::cli
