#pragma once
// A lathe in Fanuc G-code system A with travel wide enough for the manual's examples.
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "nckit/core/machine.hpp"
#include "nckit/interp/move.hpp"

namespace nckit::test {

inline MachineConfig lathe_machine(std::string_view machine_keys, double travel_mm = 200) {
    const std::string limits = "min = -" + std::to_string(travel_mm) + "\nmax = " + std::to_string(travel_mm) + "\n";
    std::string text =
        "[machine]\nname = \"t\"\ndiameter_mode = true\n" + std::string(machine_keys) +
        "\n[[axis]]\nname = \"X\"\nkind = \"linear\"\nmax_velocity = 100\nmax_acceleration = 500\nmax_jerk = 50000\n" +
        limits + "steps_per_unit = 800\n" +
        "[[axis]]\nname = \"Z\"\nkind = \"linear\"\nmax_velocity = 100\nmax_acceleration = 500\nmax_jerk = 50000\n" +
        limits + "steps_per_unit = 800\n[spindle]\nmax_rpm = 4000\n";
    auto config = parse_machine_config(text, "lathe.toml");
    if (!config) {
        ADD_FAILURE() << format_diagnostic(config.diagnostics().front());
        return default_mill();
    }
    return *config;
}

inline MachineConfig system_a_lathe(double travel_mm = 200) {
    return lathe_machine("gcode_system = \"A\"\nstartup_gcodes = \"G18 G21 G40 G97 G99\"", travel_mm);
}

//! A point of a lathe tool path: radius, Z, and whether the move that ends there is a rapid.
struct LathePoint {
    double x_radius;
    double z;
    bool rapid;
};

//! The Lines of a run as (radius, Z, rapid), in order; Arcs as their end with rapid = false.
inline std::vector<LathePoint> lathe_path_of(const std::vector<Move>& moves) {
    std::vector<LathePoint> out;
    for (const Move& m : moves) {
        if (const auto* l = std::get_if<Line>(&m.what)) out.push_back({l->to[Axis::X], l->to[Axis::Z], l->rapid});
        if (const auto* a = std::get_if<Arc>(&m.what)) out.push_back({a->to[Axis::X], a->to[Axis::Z], false});
    }
    return out;
}

}  // namespace nckit::test
