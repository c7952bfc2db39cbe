#pragma once
// What every verb shares: the machine and program options, loading them, reporting diagnostics.
#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <string>

#include "nckit/core/machine.hpp"
#include "nckit/interp/interpreter.hpp"

namespace nckit::cli {

//! Exit status for bad user input (program, config, job): nothing was moved.
constexpr int exit_bad_input = 2;

//! The options of every verb that runs a program.
struct MachineOptions {
    std::string machine;       //!< --machine; empty: the built-in mill
    std::string library;       //!< --library: folder of O-numbered programs
    std::string tools;         //!< --tools: tool file (TOML or LinuxCNC tool.tbl); replaces the machine's
    std::string vars;          //!< --vars: retained #500-#999; default: beside the machine file
    std::int64_t max_blocks = InterpreterOptions{}.max_blocks;
    bool block_delete = false;
};

void add_machine_options(CLI::App& verb, MachineOptions& options);

void print_diagnostic(const Diagnostic& diagnostic);
void print_diagnostics(const Diagnostics& diagnostics);

//! The machine from `--machine`, or the built-in mill when the path is empty.
[[nodiscard]] std::optional<MachineConfig> load_machine_or_report(const std::string& path);

//! An interpreter over FILE; errors are printed. With `keep_retained` false the run reads
//! #500-#999 but leaves their file as it was (for checks).
[[nodiscard]] std::optional<Interpreter> open_program_or_report(const std::string& program_path,
                                                                const MachineOptions& options,
                                                                bool keep_retained = true);

}  // namespace nckit::cli
