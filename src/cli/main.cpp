// nckit: the command line. Each verb lives in its own cmd_*.cpp; this file only dispatches.
#include <CLI/CLI.hpp>

#include <cstdio>

#include "common.hpp"
#include "verbs.hpp"

int main(int argc, char** argv) {
    CLI::App app{"nckit: CNC motion kernel and toolkit"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "nckit 0.1.0");
    int exit_status = 0;
    nckit::cli::add_moves_verb(app, exit_status);
    nckit::cli::add_check_verb(app, exit_status);
    nckit::cli::add_expand_verb(app, exit_status);
    nckit::cli::add_restart_verb(app, exit_status);
    nckit::cli::add_plan_verb(app, exit_status);
    nckit::cli::add_steps_verb(app, exit_status);
    nckit::cli::add_servo_verb(app, exit_status);
    nckit::cli::add_notch_verb(app, exit_status);
    nckit::cli::add_crosshatch_verb(app, exit_status);
    nckit::cli::add_eccentric_verb(app, exit_status);
    nckit::cli::add_piston_verb(app, exit_status);
    nckit::cli::add_pattern_verb(app, exit_status);
    nckit::cli::add_report_verb(app, exit_status);
    if (argc > 1 && argv[1][0] != '-') {
        if (auto hint = nckit::cli::unknown_verb_hint(app, argv[1])) {
            std::fprintf(stderr, "%s\n", hint->c_str());
            return nckit::cli::exit_bad_input;
        }
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        int status = app.exit(e);
        // Help and version are successes; a wrong command line is bad input like a bad program.
        return status == 0 ? 0 : nckit::cli::exit_bad_input;
    }
    return exit_status;
}
