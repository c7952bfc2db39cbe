#pragma once
// One self-contained HTML page: nckit's viewer (three.js, uPlot, its own code; bundled at build
// time and compiled into the binary) with the page's data inline. `nckit report` fills the tool
// path; the process verbs (`--html`) add their own charts and figures, with or without a path.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "nckit/core/machine.hpp"
#include "nckit/report/payload.hpp"
#include "nckit/report/tool_path.hpp"

namespace nckit {

struct ChartSeries {
    std::string name;
    std::vector<double> x;
    std::vector<double> y;
};

//! A chart of y against x. `equal_axes` draws it to scale (a section, a net); `y_lines` are
//! horizontal lines (limits, goals) with their labels.
struct ReportChart {
    std::string title;
    std::string x_label;
    std::string y_label;
    bool equal_axes = false;
    std::vector<ChartSeries> series;
    std::vector<std::pair<std::string, double>> y_lines;
    bool log_y = false;  //!< y on a log scale (values must be positive)
};

//! The planned program with what the page needs besides the recorder's report.
struct ToolPathSection {
    ToolPathReport report;
    MachineConfig machine;
    std::vector<std::string> sources;  //!< the text of each of report.files
};

struct ReportPage {
    std::string title;
    std::string kind;  //!< "program", or the process verb: "piston", "crosshatch", "notch", ...
    std::vector<std::pair<std::string, std::string>> figures;  //!< name, value with its unit
    std::vector<ReportChart> charts;
    std::optional<ToolPathSection> tool_path;
};

//! The tool path's part of a page's payload (header keys and blobs; see docs/report.md).
void add_tool_path(Payload& payload, const ToolPathSection& section);

//! The whole page as HTML text.
[[nodiscard]] std::string render_report_html(const ReportPage& page);

}  // namespace nckit
