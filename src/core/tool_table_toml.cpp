// The TOML tool file: `[[tool]]` tables, each with its number and the columns it needs.
#include <cmath>
#include <array>

#include <fmt/format.h>

#include "nckit/core/tool_table.hpp"
#include "nckit/core/toml_file.hpp"
#include "nckit/core/toml_table_reader.hpp"

namespace nckit {

namespace {

using core_detail::ConfigSink;
using core_detail::Need;
using core_detail::Sign;
using core_detail::TableReader;

//! A radius may be given as a diameter (tool catalogues) or a radius (offset pages); not both.
void read_radius(TableReader& reader, std::string_view radius_key, std::string_view diameter_key, double& out,
                 Sign sign, ConfigSink& sink) {
    if (reader.has(radius_key) && reader.has(diameter_key)) {
        sink.error(reader.region_of(diameter_key), "config-value",
                   fmt::format("give '{}' or '{}', not both", radius_key, diameter_key));
        (void)reader.node(radius_key, Need::optional);  // both are known keys: no second error
        (void)reader.node(diameter_key, Need::optional);
        return;
    }
    if (reader.has(diameter_key)) {
        double diameter = 0;
        if (reader.number_into(diameter_key, Need::optional, sign, diameter)) out = diameter / 2.0;
        return;
    }
    reader.number_into(radius_key, Need::optional, sign, out);
}

std::optional<ToolEntry> read_tool(const toml::table& table, ConfigSink& sink) {
    const std::size_t errors_before = sink.diagnostics.size();
    TableReader reader(table, "[[tool]]", sink);
    ToolEntry tool;
    if (auto number = reader.integer("number", Need::required, Sign::positive)) {
        if (*number > max_tool_number) {
            sink.error(reader.region_of("number"), "config-value",
                       fmt::format("'number' is a tool number 1 to {}, not {}", max_tool_number, *number));
        }
        tool.number = *number;
    }
    if (auto pocket = reader.integer("pocket", Need::optional, Sign::non_negative)) tool.pocket = *pocket;
    reader.number_into("length_mm", Need::optional, Sign::any, tool.length_mm);
    reader.number_into("length_wear_mm", Need::optional, Sign::any, tool.length_wear_mm);
    if (reader.has("nose_radius_mm") && (reader.has("radius_mm") || reader.has("diameter_mm"))) {
        sink.error(reader.region_of("nose_radius_mm"), "config-value",
                   "'nose_radius_mm' is the radius column of a lathe tool: give it or 'radius_mm'/'diameter_mm'");
    }
    read_radius(reader, "radius_mm", "diameter_mm", tool.radius_mm, Sign::non_negative, sink);
    reader.number_into("nose_radius_mm", Need::optional, Sign::non_negative, tool.radius_mm);
    read_radius(reader, "radius_wear_mm", "diameter_wear_mm", tool.radius_wear_mm, Sign::any, sink);
    reader.number_into("x_offset_mm", Need::optional, Sign::any, tool.x_offset_mm);
    reader.number_into("x_wear_mm", Need::optional, Sign::any, tool.x_wear_mm);
    if (auto orientation = reader.integer("orientation", Need::optional, Sign::non_negative)) {
        if (*orientation > 9) {
            sink.error(reader.region_of("orientation"), "config-value",
                       fmt::format("'orientation' is a tip orientation 0 to 9, not {}", *orientation));
        }
        tool.orientation = *orientation;
    }
    reader.number_into("front_angle_deg", Need::optional, Sign::any, tool.front_angle_deg);
    reader.number_into("back_angle_deg", Need::optional, Sign::any, tool.back_angle_deg);
    if (auto comment = reader.text("comment", Need::optional)) tool.comment = std::move(*comment);
    reader.reject_unknown_keys();
    // Each column with the keys that may fill it (a diameter or nose radius lands in a radius).
    struct Column {
        double value_mm;
        std::array<std::string_view, 3> keys;  // the column's own key first; empty when fewer
    };
    for (const Column& column : {Column{tool.length_mm, {"length_mm"}}, Column{tool.length_wear_mm, {"length_wear_mm"}},
                                 Column{tool.radius_mm, {"radius_mm", "diameter_mm", "nose_radius_mm"}},
                                 Column{tool.radius_wear_mm, {"radius_wear_mm", "diameter_wear_mm"}},
                                 Column{tool.x_offset_mm, {"x_offset_mm"}}, Column{tool.x_wear_mm, {"x_wear_mm"}}}) {
        if (std::abs(column.value_mm) <= max_tool_value_mm) continue;
        std::string_view given = column.keys[0];
        for (std::string_view key : column.keys) {
            if (!key.empty() && reader.has(key)) given = key;
        }
        sink.error(reader.region_of(given), "config-value",
                   fmt::format("'{}' is beyond the {} mm a tool can measure", given, max_tool_value_mm));
    }
    if (sink.diagnostics.size() != errors_before) return std::nullopt;
    return tool;
}

}  // namespace

Result<ToolTable> parse_tool_toml(std::string_view text, const std::string& file_name) {
    Result<core_detail::TomlFile> file = core_detail::parse_toml_text(text, file_name);
    if (!file) return file.diagnostics();
    ConfigSink sink{file->name, {}};
    ToolTable table;
    TableReader root(file->document, "", sink);
    if (const toml::array* tools = root.array("tool", Need::required)) {
        for (const toml::node& element : *tools) {
            const toml::table* row = element.as_table();
            if (row == nullptr) {
                sink.error(
                    element.source(), "config-type",
                    fmt::format("each [[tool]] must be a table, not {}", core_detail::type_name(element.type())));
                continue;
            }
            std::optional<ToolEntry> tool = read_tool(*row, sink);
            if (!tool) continue;
            if (table.find(tool->number) != nullptr) {
                sink.error(row->get("number")->source(), "config-duplicate-tool",
                           fmt::format("tool {} is listed twice", tool->number));
                continue;
            }
            table.insert(std::move(*tool));
        }
    }
    root.reject_unknown_keys();
    if (sink.diagnostics.empty()) return table;
    core_detail::sort_by_position(sink.diagnostics);
    return std::move(sink.diagnostics);
}

}  // namespace nckit
