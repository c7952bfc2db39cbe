#pragma once
// A lathe in Fanuc G-code system A with travel wide enough for the manual's examples.
#include <string>
#include <string_view>

#include <gtest/gtest.h>

#include "nckit/core/machine.hpp"

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

}  // namespace nckit::test
