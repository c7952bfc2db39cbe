// The crosshatch job file: one [crosshatch] table, every key checked where it stands.
#include <cmath>

#include <fmt/format.h>

#include "nckit/core/toml_file.hpp"
#include "nckit/core/toml_table_reader.hpp"
#include "nckit/drive/phase_table.hpp"
#include "nckit/process/crosshatch/crosshatch.hpp"

namespace nckit {

namespace {

using core_detail::ConfigSink;
using core_detail::Need;
using core_detail::Sign;
using core_detail::TableReader;

// A value the physics allows but no bore-hardening cell has: most likely a unit mistake (m for
// mm, rev/s for rpm), which would otherwise produce a scan of hours or of no steps at all.
void check_at_most(TableReader& reader, ConfigSink& sink, std::string_view key, double value, double limit,
                   std::string_view unit) {
    if (value > limit) {
        sink.error(reader.region_of(key), "config-value",
                   fmt::format("'{}' = {} is beyond any bore-hardening cell (at most {} {})", key, value, limit, unit));
    }
}

// A bore narrower than any laser head fits into: most likely metres for mm (0.092 for 92).
constexpr double smallest_bore_mm = 10;

void read_crosshatch(const toml::table& table, CrosshatchJob& job, ConfigSink& sink) {
    TableReader reader(table, "[crosshatch]", sink);
    reader.number_into("bore_diameter_mm", Need::required, Sign::positive, job.bore_diameter_mm);
    reader.number_into("bore_length_mm", Need::required, Sign::positive, job.bore_length_mm);
    job.bore_length_at = sink.at(reader.region_of("bore_length_mm"));
    reader.number_into("lead_screw_pitch_mm", Need::required, Sign::positive, job.lead_screw_pitch_mm);
    if (const std::optional<int> heads = reader.integer("heads", Need::required, Sign::positive)) job.heads = *heads;
    reader.number_into("lines_per_length", Need::required, Sign::positive, job.lines_per_length);
    reader.number_into("feed_screw_rpm", Need::required, Sign::positive, job.feed_screw_rpm);
    job.feed_screw_rpm_at = sink.at(reader.region_of("feed_screw_rpm"));
    reader.number_into("step_angle_deg", Need::optional, Sign::positive, job.step_angle_deg);
    reader.number_into("gear_ratio", Need::optional, Sign::positive, job.gear_ratio);
    reader.number_into("timer_clock_hz", Need::optional, Sign::positive, job.timer_clock_hz);
    job.timer_clock_at = sink.at(reader.region_of("timer_clock_hz"));
    if (const std::optional<int> divisor = reader.integer("timer_max_divisor", Need::optional, Sign::positive)) {
        if (*divisor < 2 || *divisor > 65536) {
            sink.error(reader.region_of("timer_max_divisor"), "config-value",
                       fmt::format("'timer_max_divisor' must be 2 to 65536 (a 16-bit counter), not {}", *divisor));
        } else {
            job.timer_max_divisor = static_cast<std::uint32_t>(*divisor);
        }
    }
    job.index_deg = -1;
    reader.number_into("index_deg", Need::optional, Sign::non_negative, job.index_deg);
    if (job.index_deg > 360) {
        sink.error(reader.region_of("index_deg"), "config-value",
                   fmt::format("'index_deg' must be 0 to 360, not {}", job.index_deg));
    }
    if (const std::optional<int> cycles = reader.integer("cycles", Need::optional, Sign::positive)) {
        job.cycles = *cycles;
    }
    reader.number_into("index_rpm", Need::optional, Sign::positive, job.index_rpm);
    job.index_rpm_at = sink.at(reader.region_of("index_rpm"));
    if (const std::optional<std::size_t> timing =
            reader.choice("timing", Need::optional, "timing", {"one_time_base", "free_running_timers"})) {
        job.timing = *timing == 0 ? CrosshatchTiming::one_time_base : CrosshatchTiming::free_running_timers;
    }
    if (const std::optional<std::string> table_name = reader.text("phase_table", Need::optional)) {
        if (const auto kind = drive::parse_phase_table(*table_name)) {
            job.phase_table = *kind;
        } else {
            sink.error(
                reader.region_of("phase_table"), "config-value",
                fmt::format("phase table '{}' is not one of {}", *table_name, fmt::join(phase_table_names, " ")));
        }
    }
    if (auto code = reader.integer("laser_on_mcode", Need::optional, Sign::non_negative)) job.laser_on_mcode = *code;
    if (auto code = reader.integer("laser_off_mcode", Need::optional, Sign::non_negative)) job.laser_off_mcode = *code;
    reader.reject_unknown_keys();

    check_at_most(reader, sink, "bore_diameter_mm", job.bore_diameter_mm, 2000, "mm");
    if (job.bore_diameter_mm > 0 && job.bore_diameter_mm < smallest_bore_mm) {
        sink.error(reader.region_of("bore_diameter_mm"), "config-value",
                   fmt::format("'bore_diameter_mm' = {} is below any bore-hardening cell (at least {} mm): is it "
                               "in metres?",
                               job.bore_diameter_mm, smallest_bore_mm));
    }
    check_at_most(reader, sink, "bore_length_mm", job.bore_length_mm, 5000, "mm");
    check_at_most(reader, sink, "lead_screw_pitch_mm", job.lead_screw_pitch_mm, 100, "mm");
    check_at_most(reader, sink, "heads", job.heads, 360, "helix starts");
    check_at_most(reader, sink, "lines_per_length", job.lines_per_length, 10000, "lines");
    check_at_most(reader, sink, "cycles", job.cycles, 3600, "cycles");
    check_at_most(reader, sink, "timer_clock_hz", job.timer_clock_hz, 1e9, "Hz");
    if (job.step_angle_deg >= 360) {
        sink.error(reader.region_of("step_angle_deg"), "config-value",
                   fmt::format("'step_angle_deg' must be below 360, not {}", job.step_angle_deg));
    }
    if (job.laser_on_mcode == job.laser_off_mcode) {
        sink.error(reader.region_of("laser_off_mcode"), "config-value",
                   fmt::format("the laser-on and laser-off M-codes are both M{}", job.laser_on_mcode));
    }
    if (job.heads > 0) {
        if (job.index_deg < 0) job.index_deg = 360.0 / job.heads;
        if (job.cycles == 0) job.cycles = job.heads;
    }
}

}  // namespace

Result<CrosshatchJob> parse_crosshatch_job(std::string_view toml_text, const std::string& file_name) {
    return core_detail::parse_job_text<CrosshatchJob>(toml_text, file_name, "crosshatch", read_crosshatch);
}

Result<CrosshatchJob> load_crosshatch_job(const std::filesystem::path& path) {
    return core_detail::load_job_file<CrosshatchJob>(path, "crosshatch job", "crosshatch", read_crosshatch);
}

}  // namespace nckit
