// LinuxCNC's tool.tbl read as it is: one tool per line, words of a letter and a number
// (`T1 P1 X+0.0 Z+12.5 D6.0 ;comment`). Z is the length, D the diameter, X the lathe X offset,
// Q the tip orientation, I/J the front and back angles.
#include <array>
#include <cctype>
#include <cmath>
#include <optional>
#include <charconv>
#include <memory>

#include <fmt/format.h>

#include "nckit/core/tool_table.hpp"

namespace nckit {

namespace {

constexpr double mm_per_inch = 25.4;

struct LineReader {
    std::shared_ptr<const std::string> file;
    std::uint32_t line = 0;
    Diagnostics& diagnostics;

    void error(std::size_t column, std::string message) {
        diagnostics.push_back(error_at(make_location(file, line, static_cast<std::uint32_t>(column + 1)), "tool-table",
                                       std::move(message)));
    }
};

//! The number starting at `pos` (sign, digits, point, exponent): LinuxCNC reads it with strtod.
std::optional<double> read_number(std::string_view text, std::size_t& pos) {
    std::size_t start = pos;
    if (pos < text.size() && text[pos] == '+') ++pos;  // from_chars takes '-' but not '+'
    double value = 0;
    auto [end, ec] = std::from_chars(text.data() + pos, text.data() + text.size(), value);
    if (ec != std::errc{} || !std::isfinite(value)) {
        pos = start;
        return std::nullopt;
    }
    pos = static_cast<std::size_t>(end - text.data());
    return value;
}

bool is_whole(double value) {
    return value == std::floor(value);
}

//! One line into `tool`; false when it has an error (reported) or no T word.
bool read_row(std::string_view text, LineReader& reader, bool inch, ToolEntry& tool, bool& has_tool) {
    const double scale = inch ? mm_per_inch : 1.0;
    std::array<bool, 26> seen{};
    std::size_t pos = 0;
    while (pos < text.size()) {
        char c = text[pos];
        if (c == ';') {
            std::string_view comment = text.substr(pos + 1);
            while (!comment.empty() && std::isspace(static_cast<unsigned char>(comment.front())))
                comment.remove_prefix(1);
            while (!comment.empty() && std::isspace(static_cast<unsigned char>(comment.back())))
                comment.remove_suffix(1);
            tool.comment = std::string(comment);
            break;
        }
        if (std::isspace(static_cast<unsigned char>(c))) {
            ++pos;
            continue;
        }
        const std::size_t column = pos;
        const char letter = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
        if (letter < 'A' || letter > 'Z') {
            reader.error(column, fmt::format("'{}' is not a tool table word", c));
            return false;
        }
        ++pos;
        std::optional<double> value = read_number(text, pos);
        if (!value) {
            reader.error(column, fmt::format("{} needs a number", letter));
            return false;
        }
        if (seen[letter - 'A']) {
            reader.error(column, fmt::format("{} appears twice in one tool", letter));
            return false;
        }
        seen[letter - 'A'] = true;
        if ((letter == 'Z' || letter == 'X' || letter == 'D') && std::abs(*value * scale) > max_tool_value_mm) {
            reader.error(
                column, fmt::format("{} {} is beyond the {} mm a tool can measure", letter, *value, max_tool_value_mm));
            return false;
        }
        switch (letter) {
            case 'T':
            case 'P':
            case 'Q':
                if (!is_whole(*value) || *value < 0 || *value > max_tool_number) {
                    reader.error(column,
                                 fmt::format("{} must be a whole number from 0 to {}", letter, max_tool_number));
                    return false;
                }
                if (letter == 'T') {
                    tool.number = static_cast<int>(*value);
                    has_tool = true;
                } else if (letter == 'P') {
                    tool.pocket = static_cast<int>(*value);
                } else if (*value > 9) {
                    reader.error(column, "Q is a tip orientation from 0 to 9");
                    return false;
                } else {
                    tool.orientation = static_cast<int>(*value);
                }
                break;
            case 'Z':
                tool.length_mm = *value * scale;
                break;
            case 'X':
                tool.x_offset_mm = *value * scale;
                break;
            case 'D':
                if (*value < 0) {
                    reader.error(column, "D (diameter) must not be negative");
                    return false;
                }
                tool.radius_mm = *value * scale / 2.0;
                break;
            case 'I':
                tool.front_angle_deg = *value;
                break;
            case 'J':
                tool.back_angle_deg = *value;
                break;
            case 'Y':
            case 'A':
            case 'B':
            case 'C':
            case 'U':
            case 'V':
            case 'W':
                // Offsets along other axes are columns LinuxCNC keeps; nckit offsets Z (and a
                // lathe's X) only, so a value there would be silently dropped.
                if (*value != 0) {
                    reader.error(column, fmt::format("a {} offset is not supported (only Z, X, D, Q, I, J)", letter));
                    return false;
                }
                break;
            default:
                reader.error(column, fmt::format("{} is not a tool table column", letter));
                return false;
        }
    }
    if (!has_tool && (seen['P' - 'A'] || seen['Z' - 'A'] || seen['D' - 'A'] || seen['X' - 'A'])) {
        reader.error(0, "tool line without T (tool number)");
        return false;
    }
    return true;
}

}  // namespace

Result<ToolTable> parse_tool_tbl(std::string_view text, const std::string& file_name, bool inch_values) {
    Diagnostics diagnostics;
    LineReader reader{std::make_shared<const std::string>(file_name), 0, diagnostics};
    ToolTable table;
    std::size_t start = 0;
    while (start <= text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(start, end - start);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        ++reader.line;
        ToolEntry tool;
        bool has_tool = false;
        if (read_row(line, reader, inch_values, tool, has_tool) && has_tool) {
            if (table.find(tool.number) != nullptr) {
                reader.error(line.find_first_not_of(" \t"), fmt::format("tool {} is listed twice", tool.number));
            } else {
                table.insert(std::move(tool));
            }
        }
        if (end == text.size()) break;
        start = end + 1;
    }
    if (!diagnostics.empty()) return diagnostics;
    return table;
}

}  // namespace nckit
