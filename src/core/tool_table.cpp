#include "nckit/core/tool_table.hpp"

#include <fstream>
#include <sstream>

#include <fmt/format.h>

namespace nckit {

const ToolEntry* ToolTable::find(int number) const {
    auto hit = rows_.find(number);
    return hit != rows_.end() ? &hit->second : nullptr;
}

ToolEntry& ToolTable::entry(int number) {
    ToolEntry& row = rows_[number];
    row.number = number;
    return row;
}

std::optional<double> ToolTable::radius_mm(int d_number) const {
    if (d_number == 0) return 0.0;
    const ToolEntry* row = find(d_number);
    if (row == nullptr) return std::nullopt;
    return row->total_radius_mm();
}

std::optional<double> ToolTable::length_mm(int h_number) const {
    if (h_number == 0) return 0.0;
    const ToolEntry* row = find(h_number);
    if (row == nullptr) return std::nullopt;
    return row->total_length_mm();
}

Result<ToolTable> load_tool_table(const std::filesystem::path& path) {
    const std::string name = path.string();
    auto cannot_read = [&](std::string reason) {
        return error_at(make_location(std::make_shared<const std::string>(name), 0, 0), "config-io",
                        fmt::format("cannot read tool file: {}", reason));
    };
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) return cannot_read("it is a directory");
    // A tool table holds at most some thousand rows; a huge file is a mistake, not a table.
    constexpr std::uintmax_t max_bytes = 16u << 20;
    const std::uintmax_t bytes = std::filesystem::file_size(path, ec);
    if (ec) return cannot_read(ec.message());
    if (bytes > max_bytes) return cannot_read(fmt::format("it has {} bytes, more than {}", bytes, max_bytes));
    std::ifstream in(path, std::ios::binary);
    if (!in) return cannot_read("cannot open it");
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) return cannot_read("read failed");
    if (path.extension() == ".toml") return parse_tool_toml(text.str(), name);
    return parse_tool_tbl(text.str(), name);
}

}  // namespace nckit
