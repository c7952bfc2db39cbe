#include "common.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <vector>

#include <fmt/format.h>

namespace nckit::cli {

void add_machine_options(CLI::App& verb, MachineOptions& options) {
    verb.add_option("--machine", options.machine, "machine config (TOML); default: built-in 3-axis mill");
    verb.add_option("--library", options.library, "folder of called programs, one file per O number");
    verb.add_option("--dialect", options.dialect,
                    "G-code dialect: fanuc (with Macro B) or linuxcnc (RS-274/NGC with O-words); default: the "
                    "machine file's, else fanuc")
        ->check(CLI::IsMember({"fanuc", "linuxcnc"}));
    verb.add_option("--tools", options.tools,
                    "tool file: TOML or LinuxCNC tool.tbl (replaces the machine file's 'tools')");
    verb.add_option("--vars", options.vars,
                    "file keeping #500-#999 between runs (default: the machine file with .vars)");
    verb.add_option("--max-blocks", options.max_blocks,
                    "blocks a program may run in loops and calls before it is stopped as a runaway")
        ->check(CLI::PositiveNumber);
    verb.add_flag("--block-delete", options.block_delete, "skip blocks that start with '/'");
    add_quiet_flag(verb, options.quiet);
}

namespace {
//! The run uses the built-in mill: errors a lathe program gets on it add a hint.
bool default_machine_in_use = false;
//! The program's first 4 KiB name lathe codes (G18 G7 G32 G33 G95 G96): a hint fits its errors.
bool program_looks_like_lathe = false;

bool names_lathe_codes(const std::string& head) {
    std::string upper;
    for (char c : head) {
        if (c != ' ' && c != '\t') upper += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    }
    for (const char* code : {"G18", "G7X", "G7\n", "G32", "G33", "G95", "G96"}) {
        if (upper.find(code) != std::string::npos) return true;
    }
    return false;
}

//! Edits (insert, delete, replace) between two words: how far a typo is from a verb.
std::size_t edit_distance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = above;
        }
    }
    return row[b.size()];
}
}  // namespace

std::optional<std::string> unknown_verb_hint(const CLI::App& app, const std::string& word) {
    std::string verbs;
    std::string closest;
    std::size_t best = std::string::npos;
    for (const CLI::App* verb : app.get_subcommands({})) {
        const std::string& name = verb->get_name();
        if (name == word) return std::nullopt;
        verbs += (verbs.empty() ? "" : ", ") + name;
        const std::size_t distance = edit_distance(word, name);
        if (distance < best) {
            best = distance;
            closest = name;
        }
    }
    std::string hint = fmt::format("nckit: unknown verb '{}'", word);
    // Two edits or a third of the word: a typo, not another word.
    if (best <= std::max<std::size_t>(2, word.size() / 3)) hint += fmt::format(" (did you mean '{}'?)", closest);
    return hint + fmt::format("; the verbs are: {} (nckit VERB --help)", verbs);
}

std::string json_number(double value) {
    return std::isfinite(value) ? fmt::format("{}", value) : "null";
}

void print_diagnostic(const Diagnostic& diagnostic) {
    std::fflush(stdout);
    std::fprintf(stderr, "%s\n", format_diagnostic(diagnostic).c_str());
    // The built-in machine is a mill: a lathe program's X-Z moves and spindle codes fail on it.
    static bool hinted = false;
    if (default_machine_in_use && program_looks_like_lathe && !hinted && diagnostic.severity == Severity::error &&
        (diagnostic.code == "unknown-axis" || diagnostic.code == "travel-limit" || diagnostic.code == "spindle-limit" ||
         diagnostic.code == "bad-combination" || diagnostic.code == "bad-arc" ||
         diagnostic.code == "unsupported-word")) {
        hinted = true;
        std::fprintf(stderr,
                     "%s: note: no --machine given, so this ran on the built-in 3-axis mill; a lathe "
                     "program needs its lathe, e.g. --machine examples/machines/lathe.toml\n",
                     diagnostic.location.file_name().c_str());
    }
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

namespace {

//! A program file that is no program: empty, or a TOML file (a machine or a job) given in its
//! place. Only the start of the file is read; a pipe is not looked at.
std::optional<Diagnostic> program_file_mistake(const std::string& path) {
    std::error_code ec;
    if (path == "-" || !std::filesystem::is_regular_file(path, ec)) return std::nullopt;
    std::ifstream in(path, std::ios::binary);
    std::string head(4096, '\0');
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(in.gcount()));
    auto name = std::make_shared<const std::string>(path);
    if (head.starts_with("\xEF\xBB\xBF")) head.erase(0, 3);
    const std::size_t first = head.find_first_not_of(" \t\r\n%");
    if (first == std::string::npos && std::filesystem::file_size(path, ec) <= head.size() + 3) {
        return error_at(make_location(name, 1, 1), "empty-program", "the program is empty: no blocks to run");
    }
    program_looks_like_lathe = names_lathe_codes(head);
    const bool toml_name = std::filesystem::path(path).extension() == ".toml";
    // No block of a program starts with '[' (Macro B brackets follow a word or '#').
    const bool toml_text = first != std::string::npos && head[first] == '[';
    if (toml_name || toml_text) {
        return error_at(make_location(name, 1, 1), "not-a-program",
                        "this is a TOML file (a machine or a job), not an NC program: a machine goes with "
                        "--machine, a job to its verb (nckit crosshatch|eccentric|piston JOB.toml)");
    }
    return std::nullopt;
}

}  // namespace

std::optional<Interpreter> open_program_or_report(const std::string& program_path, const MachineOptions& options,
                                                  bool keep_retained, bool warn) {
    auto machine = load_machine_or_report(options.machine);
    if (!machine) return std::nullopt;
    if (auto mistake = program_file_mistake(program_path)) {
        print_diagnostic(*mistake);
        return std::nullopt;
    }
    default_machine_in_use = options.machine.empty();
    if (!options.dialect.empty()) machine->dialect = options.dialect == "linuxcnc" ? Dialect::linuxcnc : Dialect::fanuc;
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
    interpreter.subroutine_path = machine->subroutine_path;
    interpreter.max_blocks = options.max_blocks;
    interpreter.save_retained = keep_retained;
    interpreter.keep_going_after_errors = options.keep_going;
    interpreter.retained_start = options.retained_start;
    interpreter.on_warning = [warn](const Diagnostic& warning) {
        if (warn) print_diagnostic(warning);
    };
    if (!options.vars.empty()) {
        interpreter.retained_file = options.vars;
    } else if (!options.machine.empty() && machine->dialect == Dialect::fanuc) {
        // (A LinuxCNC parameter file is read and written only when --vars names it.)
        // Retained variables live beside the machine they belong to, as in a control's memory.
        interpreter.retained_file = std::filesystem::path(options.machine).replace_extension(".vars");
    }
    return Interpreter(std::move(*machine), std::move(source).value(), interpreter);
}

}  // namespace nckit::cli
