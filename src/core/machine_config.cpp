#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>
#include <cstdint>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "nckit/core/machine.hpp"
#include "nckit/core/toml_file.hpp"
#include "nckit/core/toml_table_reader.hpp"
#include "machine_axes.hpp"
#include "machine_probe_inputs.hpp"

namespace nckit {

namespace {

using core_detail::ConfigSink;
using core_detail::Need;
using core_detail::Sign;
using core_detail::TableReader;

//! A list of M-code numbers such as `exact_stop_mcodes = [24, 25]`; absent means empty.
void read_mcode_list(TableReader& reader, std::string_view key, std::vector<int>& out, ConfigSink& sink) {
    const toml::array* codes = reader.array(key, Need::optional);
    if (codes == nullptr) return;
    const std::string what = fmt::format("each entry of '{}'", key);
    for (const toml::node& code : *codes) {
        const std::optional<int> value = core_detail::to_int(code, what, Sign::non_negative, sink);
        if (value) out.push_back(*value);
    }
}

//! `tools = "FILE"`: a tool file named relative to the machine file. Its own errors keep its own
//! FILE:LINE:COL; one that cannot be read points at the key.
void read_tools(TableReader& reader, MachineConfig& config, ConfigSink& sink) {
    std::optional<std::string> name = reader.text("tools", Need::optional);
    if (!name) return;
    if (name->empty()) {
        sink.error(reader.region_of("tools"), "config-value", "'tools' must name a tool file");
        return;
    }
    std::filesystem::path path(*name);
    if (path.is_relative() && sink.file) path = std::filesystem::path(*sink.file).parent_path() / path;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
        sink.error(reader.region_of("tools"), "config-io", fmt::format("tool file '{}' cannot be read", path.string()));
        return;
    }
    Result<ToolTable> tools = load_tool_table(path);
    if (!tools) {
        for (const Diagnostic& d : tools.diagnostics()) sink.diagnostics.push_back(d);
        return;
    }
    config.tools = std::move(tools).value();
    config.tools_file = path.string();
}

//! `subroutine_path = ["DIR", ...]`: folders named relative to the machine file.
void read_subroutine_path(TableReader& reader, MachineConfig& config, ConfigSink& sink) {
    const toml::array* dirs = reader.array("subroutine_path", Need::optional);
    if (dirs == nullptr) return;
    for (const toml::node& dir : *dirs) {
        const auto* text = dir.as_string();
        if (text == nullptr || text->get().empty()) {
            sink.error(dir.source(), "config-value", "each entry of 'subroutine_path' must be a folder name");
            continue;
        }
        std::filesystem::path path(text->get());
        if (path.is_relative() && sink.file) path = std::filesystem::path(*sink.file).parent_path() / path;
        config.subroutine_path.push_back(path);
    }
}

void read_machine(const toml::table& table, MachineConfig& config, ConfigSink& sink) {
    TableReader reader(table, "[machine]", sink);
    if (std::optional<std::string> name = reader.text("name", Need::required)) {
        // Reports and plots title themselves with it; an empty title is a config slip.
        if (name->empty()) {
            sink.error(reader.region_of("name"), "config-value", "'name' must not be empty");
        }
        config.name = std::move(*name);
    }
    // Optional: 1 ms is the servo period nearly every controller (LinuxCNC included) runs.
    reader.number_into("servo_period_s", Need::optional, Sign::positive, config.servo_period_s);
    if (reader.has("servo_period_s") && config.servo_period_s > 0 &&
        !(config.servo_period_s >= 1e-6 && config.servo_period_s <= 1.0)) {
        sink.error(reader.region_of("servo_period_s"), "config-value",
                   fmt::format("'servo_period_s' = {} is implausible: it must lie between 1e-06 and 1 s",
                               config.servo_period_s));
    }
    if (std::optional<bool> diameter = reader.flag("diameter_mode", Need::optional)) {
        config.diameter_mode = *diameter;
    }
    read_mcode_list(reader, "exact_stop_mcodes", config.exact_stop_mcodes, sink);
    read_tools(reader, config, sink);
    read_mcode_list(reader, "laser_on_mcodes", config.laser_on_mcodes, sink);
    read_mcode_list(reader, "laser_off_mcodes", config.laser_off_mcodes, sink);
    for (int code : config.laser_off_mcodes) {
        if (config.is_laser_on_mcode(code)) {
            sink.error(reader.region_of("laser_off_mcodes"), "config-value",
                       fmt::format("M{} is in both 'laser_on_mcodes' and 'laser_off_mcodes'", code));
            break;
        }
    }

    // Each list of names sits beside the enum values it maps to, in the same order.
    constexpr std::array decimal_point_modes{DecimalPointInput::calculator, DecimalPointInput::least_increment};
    if (auto i = reader.choice("decimal_point_input", Need::optional, "decimal_point_input",
                               {"calculator", "least_increment"})) {
        config.decimal_point_input = decimal_point_modes[*i];
    }
    constexpr std::array startups{CompStartup::type_b, CompStartup::type_a};
    if (auto i = reader.choice("cutter_comp_startup", Need::optional, "cutter_comp_startup", {"type_b", "type_a"})) {
        config.cutter_comp_startup = startups[*i];
    }
    constexpr std::array systems{GCodeSystem::a, GCodeSystem::b, GCodeSystem::c};
    if (auto i = reader.choice("gcode_system", Need::optional, "gcode_system", {"A", "B", "C"})) {
        config.gcode_system = systems[*i];
    }
    constexpr std::array controls{LatheControl::fanuc, LatheControl::haas};
    if (auto i = reader.choice("lathe_control", Need::optional, "lathe_control", {"fanuc", "haas"})) {
        config.lathe_control = controls[*i];
    }
    if (std::optional<std::string> codes = reader.text("startup_gcodes", Need::optional)) {
        // Only G words: the interpreter reads them as a block before the program and reports a
        // code it does not know at this key's place.
        config.startup_gcodes = *codes;
        config.startup_gcodes_at = sink.at(reader.region_of("startup_gcodes"));
    }
    constexpr std::array dialects{Dialect::fanuc, Dialect::linuxcnc};
    if (auto i = reader.choice("dialect", Need::optional, "dialect", {"fanuc", "linuxcnc"})) {
        config.dialect = dialects[*i];
    }
    read_subroutine_path(reader, config, sink);
    // nckit restart: where the tool retracts to before it comes back to the restart point.
    if (std::optional<double> safe = reader.number("restart_safe_mm", Need::optional)) config.restart_safe_mm = *safe;
    reader.number_into("restart_feed_mm_min", Need::optional, Sign::positive, config.restart_feed_mm_min);
    constexpr std::array profiles{ProfileKind::scurve, ProfileKind::trapezoid};
    if (auto i = reader.choice("profile", Need::optional, "profile", {"scurve", "trapezoid"})) {
        config.profile = profiles[*i];
    }
    reader.reject_unknown_keys();
}

void read_spindle(const toml::table& table, MachineConfig& config, ConfigSink& sink) {
    TableReader reader(table, "[spindle]", sink);
    reader.number_into("max_rpm", Need::optional, Sign::positive, config.spindle.max_rpm);
    if (auto counts = reader.integer("encoder_counts", Need::optional, Sign::positive)) {
        config.spindle.encoder_counts = *counts;
    }
    reader.number_into("ripple_fraction", Need::optional, Sign::non_negative, config.spindle.ripple_fraction);
    if (config.spindle.ripple_fraction >= 0.5) {
        sink.error(reader.region_of("ripple_fraction"), "config-value",
                   fmt::format("'ripple_fraction' must be below 0.5 (a speed swinging by half stalls the cut), not {}",
                               config.spindle.ripple_fraction));
    }
    if (auto harmonic = reader.integer("ripple_per_turn", Need::optional, Sign::positive)) {
        config.spindle.ripple_per_turn = *harmonic;
    }
    reader.number_into("ripple_phase_deg", Need::optional, Sign::any, config.spindle.ripple_phase_deg);
    reader.reject_unknown_keys();
}

MachineConfig read_document(const toml::table& document, ConfigSink& sink) {
    MachineConfig config;
    // An omitted [spindle] (or key in it) means the built-in mill's spindle.
    config.spindle = default_mill().spindle;
    TableReader root(document, "", sink);
    if (const toml::table* machine = root.table("machine", Need::optional)) {
        read_machine(*machine, config, sink);
    } else if (!root.has("machine")) {
        sink.error(root.region(), "config-missing-key", "missing table [machine]");
    }
    core_detail::read_axes(root, config, sink);
    const toml::table* machine_table = document["machine"].as_table();
    const toml::node* system = machine_table != nullptr ? machine_table->get("gcode_system") : nullptr;
    const bool lathe =
        config.find(Axis::X) != nullptr && config.find(Axis::Z) != nullptr && config.find(Axis::Y) == nullptr;
    if (system != nullptr && config.gcode_system != GCodeSystem::none && !lathe) {
        // Fanuc's systems A, B and C are a lathe's (X and Z, no Y): a mill has one set of codes.
        sink.error(system->source(), "config-value", "'gcode_system' is for lathes (X and Z axes, no Y)");
    }
    const toml::node* control = machine_table != nullptr ? machine_table->get("lathe_control") : nullptr;
    if (control != nullptr && config.lathe_control == LatheControl::haas && config.gcode_system != GCodeSystem::a) {
        // A Haas lathe writes G98/G99 feeds, U W increments and G90/G92/G94 single cycles: the
        // codes of Fanuc's system A, which the Haas-only readings refine.
        sink.error(control->source(), "config-value", "'lathe_control = \"haas\"' needs 'gcode_system = \"A\"'");
    }
    if (const toml::table* spindle = root.table("spindle", Need::optional)) {
        read_spindle(*spindle, config, sink);
    }
    core_detail::read_probe_and_inputs(root, config, sink);
    root.reject_unknown_keys();
    return config;
}

//! The document's config, or every problem found in it, sorted top to bottom.
Result<MachineConfig> read_file(Result<core_detail::TomlFile> file) {
    if (!file) return file.diagnostics();
    ConfigSink sink{file->name, {}};
    MachineConfig config = read_document(file->document, sink);
    if (sink.diagnostics.empty()) return config;
    core_detail::sort_by_position(sink.diagnostics);
    return std::move(sink.diagnostics);
}

}  // namespace

