// nckit piston JOB.toml: oval piston turning on a fast tool servo. Builds the cam engine from the
// drawing, cuts the piston in simulation three ways (no compensation, feedforward, feedforward
// plus learning across revolutions) with the job's servo, model error and spindle ripple, and
// reports the profile error of each; --cam-table, --trace and --svg write the cam, the learning
// run's last turns tick by tick and the plots, --program the slide's path as a Fanuc lathe
// program. A bad job writes nothing.
#include <cmath>
#include <filesystem>
#include <optional>
#include <sstream>
#include <system_error>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "common.hpp"
#include "nckit/report/process_pages.hpp"
#include "partial_file.hpp"
#include "nckit/process/piston/piston.hpp"
#include "nckit/process/piston/piston_json.hpp"
#include "nckit/process/piston/piston_program.hpp"
#include "nckit/process/piston/piston_svg.hpp"
#include "verbs.hpp"

namespace nckit::cli {

namespace {

struct PistonOptions {
    std::string job;
    bool json = false;
    std::string svg_dir;
    std::string svg;
    std::string cam_table;
    std::string trace;
    int trace_turns = 3;
    std::string html;
    std::string program;
};

void print_text(const PistonSimulation& s, const cam::PistonJob& job, const std::string& name) {
    const FtsSimulation& f = s.fts;
    const FtsParameters& p = s.parameters;
    fmt::print("{}: piston Z {:g} .. {:g} mm at {:g} mm/rev, section {}, {:g} rpm\n", name, p.z_start_mm, p.z_end_mm,
               p.feed_mm_rev, cam::name(job.profile.shape().kind()), p.rpm);
    fmt::print("  cam table {} x {} cells ({:.0f} kB), error bound {:.3g} nm (tolerance {:.3g} nm)\n",
               s.table_theta_cells, s.table_z_cells, static_cast<double>(s.table_bytes) / 1024.0,
               s.table_error_bound_mm * 1e6, s.table_tolerance_mm * 1e6);
    fmt::print("  servo {:g} Hz, zeta {:g}, controller model {:g} % off; {}-bit DAC over {:g} mm ({:.4g} nm steps)\n",
               p.servo.natural_frequency_hz, p.servo.damping, p.servo.model_error * 100, p.servo.dac_bits,
               p.servo.stroke_mm, f.dac_step_mm * 1e6);
    fmt::print("  {} counts per turn: {:.6g} Hz control rate; spindle speed ripple ±{:g} % once per turn{}\n",
               p.encoder_counts, f.tick_rate_hz, p.ripple.fraction * 100,
               job.source.ripple_given ? "" : " (the job gives none: the simulation's default)");
    fmt::print("  displacement up to {:.4f} mm of {:.4f} mm; acceleration {:.4g} mm/s2 of {:.4g} ({} rpm at most)\n",
               s.fit.peak_displacement_mm, s.fit.limit_mm, s.acceleration_mm_s2, s.acceleration_limit_mm_s2,
               std::isfinite(s.max_rpm) ? fmt::format("{:.0f}", std::floor(s.max_rpm)) : "no limit");
    fmt::print("  profile error over the turned surface   P-V um      RMS um\n");
    for (const auto& [label, r] : {std::pair{"uncompensated", &f.uncompensated},
                                   std::pair{"feedforward", &f.feedforward}, std::pair{"learning", &f.learning}}) {
        fmt::print("    {:<36} {:>9.4f} {:>11.4f}\n", label, r->pv_um, r->rms_um);
    }
    const std::string settled = s.settled_turn < 0 ? "never within 1 um per turn"
                                                   : fmt::format("every turn within 1 um from turn {}", s.settled_turn);
    fmt::print("  learning: {} (tool engages at turn {}); contraction {:.3f}\n", settled, p.air_turns,
               f.learning_contraction.any_frequency);
    fmt::print("  {} ticks per run, {:.3f} s of spindle time\n", f.ticks, f.duration_s);
}

//! The outputs, written together: every one is opened as NAME.partial before any is renamed, so
//! a path that cannot be written leaves none of them.
bool write_outputs(const std::vector<std::pair<std::string, std::string>>& outputs) {
    std::vector<PartialFile> files;
    for (const auto& [path, content] : outputs) {
        std::optional<PartialFile> file = PartialFile::create(path);
        if (!file) return false;
        file->write(content);
        files.push_back(std::move(*file));
    }
    bool ok = true;
    for (PartialFile& file : files) ok = file.commit() && ok;
    return ok;
}

int run_piston(PistonOptions options) {
    Result<cam::PistonJob> loaded = cam::load_piston_job(options.job);
    if (!loaded) {
        print_diagnostics(loaded.diagnostics());
        return exit_bad_input;
    }
    PistonRunOptions run;
    run.trace_turns = options.trace.empty() ? 0 : options.trace_turns;
    Result<PistonSimulation> simulation = simulate_piston(*loaded, run);
    if (!simulation) {
        print_diagnostics(simulation.diagnostics());
        return exit_bad_input;
    }
    const cam::PistonJob& job = *loaded;
    std::vector<std::pair<std::string, std::string>> outputs;
    if (!options.cam_table.empty()) {
        std::ostringstream csv;
        cam::write_cam_table_csv(csv, job);
        outputs.emplace_back(options.cam_table, std::move(csv).str());
    }
    if (!options.trace.empty()) outputs.emplace_back(options.trace, format_fts_trace_csv(simulation->fts.trace));
    if (!options.svg.empty()) outputs.emplace_back(options.svg, piston_section_svg(job));
    if (!options.svg_dir.empty()) {
        std::error_code error;
        std::filesystem::create_directories(options.svg_dir, error);
        if (error) {
            fmt::print(stderr, "{}: cannot write: {} (cannot create the folder)\n", options.svg_dir, error.message());
            return exit_bad_input;
        }
        const std::filesystem::path dir(options.svg_dir);
        outputs.emplace_back((dir / "section.svg").string(), piston_section_svg(job));
        outputs.emplace_back((dir / "drawing.svg").string(), piston_drawing_svg(job));
        outputs.emplace_back((dir / "turn_error.svg").string(),
                             piston_turn_error_svg(simulation->fts, simulation->parameters.air_turns));
    }
    if (!options.html.empty()) {
        outputs.emplace_back(options.html, render_report_html(piston_page(job, *simulation, options.job)));
    }
    if (!options.program.empty()) {
        outputs.emplace_back(options.program, piston_program(job, {simulation->parameters.air_turns, options.job}));
    }
    if (!write_outputs(outputs)) return exit_bad_input;
    if (options.json) {
        fmt::print("{}\n", to_json(*simulation).dump());
    } else {
        print_text(*simulation, job, options.job);
    }
    return 0;
}

}  // namespace

void add_piston_verb(CLI::App& app, int& exit_status) {
    auto options = std::make_shared<PistonOptions>();
    CLI::App* verb = app.add_subcommand("piston", "Oval piston turning on a fast tool servo: cam table, profile error");
    verb->add_option("JOB", options->job, "job file (TOML, tables [piston] and [servo])")->required();
    verb->add_flag("--json", options->json, "print the report as JSON");
    verb->add_option("--svg", options->svg, "draw the section (measured against drawn) into this SVG file");
    verb->add_option("--svg-dir", options->svg_dir,
                     "write section.svg, drawing.svg and turn_error.svg into this folder (created if missing)");
    verb->add_option("--cam-table", options->cam_table,
                     "write the drawn profile at the stations, every degree: z_mm,phi_deg,radius_mm");
    verb->add_option("--html", options->html,
                     "write an interactive page: section, error per turn, learning convergence (HTML)");
    verb->add_option("--program", options->program,
                     "write the slide's path as a Fanuc lathe program (G-code system A, X diameters)");
    CLI::Option* trace =
        verb->add_option("--trace", options->trace, "write the learning run's last turns at every control tick (CSV)");
    verb->add_option("--trace-turns", options->trace_turns, "turns in --trace (default 3)")
        ->check(CLI::Range(1, 1000000))
        ->needs(trace);
    verb->callback([options, &exit_status] { exit_status = run_piston(*options); });
}

}  // namespace nckit::cli
