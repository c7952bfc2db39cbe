// The eccentric job file: one [eccentric] table, every key checked where it stands.
#include <cmath>

#include <fmt/format.h>

#include "nckit/core/toml_file.hpp"
#include "nckit/core/toml_table_reader.hpp"
#include "nckit/process/eccentric/eccentric.hpp"

namespace nckit {

namespace {

using core_detail::ConfigSink;
using core_detail::Need;
using core_detail::Sign;
using core_detail::TableReader;

void read_eccentric(const toml::table& table, EccentricJob& job, ConfigSink& sink) {
    TableReader reader(table, "[eccentric]", sink);
    reader.number_into("blank_diameter_mm", Need::required, Sign::positive, job.blank_diameter_mm);
    reader.number_into("eccentricity_mm", Need::required, Sign::non_negative, job.eccentricity_mm);
    reader.number_into("eccentric_radius_mm", Need::required, Sign::positive, job.eccentric_radius_mm);
    reader.number_into("z_start_mm", Need::required, Sign::any, job.z_start_mm);
    reader.number_into("z_end_mm", Need::required, Sign::any, job.z_end_mm);
    reader.number_into("rpm", Need::required, Sign::positive, job.rpm);
    reader.number_into("feed_mm_rev", Need::required, Sign::positive, job.feed_mm_rev);
    reader.number_into("nose_radius_mm", Need::optional, Sign::non_negative, job.nose_radius_mm);
    if (auto updates = reader.integer("updates_per_turn", Need::optional, Sign::positive)) {
        job.updates_per_turn = *updates;
    }
    reader.number_into("model_error", Need::optional, Sign::any, job.model_error);
    job.rpm_at = sink.at(reader.region_of("rpm"));
    job.radius_at = sink.at(reader.region_of("eccentric_radius_mm"));
    job.feed_at = sink.at(reader.region_of("feed_mm_rev"));
    reader.reject_unknown_keys();

    const double e = job.eccentricity_mm;
    const double r = job.eccentric_radius_mm;
    if (r > 0 && e >= r) {
        // a(θ) needs r² ≥ e² sin² θ for every θ, and the paper asks e < r.
        sink.error(reader.region_of("eccentricity_mm"), "config-value",
                   fmt::format("the eccentricity {} mm must be smaller than the eccentric radius {} mm", e, r));
    }
    if (job.blank_diameter_mm > 0 && e + r > job.blank_diameter_mm / 2) {
        sink.error(reader.region_of("eccentric_radius_mm"), "config-value",
                   fmt::format("the eccentric cylinder reaches {} mm from the axis, outside the {} mm blank", e + r,
                               job.blank_diameter_mm));
    }
    if (job.z_end_mm == job.z_start_mm) {
        sink.error(reader.region_of("z_end_mm"), "config-value", "'z_end_mm' equals 'z_start_mm': nothing to turn");
    }
    if (job.rpm > 100000) {
        sink.error(reader.region_of("rpm"), "config-value", fmt::format("'rpm' = {} is beyond any lathe", job.rpm));
    }
    if (std::abs(job.z_end_mm - job.z_start_mm) / std::max(job.feed_mm_rev, 1e-12) > 1e7) {
        sink.error(reader.region_of("feed_mm_rev"), "config-value",
                   "more than ten million turns over the length: check 'feed_mm_rev'");
    }
    if (!(job.model_error > -0.5 && job.model_error < 0.5)) {
        sink.error(reader.region_of("model_error"), "config-value",
                   fmt::format("'model_error' must lie between -0.5 and 0.5, not {}", job.model_error));
    }
    if (reader.has("updates_per_turn") && job.updates_per_turn < 3) {
        // The section's circle fit needs three points a turn; fewer would report a perfect circle.
        sink.error(reader.region_of("updates_per_turn"), "config-value",
                   fmt::format("'updates_per_turn' = {} is too few: a section needs at least 3 points a turn",
                               job.updates_per_turn));
    }
    if (job.updates_per_turn > 1000000) {
        sink.error(reader.region_of("updates_per_turn"), "config-value",
                   fmt::format("'updates_per_turn' = {} is more than any encoder gives", job.updates_per_turn));
    }
}

}  // namespace

Result<EccentricJob> parse_eccentric_job(std::string_view toml_text, const std::string& file_name) {
    return core_detail::parse_job_text<EccentricJob>(toml_text, file_name, "eccentric", read_eccentric);
}

Result<EccentricJob> load_eccentric_job(const std::filesystem::path& path) {
    return core_detail::load_job_file<EccentricJob>(path, "eccentric job", "eccentric", read_eccentric);
}

}  // namespace nckit
