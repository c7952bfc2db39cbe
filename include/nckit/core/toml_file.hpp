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

namespace nckit::detail {

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

}  // namespace nckit::detail
