// nckit pattern JOB.toml: shoe-sole pattern milling. Fits the sole outline, tiles and clips the
// motif, orders the grooves (drawing order, optimised order, lower bound), writes the program
// (-o), the drawing (--svg) and reports per size, as text or --json. With a [series] and no
// --size every size is made: -o names a folder (one program per size), and the drawings and pages
// go to --svg-dir / --html-dir, since --svg and --html name one file on every verb. A bad job writes
// nothing.
#include <algorithm>
#include <filesystem>
#include <optional>

#include <fmt/format.h>

#include "common.hpp"
#include "partial_file.hpp"
#include "nckit/process/pattern/pattern_json.hpp"
#include "nckit/process/pattern/pattern_run.hpp"
#include "nckit/process/pattern/pattern_svg.hpp"
#include "nckit/report/pattern_page.hpp"
#include "tool_path_page.hpp"
#include "verbs.hpp"

namespace nckit::cli {

namespace {

using namespace nckit::pattern;

struct PatternOptions {
    std::string job;
    std::string machine;
    std::string outline;
    std::optional<double> size;
    bool mirror = false;
    std::string output;
    std::string svg;
    std::string svg_dir;
    std::string html;
    std::string html_dir;
    bool json = false;
};

struct Sole {
    SoleRun run;
    std::string name;  //!< file stem: JOB_SIZE[_mirror]
    std::string program_path;
    std::string svg_path;
    std::string title;
};

std::string size_text(double size) {
    return fmt::format("{}", size);
}

void print_json(const std::vector<Sole>& soles, const PatternOptions& o) {
    nlohmann::ordered_json sizes = nlohmann::ordered_json::array();
    for (const Sole& sole : soles) {
        nlohmann::ordered_json size = to_json(sole.run);
        size["program"] =
            sole.program_path.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(sole.program_path);
        size["svg"] = sole.svg_path.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(sole.svg_path);
        sizes.push_back(std::move(size));
    }
    const nlohmann::ordered_json report{{"job", o.job}, {"mirror", o.mirror}, {"sizes", std::move(sizes)}};
    fmt::print("{}\n", report.dump());
}

void print_text(const std::vector<Sole>& soles) {
    for (const Sole& sole : soles) {
        const SoleRun& r = sole.run;
        const Grading& g = r.layout.grading;
        fmt::print("{}: size {}{}, scale {:.5f} x {:.5f}; {} grooves ({:.1f} mm) from {} motif places\n", sole.name,
                   size_text(g.size), g.mirror ? " (mirrored)" : "", g.scale_x, g.scale_y, r.layout.cuts.size(),
                   r.cut_length_mm, r.layout.motif_instances);
        fmt::print("  outline fit {:.4f} mm ({} control points), border offset {:.2g} mm\n", r.layout.fit_error_mm,
                   r.layout.control_points, r.layout.border_offset_error_mm);
        auto line = [](const char* what, const TourCost& c) {
            fmt::print("  {:<15} air {:9.1f} mm {:8.2f} s, {:5} reversals ({:.3f} s)\n", what, c.air_distance_mm,
                       c.air_time_s, c.reversals, c.reversal_time_s);
        };
        line("drawing order", r.drawing);
        line("optimised", r.optimised);
        fmt::print("  {:<15} air {:9.1f} mm {:8.2f} s (optimised is {:+.1f} % / {:+.1f} % above)\n", "lower bound",
                   r.bound_distance_mm, r.bound_time_s,
                   r.bound_distance_mm > 0 ? 100 * (r.optimised.air_distance_mm / r.bound_distance_mm - 1) : 0.0,
                   r.bound_time_s > 0 ? 100 * (r.optimised.air_time_s / r.bound_time_s - 1) : 0.0);
        fmt::print("  planned cycle {:.2f} s: air {:.2f} s, plunges and grooves {:.2f} s\n", r.planned_cycle_s,
                   r.planned_air_s, r.planned_cut_s);
    }
}

bool write_file(const std::string& path, const std::string& text) {
    std::optional<PartialFile> file = PartialFile::create(path);
    if (!file) return false;
    file->write(text);
    return file->commit();
}

int run_pattern(const PatternOptions& o) {
    Result<PatternJob> job = load_pattern_job(o.job);
    if (!job) {
        print_diagnostics(job.diagnostics());
        return exit_bad_input;
    }
    const std::filesystem::path outline_path = o.outline.empty() ? job->outline : std::filesystem::path(o.outline);
    Result<OutlinePoints> points = load_outline_points(outline_path);
    if (!points) {
        print_diagnostics(points.diagnostics());
        return exit_bad_input;
    }
    std::optional<MachineConfig> machine = load_machine_or_report(o.machine);
    if (!machine) return exit_bad_input;

    std::vector<std::optional<double>> sizes;
    const bool series = !o.size && !job->sizes.empty();
    if (o.size) {
        sizes.push_back(*o.size);
    } else if (series) {
        std::vector<double> all{job->base_size};
        for (const SeriesSize& s : job->sizes) all.push_back(s.size);
        std::sort(all.begin(), all.end());
        all.erase(std::unique(all.begin(), all.end()), all.end());
        for (double s : all) sizes.emplace_back(s);
    } else {
        sizes.emplace_back(std::nullopt);
    }
    if (series && (!o.svg.empty() || !o.html.empty())) {
        fmt::print(stderr,
                   "{}: error: the job makes every size of its series and {} names one file: give --size N, or {} "
                   "DIR for one file per size\n",
                   o.job, o.svg.empty() ? "--html" : "--svg", o.svg.empty() ? "--html-dir" : "--svg-dir");
        return exit_bad_input;
    }
    const std::string stem = std::filesystem::path(o.job).stem().string();
    std::vector<Sole> soles;
    for (const std::optional<double>& size : sizes) {
        Result<Grading> grading = grading_for(*job, size, o.mirror);
        if (!grading) {
            print_diagnostics(grading.diagnostics());
            return exit_bad_input;
        }
        std::string name = stem;
        if (size) name += "_" + size_text(*size);
        if (o.mirror) name += "_mirror";
        const std::string title =
            fmt::format("nckit pattern {}: size {}{}", std::filesystem::path(o.job).filename().string(),
                        size ? size_text(*size) : "as digitised", o.mirror ? ", mirrored" : "");
        Result<SoleRun> run = run_pattern_sole(*job, *points, *grading, *machine, title);
        if (!run) {
            print_diagnostics(run.diagnostics());
            return exit_bad_input;
        }
        soles.push_back(Sole{std::move(*run), name, "", "", title});
    }
    // Everything is computed: only now is anything written.
    auto place = [&](const std::string& target, const Sole& sole, const char* ext) {
        if (target.empty()) return std::string();
        if (!series) return target;
        return (std::filesystem::path(target) / (sole.name + ext)).string();
    };
    auto place_in = [](const std::string& folder, const Sole& sole, const char* ext) {
        return folder.empty() ? std::string() : (std::filesystem::path(folder) / (sole.name + ext)).string();
    };
    for (const std::string* folder : {&o.output, &o.svg_dir, &o.html_dir}) {
        if ((series || folder != &o.output) && !folder->empty()) {
            std::error_code ec;
            std::filesystem::create_directories(*folder, ec);
            if (ec) {
                fmt::print(stderr, "{}:0:0: error: cannot create the folder: {}\n", *folder, ec.message());
                return exit_bad_input;
            }
        }
    }
    for (Sole& sole : soles) {
        sole.program_path = place(o.output, sole, ".nc");
        sole.svg_path = o.svg.empty() ? place_in(o.svg_dir, sole, ".svg") : o.svg;
        if (!sole.program_path.empty() && !write_file(sole.program_path, sole.run.program)) return exit_bad_input;
        const std::string svg_text = pattern_svg(sole.run, *job, sole.name);
        if (!sole.svg_path.empty() && !write_file(sole.svg_path, svg_text)) return exit_bad_input;
        if (!o.svg.empty() && !o.svg_dir.empty() && !write_file(place_in(o.svg_dir, sole, ".svg"), svg_text)) {
            return exit_bad_input;
        }
    }
    for (const Sole& sole : soles) {
        for (const std::string& page_path : {o.html, place_in(o.html_dir, sole, ".html")}) {
            if (page_path.empty()) continue;
            // The program's tool path shows the layout, the cutting order and the air moves.
            ReportPage page = pattern_page(sole.run, sole.title);
            page.tool_path = plan_tool_path_text(sole.run.program, sole.name + ".nc", *machine);
            if (!page.tool_path || !write_page(page, page_path)) return exit_bad_input;
        }
    }
    if (o.json) {
        print_json(soles, o);
    } else {
        print_text(soles);
    }
    return 0;
}

}  // namespace

void add_pattern_verb(CLI::App& app, int& exit_status) {
    auto options = std::make_shared<PatternOptions>();
    CLI::App* verb = app.add_subcommand("pattern", "Shoe-sole pattern milling: outline, layout, sizes, order, program");
    verb->add_option("JOB", options->job, "job file (TOML: [pattern], [motif], [lattice], [[region]], [series])")
        ->required();
    verb->add_option("--machine", options->machine, "machine file (default: the built-in mill)");
    verb->add_option("--outline", options->outline, "digitised outline (CSV x_mm,y_mm or DXF) instead of the job's");
    verb->add_option("--size", options->size, "make this size of the series only");
    verb->add_flag("--mirror", options->mirror, "the other foot (mirrored across the sole's length)");
    verb->add_option("-o,--output", options->output, "write the program (a folder when every size is made)");
    verb->add_option("--svg", options->svg, "draw outline, border, grooves and air moves into this file (one size)");
    verb->add_option("--svg-dir", options->svg_dir, "one drawing per size made, JOB_SIZE.svg, into this folder");
    verb->add_flag("--json", options->json, "print the report as JSON");
    verb->add_option(
        "--html", options->html,
        "write an interactive page into this file (one size): the order's figures and the program's tool path");
    verb->add_option("--html-dir", options->html_dir,
                     "one interactive page per size made, JOB_SIZE.html, into this folder");
    verb->callback([options, &exit_status] { exit_status = run_pattern(*options); });
}

}  // namespace nckit::cli
