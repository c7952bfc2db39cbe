// A lathe's tool offsets as a Fanuc 0i-T keeps them. T xxyy selects tool xx with offset yy:
// geometry plus wear in X and Z shift the program (as G43 does along Z on a mill), the nose
// radius and the imaginary tip orientation serve G41/G42; yy = 00 cancels the offset.
// G10 P writes an offset (P n: wear n, P 100nn / 10000+n: geometry n; X Z absolute, U W
// incremental, R nose radius, Q tip orientation), and the macro variables read and write them:
//   #2001+n X wear, #2101+n Z wear, #2201+n nose radius wear, #2301+n tip orientation,
//   #2701+n X geometry, #2801+n Z geometry, #2901+n nose radius geometry (n = 0..98).
// X values are diameters on a diameter-programming lathe, as the control shows them; the table
// keeps radii.
#include <cmath>

#include <fmt/format.h>

#include "executor.hpp"
#include "nckit/gcode/macro_alarms.hpp"

namespace nckit::interp {

namespace {
constexpr int offsets_per_page = 100;  // #2001-#2099 and so on: offsets 1 to 99
constexpr int max_lathe_offset = 99;
constexpr int geometry_base = 10000;  // G10 P10001: geometry of offset 1

enum class LatheColumn { x_wear, z_wear, radius_wear, tip, x_geometry, z_geometry, radius_geometry, none };

LatheColumn column_of_page(std::int64_t page) {
    switch (page) {
        case 0:
            return LatheColumn::x_wear;
        case 1:
            return LatheColumn::z_wear;
        case 2:
            return LatheColumn::radius_wear;
        case 3:
            return LatheColumn::tip;
        case 7:
            return LatheColumn::x_geometry;
        case 8:
            return LatheColumn::z_geometry;
        case 9:
            return LatheColumn::radius_geometry;
        default:
            return LatheColumn::none;
    }
}

bool is_x(LatheColumn c) {
    return c == LatheColumn::x_wear || c == LatheColumn::x_geometry;
}
}  // namespace

std::optional<Diagnostic> Executor::select_lathe_tool(const Word& t) {
    const auto value = static_cast<int>(t.value);
    // Two digits of offset: T0101, T101 and T1 (offset 1 of tool 0) as a 0i-T reads them.
    const int tool = value / 100;
    const int offset = value % 100;
    modal_.tool.selected = tool;
    modal_.tool.in_spindle = tool;  // a turret indexes at the T word: no M6
    modal_.tool.d_number = offset;
    modal_.tool_offset = AxisVector{};
    if (offset != 0) {
        if (const ToolEntry* entry = tools_.find(offset)) {
            modal_.tool_offset[Axis::X] = entry->x_offset_mm + entry->x_wear_mm;
            modal_.tool_offset[Axis::Z] = entry->length_mm + entry->length_wear_mm;
        }
    }
    return std::nullopt;
}

bool Executor::is_lathe_offset_write() const {
    return machine_.gcode_system != GCodeSystem::none && words_.group(ModalGroup::non_modal) == g(10) &&
           !words_.has('L');
}

std::optional<Diagnostic> Executor::check_lathe_offset_write() const {
    const Word* p = words_.word('P');
    const std::uint32_t column = words_.group_column(ModalGroup::non_modal);
    if (p == nullptr)
        return error(column, "bad-g10", "G10 on a lathe needs P, the offset number (or L2 P for a work system)");
    const double number = p->value >= geometry_base ? p->value - geometry_base : p->value;
    if (number < 1 || number > max_lathe_offset || p->value != std::floor(p->value)) {
        return error(p->column, "bad-g10",
                     fmt::format("G10 P: wear offset 1 to {} or geometry {} to {}", max_lathe_offset, geometry_base + 1,
                                 geometry_base + max_lathe_offset));
    }
    for (const Word& word : block_->words) {
        const char c = words_.reads_as(word.letter);
        if (c == 'G' || c == 'N' || c == 'P' || c == 'X' || c == 'Z' || c == 'R' || c == 'Q') continue;
        return error(word.column, "unused-word", fmt::format("G10 P (lathe offset) takes no {} word", word.letter));
    }
    if (const Word* q = words_.word('Q');
        q != nullptr && (q->value < 0 || q->value > 9 || q->value != std::floor(q->value))) {
        return error(q->column, "bad-value", "G10 Q is a tip orientation 0 to 9");
    }
    return std::nullopt;
}

void Executor::write_lathe_offset() {
    const Word* p = words_.word('P');
    const bool geometry = p->value >= geometry_base;
    ToolEntry& tool = tools_.entry(static_cast<int>(geometry ? p->value - geometry_base : p->value));
    auto set = [&](double& field, char letter, double value) {
        field = words_.incremental_letter[letter - 'A'] ? field + value : value;
    };
    if (const Word* x = words_.word('X'))
        set(geometry ? tool.x_offset_mm : tool.x_wear_mm, 'X', axis_value(Axis::X, *x));
    if (const Word* z = words_.word('Z'))
        set(geometry ? tool.length_mm : tool.length_wear_mm, 'Z', axis_value(Axis::Z, *z));
    if (const Word* r = words_.word('R')) (geometry ? tool.radius_mm : tool.radius_wear_mm) = offset_value(*r);
    if (const Word* q = words_.word('Q')) tool.orientation = static_cast<int>(q->value);
}

std::optional<MacroValue> Executor::read_lathe_offset_variable(std::int64_t n) const {
    const std::int64_t page = (n - first_tool_variable) / offsets_per_page;
    const int number = static_cast<int>((n - first_tool_variable) % offsets_per_page + 1);
    const LatheColumn column = column_of_page(page);
    if (column == LatheColumn::none || number > max_lathe_offset) return std::nullopt;
    const ToolEntry* tool = tools_.find(number);
    if (tool == nullptr) return MacroValue::of(0);  // an offset never set reads 0, as on a control
    double mm = 0;
    switch (column) {
        case LatheColumn::x_wear:
            mm = tool->x_wear_mm;
            break;
        case LatheColumn::z_wear:
            mm = tool->length_wear_mm;
            break;
        case LatheColumn::radius_wear:
            mm = tool->radius_wear_mm;
            break;
        case LatheColumn::tip:
            return MacroValue::of(tool->orientation);
        case LatheColumn::x_geometry:
            mm = tool->x_offset_mm;
            break;
        case LatheColumn::z_geometry:
            mm = tool->length_mm;
            break;
        case LatheColumn::radius_geometry:
            mm = tool->radius_mm;
            break;
        case LatheColumn::none:
            break;
    }
    return MacroValue::of(is_x(column) ? to_program_units(Axis::X, mm) : mm / modal_.length_factor_mm);
}

std::optional<SystemVariables::WriteError> Executor::write_lathe_offset_variable(std::int64_t n, double value) {
    const std::int64_t page = (n - first_tool_variable) / offsets_per_page;
    const int number = static_cast<int>((n - first_tool_variable) % offsets_per_page + 1);
    const LatheColumn column = column_of_page(page);
    if (column == LatheColumn::none || number > max_lathe_offset) {
        return SystemVariables::WriteError{alarm::illegal_variable, fmt::format("#{} is no tool offset of a 0i-T", n)};
    }
    if (column == LatheColumn::tip && (value < 0 || value > 9 || value != std::floor(value))) {
        return SystemVariables::WriteError{alarm::argument_range,
                                           fmt::format("#{} = {}: a tip orientation is 0 to 9", n, value)};
    }
    ToolEntry& tool = tools_.entry(number);
    const double mm = is_x(column) ? from_program_units(Axis::X, value) : value * modal_.length_factor_mm;
    switch (column) {
        case LatheColumn::x_wear:
            tool.x_wear_mm = mm;
            break;
        case LatheColumn::z_wear:
            tool.length_wear_mm = mm;
            break;
        case LatheColumn::radius_wear:
            tool.radius_wear_mm = mm;
            break;
        case LatheColumn::tip:
            tool.orientation = static_cast<int>(value);
            break;
        case LatheColumn::x_geometry:
            tool.x_offset_mm = mm;
            break;
        case LatheColumn::z_geometry:
            tool.length_mm = mm;
            break;
        case LatheColumn::radius_geometry:
            tool.radius_mm = mm;
            break;
        case LatheColumn::none:
            break;
    }
    return std::nullopt;
}

}  // namespace nckit::interp
