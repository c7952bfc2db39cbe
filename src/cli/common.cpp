#include "common.hpp"

#include <cstdio>
#include <filesystem>

namespace nckit::cli {

void add_machine_options(CLI::App& verb, MachineOptions& options) {
    verb.add_option("--machine", options.machine, "machine config (TOML); default: built-in 3-axis mill");
    verb.add_option("--library", options.library, "folder of called programs, one file per O number");
    verb.add_option("--tools", options.tools,
                    "tool file: TOML or LinuxCNC tool.tbl (replaces the machine file's 'tools')");
    verb.add_option("--vars", options.vars,
                    "file keeping #500-#999 between runs (default: the machine file with .vars)");
    verb.add_option("--max-blocks", options.max_blocks,
                    "blocks a program may run in loops and calls before it is stopped as a runaway")
        ->check(CLI::PositiveNumber);
    verb.add_flag("--block-delete", options.block_delete, "skip blocks that start with '/'");
}

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

std::optional<Interpreter> open_program_or_report(const std::string& program_path, const MachineOptions& options,
                                                  bool keep_retained) {
    auto machine = load_machine_or_report(options.machine);
    if (!machine) return std::nullopt;
    if (!options.tools.empty()) {
        auto tools = load_tool_table(options.tools);
        if (!tools) {
            print_diagnostics(tools.diagnostics());
            return std::nullopt;
        }
        machine->tools = std::move(tools).value();
        machine->tools_file = options.tools;
    }
    auto source = ProgramSource::open(program_path);
    if (!source) {
        print_diagnostics(source.diagnostics());
        return std::nullopt;
    }
    InterpreterOptions interpreter;
    interpreter.block_delete = options.block_delete;
    interpreter.library_dir = options.library;
    interpreter.max_blocks = options.max_blocks;
    interpreter.save_retained = keep_retained;
    if (!options.vars.empty()) {
        interpreter.retained_file = options.vars;
    } else if (!options.machine.empty()) {
        // Retained variables live beside the machine they belong to, as in a control's memory.
        interpreter.retained_file = std::filesystem::path(options.machine).replace_extension(".vars");
    }
    return Interpreter(std::move(*machine), std::move(source).value(), interpreter);
}

}  // namespace nckit::cli
