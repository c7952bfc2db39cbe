#include "machine_probe_inputs.hpp"

#include <charconv>
#include <string>

#include <fmt/format.h>

namespace nckit::core_detail {

namespace {

constexpr int first_input = 1000;  // Fanuc's interface signals #1000-#1199 (inputs and outputs)
constexpr int last_input = 1199;
constexpr std::size_t max_surfaces = 64;  // a bound on what a file may list

void read_surface(const toml::table& table, MachineConfig& config, ConfigSink& sink) {
    TableReader reader(table, "a probe surface", sink);
    std::optional<std::string> name = reader.text("axis", Need::required);
    std::optional<double> at = reader.number("at", Need::required);
    reader.reject_unknown_keys();
    if (!name || !at) return;
    std::optional<Axis> axis = name->size() == 1 ? axis_from_letter((*name)[0]) : std::nullopt;
    if (!axis) {
        sink.error(reader.region_of("axis"), "config-value", fmt::format("'{}' is not an axis letter", *name));
        return;
    }
    config.probe_surfaces.push_back(ProbeSurface{*axis, *at});
}

}  // namespace

void read_probe_and_inputs(TableReader& root, MachineConfig& config, ConfigSink& sink) {
    if (const toml::table* probe = root.table("probe", Need::optional)) {
        TableReader reader(*probe, "[probe]", sink);
        if (const toml::array* surfaces = reader.array("surfaces", Need::required)) {
            if (surfaces->size() > max_surfaces) {
                sink.error(reader.region_of("surfaces"), "config-value",
                           fmt::format("at most {} probe surfaces", max_surfaces));
            } else {
                for (const toml::node& node : *surfaces) {
                    if (const toml::table* table = node.as_table()) {
                        read_surface(*table, config, sink);
                    } else {
                        sink.error(node.source(), "config-type",
                                   "a probe surface is a table: { axis = \"Z\", at = -20.0 }");
                    }
                }
            }
        }
        reader.reject_unknown_keys();
    }
    if (const toml::table* inputs = root.table("inputs", Need::optional)) {
        for (const auto& [key, node] : *inputs) {
            const std::string_view name = key.str();
            int number = 0;
            auto [end, ec] = std::from_chars(name.data(), name.data() + name.size(), number);
            if (ec != std::errc{} || end != name.data() + name.size() || number < first_input || number > last_input) {
                sink.error(node.source(), "config-unknown-key",
                           fmt::format("[inputs] keys are macro variable numbers {} to {}, not '{}'", first_input,
                                       last_input, name));
                continue;
            }
            if (std::optional<double> value = to_number(node, fmt::format("#{}", number), Sign::any, sink)) {
                config.macro_inputs.push_back(MacroInput{number, *value});
            }
        }
    }
}

}  // namespace nckit::core_detail
