#pragma once
// Reading a whole TOML file (a machine config or a process job) into a document, with I/O and
// syntax problems as located diagnostics. The typed reads of its tables are toml_table_reader's.
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

#include <toml++/toml.h>

#include "nckit/core/diagnostic.hpp"
#include "nckit/core/result.hpp"
#include "nckit/core/toml_table_reader.hpp"

namespace nckit::core_detail {

//! A parsed document and the file name its diagnostics carry.
struct TomlFile {
    std::shared_ptr<const std::string> name;
    toml::table document;
};

//! Parses `text`; a syntax error becomes a "config-syntax" diagnostic at its line and column.
[[nodiscard]] Result<TomlFile> parse_toml_text(std::string_view text, const std::string& file_name);

//! Reads and parses a file; an unreadable file is a "config-io" diagnostic at FILE:0:0 whose
//! message names `what` ("machine config", "crosshatch job").
[[nodiscard]] Result<TomlFile> load_toml_file(const std::filesystem::path& path, std::string_view what);

//! Sorts diagnostics by line and column: toml++ visits keys alphabetically, not in file order.
void sort_by_position(Diagnostics& diagnostics);

//! A job file of one table, `[name]`: `read(table, job, sink)` fills the job and reports into
//! the sink; a missing table and any other top-level key are errors. All diagnostics, sorted.
template <class Job, class ReadTable>
[[nodiscard]] Result<Job> read_job_table(const TomlFile& file, std::string_view name, ReadTable read) {
    ConfigSink sink{file.name, {}};
    Job job;
    TableReader root(file.document, "", sink);
    if (const toml::table* table = root.table(name, Need::optional)) {
        read(*table, job, sink);
    } else if (!root.has(name)) {
        sink.error(root.region(), "config-missing-key", "missing table [" + std::string(name) + "]");
    }
    root.reject_unknown_keys();
    if (sink.diagnostics.empty()) return job;
    sort_by_position(sink.diagnostics);
    return std::move(sink.diagnostics);
}

//! Loads `path` and reads it with read_job_table; `what` names the file in I/O errors.
template <class Job, class ReadTable>
[[nodiscard]] Result<Job> load_job_file(const std::filesystem::path& path, std::string_view what, std::string_view name,
                                        ReadTable read) {
    Result<TomlFile> file = load_toml_file(path, what);
    if (!file) return file.diagnostics();
    return read_job_table<Job>(*file, name, read);
}

//! parse_toml_text, then read_job_table.
template <class Job, class ReadTable>
[[nodiscard]] Result<Job> parse_job_text(std::string_view text, const std::string& file_name, std::string_view name,
                                         ReadTable read) {
    Result<TomlFile> file = parse_toml_text(text, file_name);
    if (!file) return file.diagnostics();
    return read_job_table<Job>(*file, name, read);
}

}  // namespace nckit::core_detail
