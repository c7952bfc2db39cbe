// nckit check FILE: run the whole program through the interpreter, print only diagnostics.
#include <cstdio>
#include <variant>

#include "common.hpp"
#include "verbs.hpp"

namespace nckit::cli {

namespace {
struct CheckOptions {
    std::string program;
    MachineOptions machine;
    int max_errors = 20;
};

int run_check(CheckOptions& options) {
    options.machine.keep_going = true;
    auto interpreter = open_program_or_report(options.program, options.machine, false);
    if (!interpreter) return exit_bad_input;
    ProgramProgress progress("check", options.program, options.machine.quiet);
    int errors = 0;
    std::uint32_t last_line = 0;
    for (;;) {
        InterpResult result = interpreter->next();
        if (std::holds_alternative<ProgramEnd>(result)) break;
        if (const auto* diagnostic = std::get_if<Diagnostic>(&result)) {
            // A stopping error repeats itself; a block's error comes once and the run goes on.
            if (errors > 0 && diagnostic->location.line == last_line) break;
            progress.finish();
            print_diagnostic(*diagnostic);
            last_line = diagnostic->location.line;
            if (++errors >= options.max_errors) {
                std::fprintf(stderr, "%s: stopped after %d errors (--max-errors)\n", options.program.c_str(), errors);
                break;
            }
            continue;
        }
        progress.update(*interpreter);
    }
    progress.finish();
    return errors == 0 ? 0 : exit_bad_input;
}
}  // namespace

void add_check_verb(CLI::App& app, int& exit_status) {
    auto options = std::make_shared<CheckOptions>();
    CLI::App* verb =
        app.add_subcommand("check", "Check a program: print every error (up to --max-errors), exit 0 when clean");
    verb->add_option("FILE", options->program, "NC program ('-': standard input)")->required();
    add_machine_options(*verb, options->machine);
    verb->add_option("--max-errors", options->max_errors, "stop after this many errors (1-10000, default 20)")
        ->check(CLI::Range(1, 10000));
    verb->callback([options, &exit_status] { exit_status = run_check(*options); });
}

}  // namespace nckit::cli
