// nckit eccentric JOB.toml: eccentric shaft turning with X slaved to the spindle angle (an
// electronic cam) instead of a macro of short blocks. Simulates the cut section on the machine's
// X axis (its servo model when it has one, with and without feedforward from the known cam),
// reports roundness and centre offset against the drawing and the highest spindle speed the X
// axis can follow within 1 µm; --cam-table writes the cam, X diameter per degree; --program the
// cam as a Fanuc lathe program, one block a degree.
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "common.hpp"
#include "nckit/report/process_pages.hpp"
#include "tool_path_page.hpp"
#include "partial_file.hpp"
#include "nckit/process/eccentric/eccentric.hpp"
#include "nckit/process/eccentric/eccentric_json.hpp"
#include "nckit/process/eccentric/eccentric_program.hpp"
#include "verbs.hpp"

namespace nckit::cli {

namespace {

struct EccentricOptions {
    std::string job;
    std::string machine;
    bool json = false;
    std::string cam_table;
    std::string html;
    std::string program;
};

void print_json(const EccentricReport& r) {
    fmt::print("{}\n", to_json(r).dump());
}

void print_text(const EccentricReport& r, const std::string& name) {
    const EccentricJob& j = r.job;
    fmt::print("{}: eccentric R{} offset {} mm on a {} mm blank, X slaved to the spindle angle\n", name,
               j.eccentric_radius_mm, j.eccentricity_mm, j.blank_diameter_mm);
    fmt::print("  X diameter {:.4f} to {:.4f} mm; at {} rpm X needs {:.4g} mm/s, {:.4g} mm/s2, {:.4g} mm/s3\n",
               r.x_min_diameter_mm, r.x_max_diameter_mm, j.rpm, r.peak_velocity_mm_s, r.peak_acceleration_mm_s2,
               r.peak_jerk_mm_s3);
    const char* axis = r.servo_axis ? "servo X with feedforward" : "ideal X (no servo model)";
    fmt::print("  section ({}, {} updates per turn): roundness {:.4f} um, centre offset {:.4f} um\n", axis,
               r.updates_per_turn, r.compensated.roundness_um, r.compensated.center_offset_um);
    if (r.servo_axis) {
        fmt::print("  without feedforward: roundness {:.4f} um, centre offset {:.4f} um\n",
                   r.uncompensated.roundness_um, r.uncompensated.center_offset_um);
    }
    fmt::print("  highest spindle speed within 1 um: {:.4g} rpm (limited by {})\n", r.max_rpm, r.limited_by);
    fmt::print("  pass: {:.6g} turns, {:.3f} s\n", r.turns, r.cycle_time_s);
}

bool write_text(const std::string& path, const std::string& text) {
    std::optional<PartialFile> file = PartialFile::create(path);
    if (!file) return false;
    file->write(text);
    return file->commit();
}

bool write_cam_table(const std::string& path, const EccentricJob& job) {
    std::optional<PartialFile> file = PartialFile::create(path);
    if (!file) return false;
    std::string text = "theta_deg,x_diameter_mm\n";
    for (int deg = 0; deg < 360; ++deg) {
        text += fmt::format("{},{:.6f}\n", deg, 2.0 * eccentric_cam(job, deg * std::numbers::pi / 180.0).radius_mm);
    }
    file->write(text);
    return file->commit();
}

int run_eccentric(const EccentricOptions& options) {
    Result<EccentricJob> job = load_eccentric_job(options.job);
    if (!job) {
        print_diagnostics(job.diagnostics());
        return exit_bad_input;
    }
    std::optional<MachineConfig> machine = load_machine_or_report(options.machine);
    if (!machine) return exit_bad_input;
    Result<EccentricReport> report = simulate_eccentric(*job, *machine);
    if (!report) {
        print_diagnostics(report.diagnostics());
        return exit_bad_input;
    }
    std::optional<std::string> program;
    if (!options.program.empty()) {
        Result<std::string> text = eccentric_program(*job, options.job);
        if (!text) {
            print_diagnostics(text.diagnostics());
            return exit_bad_input;
        }
        program = std::move(text).value();
    }
    if (!options.cam_table.empty() && !write_cam_table(options.cam_table, *job)) return exit_bad_input;
    if (program && !write_text(options.program, *program)) return exit_bad_input;
    if (!options.html.empty() && !write_page(eccentric_page(*report, options.job), options.html)) return exit_bad_input;
    if (options.json) {
        print_json(*report);
    } else {
        print_text(*report, options.job);
    }
    return 0;
}

}  // namespace

void add_eccentric_verb(CLI::App& app, int& exit_status) {
    auto options = std::make_shared<EccentricOptions>();
    CLI::App* verb = app.add_subcommand("eccentric", "Eccentric shaft turning with X slaved to the spindle angle");
    verb->add_option("JOB", options->job, "job file (TOML, table [eccentric])")->required();
    verb->add_option("--machine", options->machine, "machine config (TOML); default: the built-in mill");
    verb->add_flag("--json", options->json, "print the report as JSON");
    verb->add_option("--cam-table", options->cam_table, "write the cam as CSV: theta_deg,x_diameter_mm");
    verb->add_option("--html", options->html, "write an interactive page: section, centre offset, cam (HTML)");
    verb->add_option("--program", options->program,
                     "write the cam as a Fanuc lathe program (G-code system A), one block a degree");
    verb->callback([options, &exit_status] { exit_status = run_eccentric(*options); });
}

}  // namespace nckit::cli
