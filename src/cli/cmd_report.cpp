// nckit report FILE -o OUT.html: the planned program as one interactive page (tool path coloured
// by planned speed, code pane, time slider, each axis's v/a/j against time, where the feed was
// not reached and why). The page is self-contained: it opens from disk with no network.
#include <cmath>

#include <fmt/format.h>

#include "common.hpp"
#include "tool_path_page.hpp"
#include "verbs.hpp"

namespace nckit::cli {

namespace {

struct ReportOptions {
    std::string program;
    std::string output;
    MachineOptions machine;
    double tolerance_mm = ToolPathOptions{}.tolerance_mm;
};

int run_report(const ReportOptions& options) {
    ToolPathOptions path_options;
    path_options.tolerance_mm = options.tolerance_mm;
    auto section = plan_tool_path(options.program, options.machine, path_options);
    if (!section) return exit_bad_input;
    ReportPage page;
    page.title = fmt::format("nckit report: {}", options.program);
    page.kind = "program";
    page.tool_path = std::move(section);
    return write_page(page, options.output) ? 0 : exit_bad_input;
}

}  // namespace

void add_report_verb(CLI::App& app, int& exit_status) {
    auto options = std::make_shared<ReportOptions>();
    CLI::App* verb = app.add_subcommand("report", "Write the planned program as one interactive HTML page");
    verb->add_option("FILE", options->program, "NC program")->required();
    add_machine_options(*verb, options->machine);
    verb->add_option("-o,--output", options->output, "the page to write (OUT.html)")->required();
    verb->add_option("--tolerance", options->tolerance_mm,
                     "mm: the drawn path stays this close to the planned one (points inside a move are dropped)")
        ->check(CLI::Range(1e-6, 10.0));
    verb->callback([options, &exit_status] { exit_status = run_report(*options); });
}

}  // namespace nckit::cli
