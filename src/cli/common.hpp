#pragma once
// What every verb shares: loading the machine, opening the program, reporting diagnostics.
#include <optional>
#include <string>

#include "nckit/core/machine.hpp"
#include "nckit/interp/interpreter.hpp"

namespace nckit::cli {

//! Exit status for bad user input (program, config, job): nothing was moved.
constexpr int exit_bad_input = 2;

void print_diagnostic(const Diagnostic& diagnostic);
void print_diagnostics(const Diagnostics& diagnostics);

//! The machine from `--machine`, or the built-in mill when the path is empty.
[[nodiscard]] std::optional<MachineConfig> load_machine_or_report(const std::string& path);

//! An interpreter over FILE on MACHINE; errors are printed.
[[nodiscard]] std::optional<Interpreter> open_program_or_report(const std::string& program_path,
                                                                const std::string& machine_path,
                                                                const InterpreterOptions& options);

}  // namespace nckit::cli
