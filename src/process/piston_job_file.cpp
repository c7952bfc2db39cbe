// A piston job with the places in its file the simulation reports at. The job reader keeps
// values only, so the document is read a second time for positions: a few microseconds on a file
// of a few dozen lines, and the job reader stays a plain value reader.
#include <utility>

#include "nckit/core/toml_file.hpp"
#include "nckit/process/piston.hpp"

namespace nckit {

namespace {

//! The region of `key` in `table`, or the table's own when the key is absent.
const toml::source_region& region_of(const toml::table& table, std::string_view key) {
    const toml::node* node = table.get(key);
    return node != nullptr ? node->source() : table.source();
}

Result<PistonJobFile> with_source(Result<cam::PistonJob> job, Result<detail::TomlFile> file) {
    if (!job) return job.diagnostics();
    // The job read the same text without error, so the document parses and both tables exist.
    if (!file) return file.diagnostics();
    const detail::ConfigSink sink{file->name, {}};
    const toml::table& servo = *file->document["servo"].as_table();
    const toml::table& piston = *file->document["piston"].as_table();
    PistonJobSource source;
    source.servo = sink.at(servo.source());
    source.stroke = sink.at(region_of(servo, "stroke_mm"));
    source.encoder_counts = sink.at(region_of(piston, "encoder_counts"));
    source.ripple_given = piston.contains("spindle_ripple");
    return PistonJobFile{std::move(job).value(), std::move(source)};
}

}  // namespace

Result<PistonJobFile> load_piston_job_file(const std::filesystem::path& path) {
    Result<cam::PistonJob> job = cam::load_piston_job(path);
    if (!job) return job.diagnostics();
    return with_source(std::move(job), detail::load_toml_file(path, "piston job"));
}

Result<PistonJobFile> parse_piston_job_file(std::string_view toml_text, const std::string& file_name) {
    Result<cam::PistonJob> job = cam::parse_piston_job(toml_text, file_name);
    if (!job) return job.diagnostics();
    return with_source(std::move(job), detail::parse_toml_text(toml_text, file_name));
}

}  // namespace nckit