const AxisConfig* MachineConfig::find(Axis axis) const {
    const auto hit = std::find_if(axes.begin(), axes.end(), [axis](const AxisConfig& a) { return a.axis == axis; });
    return hit != axes.end() ? &*hit : nullptr;
}

AxisSet MachineConfig::axis_set() const {
    AxisSet set;
    for (const AxisConfig& a : axes) set.insert(a.axis);
    return set;
}

bool MachineConfig::is_laser_on_mcode(int code) const {
    return std::find(laser_on_mcodes.begin(), laser_on_mcodes.end(), code) != laser_on_mcodes.end();
}

bool MachineConfig::is_laser_off_mcode(int code) const {
    return std::find(laser_off_mcodes.begin(), laser_off_mcodes.end(), code) != laser_off_mcodes.end();
}

bool MachineConfig::is_exact_stop_mcode(int code) const {
    return std::find(exact_stop_mcodes.begin(), exact_stop_mcodes.end(), code) != exact_stop_mcodes.end();
}

Result<MachineConfig> parse_machine_config(std::string_view toml_text, const std::string& file_name) {
    return read_file(core_detail::parse_toml_text(toml_text, file_name));
}

Result<MachineConfig> load_machine_config(const std::filesystem::path& path) {
    return read_file(core_detail::load_toml_file(path, "machine config"));
}

}  // namespace nckit
