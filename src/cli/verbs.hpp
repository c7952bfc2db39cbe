#pragma once
// One registration function per verb: each adds its subcommand and options to the app.
#include <CLI/CLI.hpp>

namespace nckit::cli {

void add_moves_verb(CLI::App& app, int& exit_status);
void add_check_verb(CLI::App& app, int& exit_status);
void add_expand_verb(CLI::App& app, int& exit_status);
void add_restart_verb(CLI::App& app, int& exit_status);
void add_plan_verb(CLI::App& app, int& exit_status);
void add_steps_verb(CLI::App& app, int& exit_status);
void add_servo_verb(CLI::App& app, int& exit_status);
void add_notch_verb(CLI::App& app, int& exit_status);
void add_crosshatch_verb(CLI::App& app, int& exit_status);
void add_eccentric_verb(CLI::App& app, int& exit_status);
void add_piston_verb(CLI::App& app, int& exit_status);
void add_pattern_verb(CLI::App& app, int& exit_status);
void add_report_verb(CLI::App& app, int& exit_status);

}  // namespace nckit::cli
