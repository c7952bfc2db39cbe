// nckit notch FILE: laser notching. Moves each laser-on M-code back along the cut line by the
// run-up the S-curve needs to reach the cut's feed, runs the stroke on past the programmed end
// with the beam switched off there by position, and reports the planned speed along every
// programmed cut before and after. -o writes the rewritten program (a plain program, as
// `nckit expand` writes); the report goes to standard output, as text or with --json.
#include <cstdio>
#include <filesystem>
#include <variant>

#include <fmt/format.h>

#include "common.hpp"
#include "partial_file.hpp"
#include "nckit/report/process_pages.hpp"
#include "tool_path_page.hpp"
#include "nckit/process/notch/notch.hpp"
#include "verbs.hpp"

namespace nckit::cli {

namespace {

struct NotchCliOptions {
    std::string program;
    std::string output;
    MachineOptions machine;
    bool json = false;
    std::string html;
};

std::string speed_json(const CutSpeed& speed) {
    std::string out =
        fmt::format("{{\"min_mm_min\":{},\"max_mm_min\":{},\"mean_mm_min\":{},\"covered_mm\":{},\"profile\":[",
                    speed.min_mm_min, speed.max_mm_min, speed.mean_mm_min, speed.covered_mm);
    for (std::size_t i = 0; i < speed.profile.size(); ++i) {
        out += fmt::format("{}[{},{}]", i == 0 ? "" : ",", speed.profile[i][0], speed.profile[i][1]);
    }
    return out + "]}";
}

void print_json(const NotchJob& job) {
    std::string out = "{\"cuts\":[";
    for (std::size_t i = 0; i < job.cuts.size(); ++i) {
        const NotchCut& cut = job.cuts[i];
        out += fmt::format(
            "{}{{\"line\":{},\"sequence_number\":{},\"laser_on_mcode\":{},\"length_mm\":{},\"feed_mm_min\":{},"
            "\"cut_speed_mm_min\":{},\"run_up_mm\":{},\"run_up_placed_mm\":{},\"overrun_mm\":{},"
            "\"approach_shortened\":{},\"profile_coordinate\":\"{}\",\"before\":{},\"after\":{}}}",
            i == 0 ? "" : ",", cut.where.line, cut.sequence_number, cut.laser_on_mcode, cut.length_mm, cut.feed_mm_min,
            cut.cut_speed_mm_min, cut.run_up_mm, cut.run_up_placed_mm, cut.overrun_mm,
            cut.approach_shortened ? "true" : "false",
            cut.profile_axis ? std::string(1, letter(*cut.profile_axis)) : std::string("s"), speed_json(cut.before),
            speed_json(cut.after));
    }
    fmt::print("{}]}}\n", out);
}

void print_text(const NotchJob& job, const std::string& program) {
    fmt::print("{}: {} notch cut(s)\n", program, job.cuts.size());
    for (const NotchCut& cut : job.cuts) {
        fmt::print("line {}{}: M{} then a {:.4f} mm cut at F{}\n", cut.where.line,
                   cut.sequence_number >= 0 ? fmt::format(" (N{})", cut.sequence_number) : std::string(),
                   cut.laser_on_mcode, cut.length_mm, cut.feed_mm_min);
        fmt::print("  run-up {:.6f} mm (placed {:.4f} mm{}), overrun {:.6f} mm\n", cut.run_up_mm, cut.run_up_placed_mm,
                   cut.approach_shortened ? ", on the approach" : ", head steps back", cut.overrun_mm);
        for (const auto& [name, speed] : {std::pair{"before", &cut.before}, std::pair{"after ", &cut.after}}) {
            fmt::print("  {} speed along the cut: min {:.3f} max {:.3f} mean {:.3f} mm/min over {:.4f} mm\n", name,
                       speed->min_mm_min, speed->max_mm_min, speed->mean_mm_min, speed->covered_mm);
        }
    }
}

int run_notch(const NotchCliOptions& options) {
    auto interpreter = open_program_or_report(options.program, options.machine, false);
    if (!interpreter) return exit_bad_input;
    if (interpreter->machine().laser_on_mcodes.empty()) {
        // Without a laser-on code there is no cut to find: "0 notch cut(s)" would be a silent no-op.
        fmt::print(stderr,
                   "{}: error: machine '{}' names no laser code: give [machine] laser_on_mcodes (and "
                   "laser_off_mcodes), e.g. --machine examples/machines/notcher.toml\n",
                   options.machine.machine.empty() ? "nckit notch" : options.machine.machine,
                   interpreter->machine().name);
        return exit_bad_input;
    }
    std::vector<Move> moves;
    for (;;) {
        InterpResult result = interpreter->next();
        if (std::holds_alternative<ProgramEnd>(result)) break;
        if (const auto* diagnostic = std::get_if<Diagnostic>(&result)) {
            print_diagnostic(*diagnostic);
            return exit_bad_input;
        }
        moves.push_back(std::move(std::get<Move>(result)));
    }
    Result<NotchJob> job = notch_program(moves, interpreter->machine(), options.program);
    if (!job) {
        print_diagnostics(job.diagnostics());
        return exit_bad_input;
    }
    std::optional<ReportPage> page;
    if (!options.html.empty()) {
        // The page shows the rewritten program's tool path beside the speeds over the cuts.
        page = notch_page(*job, options.program);
        page->tool_path = plan_tool_path_text(
            job->program, options.output.empty() ? options.program + " (rewritten)" : options.output,
            interpreter->machine());
        if (!page->tool_path) return exit_bad_input;
    }
    if (!options.output.empty()) {
        std::optional<PartialFile> out = PartialFile::create(options.output);
        if (!out) return exit_bad_input;
        out->write(job->program);
        if (!out->commit()) return exit_bad_input;
    }
    if (page && !write_page(*page, options.html)) return exit_bad_input;
    if (options.json) {
        print_json(*job);
    } else {
        print_text(*job, options.program);
    }
    return 0;
}

}  // namespace

void add_notch_verb(CLI::App& app, int& exit_status) {
    auto options = std::make_shared<NotchCliOptions>();
    CLI::App* verb = app.add_subcommand(
        "notch", "Laser notching: place each laser-on M-code a run-up before its cut so the cut runs at feed");
    verb->add_option("FILE", options->program, "NC program ('-': standard input)")->required();
    verb->add_option("-o,--output", options->output, "write the rewritten program here");
    add_machine_options(*verb, options->machine);
    verb->add_flag("--json", options->json, "print the report (with the speed profiles) as one JSON object");
    verb->add_option("--html", options->html,
                     "write an interactive page: speed over each cut before and after, the rewritten tool path");
    verb->callback([options, &exit_status] { exit_status = run_notch(*options); });
}

}  // namespace nckit::cli
