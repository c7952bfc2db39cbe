#include "common.hpp"

#include <cstdio>

namespace nckit::cli {

void print_diagnostic(const Diagnostic& diagnostic) {
    std::fflush(stdout);
    std::fprintf(stderr, "%s\n", format_diagnostic(diagnostic).c_str());
}

void print_diagnostics(const Diagnostics& diagnostics) {
    for (const Diagnostic& d : diagnostics) print_diagnostic(d);
}

std::optional<MachineConfig> load_machine_or_report(const std::string& path) {
    if (path.empty()) return default_mill();
    auto machine = load_machine_config(path);
    if (!machine) {
        print_diagnostics(machine.diagnostics());
        return std::nullopt;
    }
    return std::move(machine).value();
}

std::optional<Interpreter> open_program_or_report(const std::string& program_path,
                                                  const std::string& machine_path,
                                                  const InterpreterOptions& options) {
    auto machine = load_machine_or_report(machine_path);
    if (!machine) return std::nullopt;
    auto source = ProgramSource::open(program_path);
    if (!source) {
        print_diagnostics(source.diagnostics());
        return std::nullopt;
    }
    return Interpreter(std::move(*machine), std::move(source).value(), options);
}

}  // namespace nckit::cli
