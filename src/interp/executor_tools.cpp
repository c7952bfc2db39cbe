// Tools: T selects, M6 changes (through the machine's tool-change position), G43/G44 H and
// G43.1 apply a length offset along Z, G49 cancels it, G10 L1/L10-L13 write the table during the
// run, and #2001-#2800 read and write it (Fanuc's offset memory C layout for up to 200 offsets).
#include <cmath>

#include <fmt/format.h>

#include "executor.hpp"
#include "nckit/gcode/macro_alarms.hpp"

namespace nckit::interp {

namespace {
// Fanuc's offset memory C with up to 200 offsets: four pages of 200 variables each.
constexpr std::int64_t tool_variables_first = first_tool_variable;
constexpr std::int64_t tool_variables_per_page = 200;
constexpr std::int64_t tool_variables_last = last_tool_variable;
enum class ToolColumn { length_wear, length, radius_wear, radius };

double& tool_field(ToolEntry& tool, ToolColumn column) {
    switch (column) {
        case ToolColumn::length_wear:
            return tool.length_wear_mm;
        case ToolColumn::length:
            return tool.length_mm;
        case ToolColumn::radius_wear:
            return tool.radius_wear_mm;
        case ToolColumn::radius:
            return tool.radius_mm;
    }
    return tool.length_mm;
}

bool is_whole_number(double value) {
    return value == std::floor(value);
}
}  // namespace

AxisVector Executor::program_offset() const {
    return offsets_.total(modal_.work_system) + modal_.tool_offset;
}

std::optional<Diagnostic> Executor::number_word(char letter, int& out) const {
    const Word* word = words_.word(letter);
    if (word == nullptr) return std::nullopt;
    if (word->value < 0 || word->value > max_tool_number || !is_whole_number(word->value)) {
        return error(word->column, "bad-value",
                     fmt::format("{} must be a whole number from 0 to {}", letter, max_tool_number));
    }
    out = static_cast<int>(word->value);
    return std::nullopt;
}

std::optional<Diagnostic> Executor::set_tool_length() {
    GCode mode = words_.group(ModalGroup::length_comp);
    ToolState& tool = modal_.tool;
    int h = -1;
    if (auto e = number_word('H', h)) return e;
    // G41.1/G42.1 D is a diameter, not an offset number.
    if (const Word* d = words_.word('D');
        d != nullptr && words_.group(ModalGroup::spindle_mode) != g(96) && lathe_cycle_of_block() < 0 &&
        words_.group(ModalGroup::cutter_comp) != g(41, 1) && words_.group(ModalGroup::cutter_comp) != g(42, 1)) {
        int number = 0;
        if (auto e = number_word('D', number)) return e;
        tool.d_number = number;
    }
    if (mode < 0) {
        // An H word under G43/G44 switches to that offset; alone it only sets the modal H.
        if (h < 0) return std::nullopt;
        if (tool.length_mode != g(43) && tool.length_mode != g(44)) {
            tool.h_number = h;
            return std::nullopt;
        }
        mode = tool.length_mode;
    }
    const std::uint32_t column = words_.group_column(ModalGroup::length_comp) != 0
                                     ? words_.group_column(ModalGroup::length_comp)
                                     : column_of('H');
    if (mode == g(49)) {
        modal_.tool_offset = AxisVector{};
        tool.length_mode = mode;
        if (h >= 0) tool.h_number = h;
        return std::nullopt;
    }
    if (!configured_.contains(Axis::Z)) {
        return error(column, "no-tool-axis", "tool length offsets need a Z axis");
    }
    if (mode == g(43, 1)) {
        // LinuxCNC's dynamic offset: the Z word is the length itself, not a move.
        const Word* z = words_.word('Z');
        if (z == nullptr) return error(column, "missing-word", "G43.1 needs Z (the tool length)");
        modal_.tool_offset = AxisVector{};
        modal_.tool_offset[Axis::Z] = axis_value(Axis::Z, *z);
        tool.length_mode = mode;
        return std::nullopt;
    }
    // G43 without H: the modal H, or (as LinuxCNC) the tool in the spindle.
    int number = h >= 0 ? h : tool.h_number != 0 ? tool.h_number : tool.in_spindle;
    std::optional<double> length = tools_.length_mm(number);
    if (!length) {
        return error(h >= 0 ? column_of('H') : column, "no-tool-offset",
                     tools_.empty() ? fmt::format("H{} needs a tool table (--tools FILE or tools = \"FILE\")", number)
                                    : fmt::format("H{} has no entry in the tool table", number));
    }
    modal_.tool_offset = AxisVector{};
    modal_.tool_offset[Axis::Z] = mode == g(44) ? -*length : *length;
    tool.h_number = number;
    tool.length_mode = mode;
    return std::nullopt;
}

std::optional<Diagnostic> Executor::change_tool(std::vector<Move>& out) {
    // To the tool-change position at rapid: Z first (clear of the part), then the other axes.
    AxisVector target = position_;
    bool z_moves = false;
    bool others_move = false;
    for (const AxisConfig& axis : machine_.axes) {
        if (!axis.tool_change) continue;
        (axis.axis == Axis::Z ? z_moves : others_move) = true;
    }
    if (z_moves) {
        target[Axis::Z] = *machine_.find(Axis::Z)->tool_change;
        if (auto e = straight(g(0), target, out)) return e;
    }
    if (others_move) {
        for (const AxisConfig& axis : machine_.axes) {
            if (axis.tool_change) target[axis.axis] = *axis.tool_change;
        }
        if (auto e = straight(g(0), target, out)) return e;
    }
    modal_.tool.in_spindle = modal_.tool.selected;
    // LinuxCNC takes the position back from the machine after a tool change: after G40, the
    // tool stands beside the contour, and the next move starts there, not on the contour.
    if (machine_.dialect == Dialect::linuxcnc) {
        if (auto at = comp_.take_exit_position()) set_position(*at);
    }
    return std::nullopt;
}

std::optional<Diagnostic> Executor::check_tool_table_write() const {
    const Word* l = words_.word('L');
    const Word* p = words_.word('P');
    const int kind = static_cast<int>(l->value);
    if (p == nullptr || p->value < 1 || p->value > max_tool_number || !is_whole_number(p->value)) {
        return error(p ? p->column : column_of('L'), "bad-g10",
                     fmt::format("G10 L{} needs P, the offset number (1 to {})", kind, max_tool_number));
    }
    const bool linuxcnc_form = kind == 1 && (words_.has('Z') || words_.has('X'));
    if (!linuxcnc_form && !words_.has('R')) {
        return error(column_of('L'), "missing-word", fmt::format("G10 L{} needs R, the offset value", kind));
    }
    for (const AxisConfig& axis : machine_.axes) {
        char c = letter(axis.axis);
        if (words_.has(c) && !(linuxcnc_form && (c == 'Z' || c == 'X'))) {
            return error(column_of(c), "unused-word", fmt::format("G10 L{} takes no {} word", kind, c));
        }
    }
    return std::nullopt;
}

void Executor::write_tool_table() {
    const int kind = static_cast<int>(words_.word('L')->value);
    ToolEntry& tool = tools_.entry(static_cast<int>(words_.word('P')->value));
    auto length = [&](const Word& w) { return offset_value(w); };
    auto set = [&](double& field, double value) { field = modal_.incremental ? field + value : value; };
    if (kind == 1 && (words_.has('Z') || words_.has('X'))) {
        // LinuxCNC's form: Z length, X (lathe) offset, R radius.
        if (const Word* z = words_.word('Z')) set(tool.length_mm, length(*z));
        if (const Word* x = words_.word('X')) set(tool.x_offset_mm, axis_value(Axis::X, *x));
        if (const Word* r = words_.word('R')) set(tool.radius_mm, length(*r));
        return;
    }
    const double value = length(*words_.word('R'));
    switch (kind) {
        case 1:
        case 10:
            set(tool.length_mm, value);
            break;  // L1: Fanuc memory A, one value
        case 11:
            set(tool.length_wear_mm, value);
            break;
        case 12:
            set(tool.radius_mm, value);
            break;
        case 13:
            set(tool.radius_wear_mm, value);
            break;
        default:
            break;
    }
}

std::optional<MacroValue> Executor::read_tool_variable(std::int64_t n) const {
    if (machine_.gcode_system != GCodeSystem::none) return read_lathe_offset_variable(n);
    if (n < tool_variables_first || n > tool_variables_last) return std::nullopt;
    const std::int64_t page = (n - tool_variables_first) / tool_variables_per_page;
    if (page > 3) return std::nullopt;
    const int number = static_cast<int>((n - tool_variables_first) % tool_variables_per_page + 1);
    const ToolEntry* tool = tools_.find(number);
    if (tool == nullptr) return MacroValue::of(0);  // an offset never set reads 0, as on a control
    ToolEntry copy = *tool;
    return MacroValue::of(tool_field(copy, static_cast<ToolColumn>(page)) / modal_.length_factor_mm);
}

std::optional<SystemVariables::WriteError> Executor::write_tool_variable(std::int64_t n, double value) {
    if (machine_.gcode_system != GCodeSystem::none) return write_lathe_offset_variable(n, value);
    const std::int64_t page = (n - tool_variables_first) / tool_variables_per_page;
    if (page > 3) {
        return SystemVariables::WriteError{alarm::illegal_variable,
                                           fmt::format("#{} is beyond the 200 offsets of #2001-#2800", n)};
    }
    const int number = static_cast<int>((n - tool_variables_first) % tool_variables_per_page + 1);
    tool_field(tools_.entry(number), static_cast<ToolColumn>(page)) = value * modal_.length_factor_mm;
    return std::nullopt;
}

}  // namespace nckit::interp
