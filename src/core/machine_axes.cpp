#include "machine_axes.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string_view>

#include <fmt/format.h>
#include <toml++/toml.h>

namespace nckit::core_detail {

namespace {

//! One [[axis]] as read: the config, plus what the cross-axis checks need even when the
//! table had errors of its own (a duplicate is worth reporting alongside a bad limit).
struct AxisEntry {
    AxisConfig config;
    bool named = false;  //!< `name` was a valid axis letter; config.axis holds it
    bool valid = false;  //!< the table produced no diagnostics
    toml::source_region name_region;
};

// Limits end up as divisors (time = distance / velocity, steps = mm * steps_per_unit), so zero
// is an error here rather than a silent "unlimited" or a division by zero in the planner.
void read_limits(TableReader& reader, AxisConfig& axis, ConfigSink& sink) {
    reader.number_into("max_velocity", Need::required, Sign::positive, axis.max_velocity);
    reader.number_into("max_acceleration", Need::required, Sign::positive, axis.max_acceleration);
    reader.number_into("max_jerk", Need::required, Sign::positive, axis.max_jerk);
    reader.number_into("steps_per_unit", Need::required, Sign::positive, axis.steps_per_unit);
    reader.number_into("backlash", Need::optional, Sign::non_negative, axis.backlash);
    reader.number_into("backlash_rate_steps_s", Need::optional, Sign::positive, axis.backlash_rate_steps_s);
    // Positive is not enough: max_velocity = 1e-308 makes a cycle time of inf s. The bounds are
    // far outside any machine (1 µm/s to 1 km/s, ...) and keep every figure finite.
    struct Bound {
        std::string_view key;
        double value;
        double low;
        double high;
    };
    for (const Bound& b :
         {Bound{"max_velocity", axis.max_velocity, 1e-3, 1e6},
          Bound{"max_acceleration", axis.max_acceleration, 1e-3, 1e9}, Bound{"max_jerk", axis.max_jerk, 1e-3, 1e12},
          Bound{"steps_per_unit", axis.steps_per_unit, 1e-3, 1e9}, Bound{"backlash", axis.backlash, 0.0, 1e3},
          Bound{"backlash_rate_steps_s", axis.backlash_rate_steps_s, 1e-3, 1e9}}) {
        if (!reader.has(b.key) || (b.value >= b.low && b.value <= b.high) || !(b.value > 0 || b.low == 0)) continue;
        sink.error(
            reader.region_of(b.key), "config-value",
            fmt::format("'{}' = {} is implausible: it must lie between {} and {}", b.key, b.value, b.low, b.high));
    }
}

void read_travel(TableReader& reader, AxisConfig& axis, ConfigSink& sink) {
    const bool have_min = reader.number_into("min", Need::required, Sign::any, axis.min);
    const bool have_max = reader.number_into("max", Need::required, Sign::any, axis.max);
    const bool have_home = reader.number_into("home", Need::optional, Sign::any, axis.home);
    if (auto change = reader.number("tool_change", Need::optional)) {
        if (*change < axis.min || *change > axis.max) {
            sink.error(
                reader.region_of("tool_change"), "config-value",
                fmt::format("'tool_change' ({}) must lie within min..max ({}..{})", *change, axis.min, axis.max));
        }
        axis.tool_change = *change;
    }
    if (!have_min || !have_max) return;
    constexpr double max_travel = 1e6;  // mm (deg): a kilometre of travel is no machine's
    for (const char* key : {"min", "max"}) {
        const double value = std::string_view(key) == "min" ? axis.min : axis.max;
        if (std::abs(value) > max_travel) {
            sink.error(reader.region_of(key), "config-value",
                       fmt::format("'{}' = {} is implausible: travel must lie within +-{}", key, value, max_travel));
            return;
        }
    }
    if (axis.min >= axis.max) {
        sink.error(reader.region_of("max"), "config-value",
                   fmt::format("'max' ({}) must be greater than 'min' ({})", axis.max, axis.min));
        return;
    }
    if (axis.home >= axis.min && axis.home <= axis.max) return;
    if (have_home) {
        sink.error(reader.region_of("home"), "config-value",
                   fmt::format("'home' ({}) must lie within min..max ({}..{})", axis.home, axis.min, axis.max));
    } else if (!reader.has("home")) {
        // G28 would drive to the default 0 beyond the travel; make the user choose a home.
        sink.error(
            reader.region(), "config-value",
            fmt::format("'home' defaults to 0, which lies outside min..max ({}..{}): set it", axis.min, axis.max));
    }
}

//! The winding bits a phase table drives (winding A the highest): what port_set_bits must leave
//! clear. Spelt here because core cannot ask the drive stage.
std::uint8_t winding_mask(PhaseTableKind kind) {
    switch (kind) {
        case PhaseTableKind::none:
            return 0;
        case PhaseTableKind::three_phase_six_beat:
        case PhaseTableKind::three_phase_three_beat:
            return 0x07;
        case PhaseTableKind::two_phase_full_step:
        case PhaseTableKind::two_phase_half_step:
            return 0x0F;
    }
    return 0;
}

//! How the phase table's pattern becomes the port byte; only meaningful beside a phase_table.
void read_port(TableReader& reader, AxisConfig& axis, ConfigSink& sink) {
    for (std::string_view key : {"port_active_low", "port_set_bits"}) {
        if (reader.has(key) && axis.phase_table == PhaseTableKind::none) {
            sink.error(reader.region_of(key), "config-value",
                       fmt::format("'{}' encodes a phase table's port: set 'phase_table' too", key));
        }
    }
    if (std::optional<bool> low = reader.flag("port_active_low", Need::optional)) axis.port_active_low = *low;
    const std::optional<int> bits = reader.integer("port_set_bits", Need::optional, Sign::non_negative);
    if (!bits) return;
    if (*bits > 0xFF) {
        sink.error(reader.region_of("port_set_bits"), "config-value",
                   fmt::format("'port_set_bits' must fit the 8-bit port (0 to 255), not {}", *bits));
        return;
    }
    const std::uint8_t mask = winding_mask(axis.phase_table);
    if ((*bits & mask) != 0) {
        // A bit held high on a winding line would energise (or, active low, free) that winding.
        sink.error(reader.region_of("port_set_bits"), "config-value",
                   fmt::format("'port_set_bits' (0x{:02X}) overlaps the winding bits 0x{:02X} of phase table '{}'",
                               *bits, mask, phase_table_names[static_cast<std::size_t>(axis.phase_table)]));
        return;
    }
    axis.port_set_bits = static_cast<std::uint8_t>(*bits);
}

//! [axis.servo]: the axis is a servo whose position loop is the second-order model.
void read_servo(TableReader& axis_reader, AxisConfig& axis, ConfigSink& sink) {
    const toml::node* node = axis_reader.node("servo", Need::optional);
    if (node == nullptr) return;
    const toml::table* table = node->as_table();
    if (table == nullptr) {
        sink.error(
            node->source(), "config-type",
            fmt::format("'servo' must be a table ([axis.servo] after its [[axis]]), not {}", type_name(node->type())));
        return;
    }
    TableReader reader(*table, "[axis.servo]", sink);
    AxisServoConfig servo;
    const bool have_frequency =
        reader.number_into("natural_frequency_hz", Need::required, Sign::positive, servo.natural_frequency_hz);
    const bool have_damping = reader.number_into("damping", Need::required, Sign::non_negative, servo.damping);
    // A gain of 0 would make an axis that never moves; a negative one one that runs away.
    const bool gain_ok = !reader.has("gain") || reader.number_into("gain", Need::optional, Sign::positive, servo.gain);
    reader.reject_unknown_keys();
    if (have_frequency && have_damping && gain_ok) axis.servo = servo;
}

AxisEntry read_axis(const toml::table& table, ConfigSink& sink) {
    const std::size_t errors_before = sink.diagnostics.size();
    TableReader reader(table, "[[axis]]", sink);
    AxisEntry entry;
    static_assert(axis_letters == "XYZABCUVW", "the name choices below follow Axis's order");
    if (auto i = reader.choice("name", Need::required, "axis", {"X", "Y", "Z", "A", "B", "C", "U", "V", "W"})) {
        entry.config.axis = static_cast<Axis>(*i);
        entry.named = true;
        entry.name_region = reader.region_of("name");
    }
    constexpr std::array kinds{AxisKind::linear, AxisKind::rotary};
    if (auto i = reader.choice("kind", Need::required, "kind", {"linear", "rotary"})) {
        entry.config.kind = kinds[*i];
    }
    read_limits(reader, entry.config, sink);
    read_travel(reader, entry.config, sink);
    static_assert(phase_table_names.size() == 5, "the phase_table choices below follow the names");
    if (auto i = reader.choice("phase_table", Need::optional, "phase_table",
                               {phase_table_names[0], phase_table_names[1], phase_table_names[2], phase_table_names[3],
                                phase_table_names[4]})) {
        entry.config.phase_table = static_cast<PhaseTableKind>(*i);
    }
    read_port(reader, entry.config, sink);
    read_servo(reader, entry.config, sink);
    reader.reject_unknown_keys();
    entry.valid = sink.diagnostics.size() == errors_before;
    return entry;
}

}  // namespace

void read_axes(TableReader& root, MachineConfig& config, ConfigSink& sink) {
    const toml::node* node = root.node("axis", Need::optional);
    if (node == nullptr) {
        sink.error(root.region(), "config-no-axes", "at least one [[axis]] is required");
        return;
    }
    const toml::array* tables = node->as_array();
    if (tables == nullptr) {
        sink.error(node->source(), "config-type",
                   fmt::format("'axis' must be an array of tables ([[axis]]), not {}", type_name(node->type())));
        return;
    }
    if (tables->empty()) {
        sink.error(node->source(), "config-no-axes", "at least one [[axis]] is required");
        return;
    }
    std::array<std::optional<std::uint32_t>, axis_count> first_line{};  // where each axis was named
    for (const toml::node& element : *tables) {
        const toml::table* table = element.as_table();
        if (table == nullptr) {
            sink.error(element.source(), "config-type",
                       fmt::format("each [[axis]] must be a table, not {}", type_name(element.type())));
            continue;
        }
        AxisEntry entry = read_axis(*table, sink);
        if (entry.named) {
            std::optional<std::uint32_t>& first = first_line[index(entry.config.axis)];
            if (first) {
                sink.error(
                    entry.name_region, "config-duplicate-axis",
                    fmt::format("axis '{}' is listed twice (first at line {})", letter(entry.config.axis), *first));
            } else {
                first = entry.name_region.begin.line;
            }
        }
        if (entry.valid) config.axes.push_back(entry.config);
    }
}

}  // namespace nckit::core_detail
