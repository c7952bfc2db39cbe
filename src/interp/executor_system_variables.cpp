// Macro B system variables that the machine state answers. Axis numbers follow the machine
// file's axis order (a mill X Y Z A B C = 1..6, a lathe X Z = 1, 2), values are in program
// units (inch under G20) and X is a diameter in diameter mode, as a Fanuc control shows them.
#include <cmath>

#include <fmt/format.h>

#include "executor.hpp"
#include "nckit/gcode/macro_alarms.hpp"
#include "nckit/interp/arc_geometry.hpp"
#include "nckit/interp/move_summary.hpp"

namespace nckit::interp {

namespace {
constexpr std::int64_t axes_per_block = 6;       // #5001-#5006 and the like
constexpr std::int64_t work_offset_base = 5221;  // G54 X; +20 for each further system
constexpr std::int64_t work_offset_stride = 20;
constexpr double m_per_foot = 0.3048;  // G96 S is in ft/min under G20
}  // namespace

const AxisConfig* Executor::axis_by_number(std::int64_t one_based) const {
    if (one_based < 1 || one_based > static_cast<std::int64_t>(machine_.axes.size())) return nullptr;
    return &machine_.axes[static_cast<std::size_t>(one_based - 1)];
}

double Executor::to_program_units(Axis axis, double mm) const {
    double value = axis_is_linear(axis) ? mm / modal_.length_factor_mm : mm;
    return axis == Axis::X && modal_.diameter_mode ? value * 2.0 : value;
}

double Executor::from_program_units(Axis axis, double value) const {
    double mm = axis_is_linear(axis) ? value * modal_.length_factor_mm : value;
    return axis == Axis::X && modal_.diameter_mode ? mm / 2.0 : mm;
}

std::optional<MacroValue> Executor::modal_code(int group) const {
    auto code = [](double g) { return MacroValue::of(g); };
    switch (group) {
        case 1:
            // Fanuc: a drilling cycle is group 09; group 01 keeps the code of before the cycle.
            if (machine_.dialect == Dialect::fanuc && is_drilling_cycle(modal_.motion)) {
                return code(modal_.motion_before_cycle / 10.0);
            }
            return code(modal_.motion / 10);
        case 2:
            return code(modal_.plane == Plane::xy ? 17 : modal_.plane == Plane::zx ? 18 : 19);
        case 3:
            return code(modal_.incremental ? 91 : 90);
        case 5:
            return code(modal_.feed_mode == FeedMode::per_revolution ? 95 : 94);
        case 6:
            return code(modal_.length_factor_mm != 1.0 ? 20 : 21);
        case 7:
            return code(modal_.cutter_comp == 0 ? 40 : modal_.cutter_comp);
        case 8:
            return code(modal_.tool.length_mode / 10.0);
        case 9:
            return code(is_drilling_cycle(modal_.motion) ? modal_.motion / 10 : 80);
        case 10:
            return code(modal_.cycle.return_to_initial ? 98 : 99);
        case 11:
            return code(50);
        case 13:
            return code(modal_.spindle.constant_surface_speed ? 96 : 97);
        case 14:
            return code(54 + static_cast<double>(modal_.work_system));
        case 15:
            return code(modal_.path.exact_stop ? 61 : 64);
        default:
            return MacroValue{};  // groups nckit has no codes for read vacant
    }
}

std::optional<MacroValue> Executor::read_system(std::int64_t n) const {
    if (n >= 4001 && n <= 4022) return modal_code(static_cast<int>(n - 4000));
    switch (n) {
        case 3901:
            return MacroValue::of(parts_done_);
        case 3902:
            return MacroValue::of(parts_required_);
        case 4107:
            return MacroValue::of(modal_.tool.d_number);
        case 4109:
            return MacroValue::of(modal_.feed / modal_.length_factor_mm);
        case 4111:
            return MacroValue::of(modal_.tool.h_number);
        case 4113:
            return MacroValue::of(last_mcode_);
        case 4119: {
            // S as programmed: the surface speed is kept in m/min, but a G20 program wrote ft/min.
            const SpindleState& spindle = modal_.spindle;
            if (!spindle.constant_surface_speed) return MacroValue::of(spindle.rpm);
            double speed = spindle.surface_speed_m_min;
            return MacroValue::of(inch_units() ? speed / m_per_foot : speed);
        }
        case 4120:
            return MacroValue::of(modal_.tool.selected);
        default:
            break;
    }
    if (n >= first_tool_variable && n <= last_tool_variable) return read_tool_variable(n);
    if (n >= first_macro_input && n <= last_macro_input) return read_macro_input(n);
    const AxisVector work = position_ - program_offset();
    auto axis_value = [&](std::int64_t base, const AxisVector& source) -> std::optional<MacroValue> {
        const AxisConfig* axis = axis_by_number(n - base + 1);
        if (axis == nullptr) return MacroValue{};
        return MacroValue::of(to_program_units(axis->axis, source[axis->axis]));
    };
    if (n >= 5001 && n < 5001 + axes_per_block) return axis_value(5001, work);
    if (n >= 5021 && n < 5021 + axes_per_block) return axis_value(5021, position_);
    if (n >= 5041 && n < 5041 + axes_per_block) return axis_value(5041, work);
    // The G31 skip point in the work system it was measured in (the offsets in force now).
    if (n >= 5061 && n < 5061 + axes_per_block) return axis_value(5061, skip_position_ - program_offset());
    if (n >= 5081 && n < 5081 + axes_per_block) return axis_value(5081, modal_.tool_offset);
    if (n >= work_offset_base && n < work_offset_base + 6 * work_offset_stride) {
        std::int64_t system = (n - work_offset_base) / work_offset_stride;
        std::int64_t slot = (n - work_offset_base) % work_offset_stride;
        if (slot >= axes_per_block) return std::nullopt;
        return axis_value(work_offset_base + system * work_offset_stride,
                          offsets_.work[static_cast<std::size_t>(system)]);
    }
    return std::nullopt;
}

std::optional<SystemVariables::WriteError> Executor::write_system(std::int64_t n, double value) {
    if (n == 3901) {
        parts_done_ = value;
        return std::nullopt;
    }
    if (n == 3902) {
        parts_required_ = value;
        return std::nullopt;
    }
    if (n >= first_tool_variable && n <= last_tool_variable) return write_tool_variable(n, value);
    if (n >= first_macro_output && n <= last_macro_input) {
        const auto slot = static_cast<std::size_t>(n - first_macro_output);
        macro_outputs_[slot] = value;
        macro_output_set_[slot] = true;
        return std::nullopt;
    }
    if (n >= work_offset_base && n < work_offset_base + 6 * work_offset_stride) {
        std::int64_t system = (n - work_offset_base) / work_offset_stride;
        std::int64_t slot = (n - work_offset_base) % work_offset_stride;
        const AxisConfig* axis = slot < axes_per_block ? axis_by_number(slot + 1) : nullptr;
        if (axis == nullptr) {
            return SystemVariables::WriteError{alarm::illegal_variable,
                                               fmt::format("#{} names no axis of this machine", n)};
        }
        offsets_.work[static_cast<std::size_t>(system)][axis->axis] = from_program_units(axis->axis, value);
        return std::nullopt;
    }
    if (read_system(n)) {
        return SystemVariables::WriteError{alarm::protected_variable, fmt::format("#{} is read-only", n)};
    }
    return SystemVariables::WriteError{alarm::illegal_variable, fmt::format("#{} is not a variable", n)};
}

std::optional<MacroValue> Executor::read_macro_input(std::int64_t n) const {
    // #1100-#1199 are outputs: what the program wrote reads back; otherwise the machine file's
    // [inputs] value, and 0 (signal off) for an input it does not list.
    if (n >= first_macro_output) {
        const auto slot = static_cast<std::size_t>(n - first_macro_output);
        if (macro_output_set_[slot]) return MacroValue::of(macro_outputs_[slot]);
    }
    for (const MacroInput& input : machine_.macro_inputs) {
        if (input.number == n) return MacroValue::of(input.value);
    }
    return MacroValue::of(0.0);
}

double Executor::duration_s(const Move& move) const {
    auto at_feed = [](double length_mm, const Feed& feed) {
        return feed.mm_per_min > 0 ? length_mm / feed.mm_per_min * 60.0 : 0.0;
    };
    if (const auto* line = std::get_if<Line>(&move.what)) {
        if (!line->rapid) {
            AxisVector d = line->to - line->from;
            return at_feed(std::hypot(d[Axis::X], d[Axis::Y], d[Axis::Z]), line->feed);
        }
        double slowest = 0;  // a rapid takes as long as its slowest axis at full speed
        for (const AxisConfig& axis : machine_.axes) {
            slowest = std::max(slowest, std::abs(line->to[axis.axis] - line->from[axis.axis]) / axis.max_velocity);
        }
        return slowest;
    }
    if (const auto* arc = std::get_if<Arc>(&move.what)) return at_feed(arc_length_mm(*arc), arc->feed);
    if (const auto* sync = std::get_if<SyncMove>(&move.what)) {
        AxisVector d = sync->to - sync->from;
        return at_feed(std::hypot(d[Axis::X], d[Axis::Y], d[Axis::Z]), sync->feed);
    }
    if (const auto* dwell = std::get_if<Dwell>(&move.what)) return dwell->seconds;
    return 0.0;
}

}  // namespace nckit::interp
