#include "plugin_settings.hpp"

#include <charconv>
#include <fstream>

#include <fmt/format.h>

namespace nckit::lcnc {

namespace {

constexpr std::size_t max_ini_lines = 100'000;  // an INI is a few hundred lines; bound the loop

std::string trim(std::string_view s) {
    std::size_t b = s.find_first_not_of(" \t\r");
    if (b == std::string_view::npos) return {};
    std::size_t e = s.find_last_not_of(" \t\r");
    return std::string(s.substr(b, e - b + 1));
}

std::string upper(std::string s) {
    for (char& c : s) {
        if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
    }
    return s;
}

}  // namespace

std::optional<std::string> read_plugin_settings(const std::filesystem::path& ini_path, PluginSettings& settings) {
    std::ifstream in(ini_path);
    if (!in) return fmt::format("{}: error: cannot open the INI file", ini_path.string());
    const std::filesystem::path base = ini_path.parent_path();
    auto path_of = [&](const std::string& value) {
        std::filesystem::path p(value);
        return p.is_relative() ? base / p : p;
    };
    std::string section;
    std::string text;
    bool tool_table_from_nckit = false;
    for (std::size_t number = 1; number <= max_ini_lines && std::getline(in, text); ++number) {
        std::string line = trim(text);
        if (line.empty() || line[0] == '#' || line[0] == ';') continue;
        if (line[0] == '[') {
            section = upper(trim(std::string_view(line).substr(1, line.find(']') - 1)));
            continue;
        }
        std::size_t eq = line.find('=');
        if (section != "NCKIT") {
            // LinuxCNC's own tool table and length unit, unless [NCKIT] names a table itself.
            if (eq == std::string::npos) continue;
            std::string key = upper(trim(std::string_view(line).substr(0, eq)));
            std::string value = trim(std::string_view(line).substr(eq + 1));
            if (section == "EMCIO" && key == "TOOL_TABLE" && !tool_table_from_nckit && !value.empty()) {
                settings.tool_table_file = path_of(value);
            } else if (section == "TRAJ" && key == "LINEAR_UNITS") {
                std::string unit = upper(value);
                settings.tool_table_inch = unit == "INCH" || unit == "IN" || unit == "INCHES";
            }
            continue;
        }
        auto where = [&](std::string_view what) {
            return fmt::format("{}:{}:1: error: [NCKIT] {}", ini_path.string(), number, what);
        };
        if (eq == std::string::npos) return where(fmt::format("'{}' is not KEY = VALUE", line));
        std::string key = upper(trim(std::string_view(line).substr(0, eq)));
        std::string value = trim(std::string_view(line).substr(eq + 1));
        if (key == "MACHINE") {
            settings.machine_file = path_of(value);
        } else if (key == "LIBRARY") {
            settings.library_dir = path_of(value);
        } else if (key == "RETAINED") {
            settings.retained_file = path_of(value);
        } else if (key == "MAX_BLOCKS") {
            std::int64_t n = 0;
            auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), n);
            if (ec != std::errc{} || end != value.data() + value.size() || n <= 0) {
                return where(fmt::format("MAX_BLOCKS = {}: expected a positive whole number", value));
            }
            settings.max_blocks = n;
        } else if (key == "G64_TOLERANCE") {
            double v = 0;
            auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), v);
            if (ec != std::errc{} || end != value.data() + value.size() || !(v >= 0)) {
                return where(fmt::format("G64_TOLERANCE = {}: expected a distance in mm, 0 or more", value));
            }
            settings.g64_tolerance_mm = v;
        } else if (key == "TOOL_TABLE") {
            settings.tool_table_file = path_of(value);
            tool_table_from_nckit = true;
        } else if (key == "EXACT_PATH") {
            if (value != "0" && value != "1") return where(fmt::format("EXACT_PATH = {}: expected 0 or 1", value));
            settings.exact_path = value == "1";
        } else if (key == "LINE_COMMENTS") {
            if (value != "0" && value != "1") return where(fmt::format("LINE_COMMENTS = {}: expected 0 or 1", value));
            settings.line_comments = value == "1";
        } else if (key == "JOURNAL") {
            settings.journal_file = value.empty() ? std::filesystem::path() : path_of(value);
        } else if (key == "JOURNAL_FSYNC_MS") {
            std::int64_t n = 0;
            auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), n);
            if (ec != std::errc{} || end != value.data() + value.size() || n < 0 || n > 3'600'000) {
                return where(fmt::format("JOURNAL_FSYNC_MS = {}: expected a whole number of ms, 0 to 3600000", value));
            }
            settings.journal_fsync_ms = n;
        } else {
            return where(
                fmt::format("unknown key {} (MACHINE, LIBRARY, RETAINED, MAX_BLOCKS, G64_TOLERANCE, "
                            "EXACT_PATH, TOOL_TABLE, LINE_COMMENTS, JOURNAL, JOURNAL_FSYNC_MS)",
                            key));
        }
    }
    return std::nullopt;
}

}  // namespace nckit::lcnc
