#include "nckit/core/toml_file.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <tuple>

#include <fmt/format.h>

namespace nckit::core_detail {

namespace {

std::string lower_first(std::string text) {
    if (!text.empty()) text[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(text[0])));
    return text;
}

//! toml++ says "Error while parsing key-value pair: ..."; our messages are lower case and the
//! printed form already says "error".
Diagnostic syntax_error(const toml::parse_error& error, std::shared_ptr<const std::string> file) {
    std::string description(error.description());
    constexpr std::string_view prefix = "Error while parsing ";
    if (description.rfind(prefix, 0) == 0) {
        description = "toml syntax error in " + description.substr(prefix.size());
    } else {
        description = "toml syntax error: " + lower_first(std::move(description));
    }
    while (!description.empty() && description.back() == '.') description.pop_back();
    const toml::source_position at = error.source().begin;
    return error_at(make_location(std::move(file), at.line, at.column), "config-syntax", std::move(description));
}

}  // namespace

Result<TomlFile> parse_toml_text(std::string_view text, const std::string& file_name) {
    TomlFile file{std::make_shared<const std::string>(file_name), {}};
    try {
        file.document = toml::parse(text, std::string_view{file_name});
    } catch (const toml::parse_error& error) {
        return syntax_error(error, file.name);
    }
    return file;
}

Result<TomlFile> load_toml_file(const std::filesystem::path& path, std::string_view what) {
    const std::string file_name = path.string();
    auto cannot_read = [&](std::string reason) {
        return error_at(make_location(std::make_shared<const std::string>(file_name), 0, 0), "config-io",
                        fmt::format("cannot read {}: {}", what, reason));
    };
    // An ifstream "opens" a directory and only fails (by throwing) on the first read.
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) return cannot_read("it is a directory");
    // Configs and jobs are a few kB; a huge file is a mistake (a program or a log passed by
    // error), and reading it whole would only exhaust memory.
    constexpr std::uintmax_t max_bytes = 16u << 20;
    const std::uintmax_t bytes = std::filesystem::file_size(path, ec);
    if (!ec && bytes > max_bytes) {
        return cannot_read(fmt::format("it has {} bytes, more than the {} a config may have", bytes, max_bytes));
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) return cannot_read(lower_first(std::strerror(errno)));
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) return cannot_read("read failed");
    return parse_toml_text(text.str(), file_name);
}

void sort_by_position(Diagnostics& diagnostics) {
    std::stable_sort(diagnostics.begin(), diagnostics.end(), [](const Diagnostic& a, const Diagnostic& b) {
        return std::tie(a.location.line, a.location.column) < std::tie(b.location.line, b.location.column);
    });
}

}  // namespace nckit::core_detail
