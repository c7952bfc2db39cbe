// nckit crosshatch JOB.toml: cylinder-bore crosshatch laser hardening. Computes the rotation
// speed, both motors' step rates and timer divisors with their speed errors, the crosshatch
// angle and the index rule, and generates the whole scan: -o the G-code (Z and a rotary A),
// --steps the two motors' step streams (binary records as `nckit steps` writes them, or with
// --text "t_ns axis dir port" lines), --svg the unrolled bore with every laser track.
// The report goes to standard output, as text or with --json. A bad job writes nothing.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>

#include <fmt/format.h>

#include "common.hpp"
#include "nckit/report/process_pages.hpp"
#include "tool_path_page.hpp"
#include "partial_file.hpp"
#include "step_record.hpp"
#include "nckit/process/crosshatch/crosshatch.hpp"
#include "nckit/process/crosshatch/crosshatch_scan.hpp"
#include "nckit/process/crosshatch/crosshatch_json.hpp"
#include "verbs.hpp"

namespace nckit::cli {

namespace {

struct CrosshatchOptions {
    std::string job;
    bool json = false;
    std::string svg;
    std::string gcode;
    std::string steps;
    bool text = false;
    std::string html;
};

void print_json(const CrosshatchPlan& plan, const CrosshatchScan& scan) {
    fmt::print("{}\n", to_json(plan, scan).dump());
}

void print_text(const CrosshatchPlan& plan, const CrosshatchScan& scan, const std::string& name) {
    const CrosshatchJob& job = plan.job;
    fmt::print("{}: bore D {} mm x H {} mm, {} heads, {} lines per length\n", name, job.bore_diameter_mm,
               job.bore_length_mm, job.heads, job.lines_per_length);
    fmt::print(
        "  feed      {:.6g} mm/min (screw {:.6g} rpm): {:.6g} steps/s, divisor {} -> {:.6g} steps/s ({:+.4f} %)\n",
        plan.feed_mm_min, job.feed_screw_rpm, plan.feed.timer.wanted_hz, plan.feed.timer.divisor,
        plan.feed.timer.rate_hz, plan.feed.timer.speed_error * 100);
    fmt::print("  rotation  {:.6g} rpm: {:.6g} steps/s, divisor {} -> {:.6g} steps/s ({:+.4f} %)\n", plan.rotation_rpm,
               plan.rotation.timer.wanted_hz, plan.rotation.timer.divisor, plan.rotation.timer.rate_hz,
               plan.rotation.timer.speed_error * 100);
    fmt::print("  crosshatch angle {:.4f} deg (helix {:.4f} deg), line spacing {:.4f} mm, {:.6g} turns per stroke\n",
               plan.crosshatch_angle_deg, plan.helix_angle_deg, plan.line_spacing_mm, plan.turns_per_stroke);
    fmt::print("  round trip {:.6g} deg, index {:.6g} deg: {}\n", plan.round_trip_deg, job.index_deg,
               plan.special ? "special angle, no correction move"
                            : fmt::format("arbitrary angle, correction {:+.6g} deg ({} steps) after each cycle",
                                          plan.index_move_deg, plan.index_move_steps));
    fmt::print(
        "  scan ({}): {} cycles, {:.1f} s; tracks at {:.4f} deg ({:+.4f}), drift {:.4g} deg per stroke, "
        "closure error {:.3g} steps\n",
        timing_name(job.timing), job.cycles, scan.duration_s, scan.track_angle_deg,
        std::abs(scan.track_angle_error_deg) < 5e-9 ? 0.0 : scan.track_angle_error_deg, scan.drift_deg_per_stroke,
        scan.closure_error_steps);
}

//! Writes `text` to `path` through NAME.partial; false (error printed) when it cannot.
bool write_file(const std::string& path, const std::string& text) {
    std::optional<PartialFile> file = PartialFile::create(path);
    if (!file) return false;
    file->write(text);
    return file->commit();
}

bool write_steps(const CrosshatchOptions& options, const CrosshatchPlan& plan) {
    std::optional<PartialFile> file = PartialFile::create(options.steps);
    if (!file) return false;
    std::string buffer;
    for_each_crosshatch_step(plan, [&](const StepEvent& e, std::uint8_t port) {
        if (options.text) {
            buffer += fmt::format("{} {} {} 0x{:02X}\n", e.t_ns, e.axis, e.direction, port);
        } else {
            append_step_record(buffer, e);
        }
        if (buffer.size() > (1 << 16)) {
            file->write(buffer);
            buffer.clear();
        }
    });
    file->write(buffer);
    return file->commit();
}

int run_crosshatch(const CrosshatchOptions& options) {
    Result<CrosshatchJob> job = load_crosshatch_job(options.job);
    if (!job) {
        print_diagnostics(job.diagnostics());
        return exit_bad_input;
    }
    Result<CrosshatchPlan> plan = plan_crosshatch(*job);
    if (!plan) {
        print_diagnostics(plan.diagnostics());
        return exit_bad_input;
    }
    const CrosshatchScan scan = build_crosshatch_scan(*plan);
    const std::string name = std::filesystem::path(options.job).filename().string();
    if (!options.gcode.empty() && !write_file(options.gcode, crosshatch_gcode(*plan, name))) return exit_bad_input;
    if (!options.svg.empty() && !write_file(options.svg, crosshatch_svg(*plan, scan))) return exit_bad_input;
    if (!options.steps.empty() && !write_steps(options, *plan)) return exit_bad_input;
    if (!options.html.empty() && !write_page(crosshatch_page(*plan, scan, name), options.html)) return exit_bad_input;
    if (options.json) {
        print_json(*plan, scan);
    } else {
        print_text(*plan, scan, options.job);
    }
    return 0;
}

}  // namespace

void add_crosshatch_verb(CLI::App& app, int& exit_status) {
    auto options = std::make_shared<CrosshatchOptions>();
    CLI::App* verb = app.add_subcommand("crosshatch", "Cylinder-bore crosshatch laser hardening: speeds, timers, scan");
    verb->add_option("JOB", options->job, "job file (TOML, table [crosshatch])")->required();
    verb->add_flag("--json", options->json, "print the report as JSON");
    verb->add_option("--svg", options->svg, "draw the unrolled bore with the laser tracks (SVG)");
    verb->add_option("--html", options->html, "write an interactive page: the unrolled net, speeds, divisors (HTML)");
    verb->add_option("-o,--output", options->gcode, "write the scan as G-code (Z and a rotary A axis)");
    CLI::Option* steps =
        verb->add_option("--steps", options->steps, "write both motors' step streams (axis 0 feed, 1 rotation)");
    verb->add_flag("--text", options->text, "--steps as text: t_ns axis dir port")->needs(steps);
    verb->callback([options, &exit_status] { exit_status = run_crosshatch(*options); });
}

}  // namespace nckit::cli
