// nckit check FILE: run the whole program through the interpreter, print only diagnostics.
#include <variant>

#include "common.hpp"
#include "verbs.hpp"

namespace nckit::cli {

namespace {
struct CheckOptions {
    std::string program;
    MachineOptions machine;
};
}  // namespace

void add_check_verb(CLI::App& app, int& exit_status) {
    auto options = std::make_shared<CheckOptions>();
    CLI::App* verb = app.add_subcommand("check", "Check a program: print its errors, exit 0 when clean");
    verb->add_option("FILE", options->program, "NC program")->required();
    add_machine_options(*verb, options->machine);
    verb->callback([options, &exit_status] {
        auto interpreter = open_program_or_report(options->program, options->machine, false);
        if (!interpreter) {
            exit_status = exit_bad_input;
            return;
        }
        for (;;) {
            InterpResult result = interpreter->next();
            if (std::holds_alternative<ProgramEnd>(result)) return;
            if (const auto* diagnostic = std::get_if<Diagnostic>(&result)) {
                print_diagnostic(*diagnostic);
                exit_status = exit_bad_input;
                return;
            }
        }
    });
}

}  // namespace nckit::cli
