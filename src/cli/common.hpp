#pragma once
// What every verb shares: the machine and program options, loading them, reporting diagnostics.
#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "nckit/core/machine.hpp"
#include "nckit/interp/interpreter.hpp"
#include "progress.hpp"

namespace nckit::cli {

//! Exit status for bad user input (program, config, job): nothing was moved.
constexpr int exit_bad_input = 2;

//! The options of every verb that runs a program.
struct MachineOptions {
    std::string machine;  //!< --machine; empty: the built-in mill
    std::string library;  //!< --library: folder of O-numbered programs (LinuxCNC: NAME.ngc subs)
    std::string dialect;  //!< --dialect fanuc|linuxcnc; empty: the machine file's (default fanuc)
    std::string tools;    //!< --tools: tool file (TOML or LinuxCNC tool.tbl); replaces the machine's
    std::string vars;     //!< --vars: retained #500-#999; default: beside the machine file
    std::int64_t max_blocks = InterpreterOptions{}.max_blocks;
    bool block_delete = false;
    bool quiet = false;       //!< --quiet: no progress on stderr
    bool keep_going = false;  //!< report a block's error and go on (nckit check)
    //! #500-#999 to start with instead of the --vars file's (restart --journal); not an option.
    std::optional<std::vector<RetainedVariable>> retained_start;
};

void add_machine_options(CLI::App& verb, MachineOptions& options);

//! For a first argument that names no verb: "unknown verb 'X' (did you mean 'Y'?); verbs: ...".
[[nodiscard]] std::optional<std::string> unknown_verb_hint(const CLI::App& app, const std::string& word);

//! A JSON number with full precision; "null" for inf and NaN, which JSON has no spelling for.
[[nodiscard]] std::string json_number(double value);

void print_diagnostic(const Diagnostic& diagnostic);
void print_diagnostics(const Diagnostics& diagnostics);

//! The machine from `--machine`, or the built-in mill when the path is empty.
[[nodiscard]] std::optional<MachineConfig> load_machine_or_report(const std::string& path);

//! An interpreter over FILE ("-": standard input); errors are printed. The run reads #500-#999
//! and writes their file back only with `keep_retained` (`nckit moves --save-vars`): looking at
//! a program never changes files as a side effect. Without `warn`, the program's warnings are
//! not printed (a verb that runs the program again, after a first run has printed them).
[[nodiscard]] std::optional<Interpreter> open_program_or_report(const std::string& program_path,
                                                                const MachineOptions& options,
                                                                bool keep_retained = false, bool warn = true);

//! Progress over the main program (blocks, rate, share of the file read) for `verb`.
class ProgramProgress {
public:
    ProgramProgress(const std::string& verb, const std::string& program_path, bool quiet)
        : progress_("nckit " + verb, "blocks", quiet), total_bytes_(regular_file_bytes(program_path)) {}
    void update(const Interpreter& interpreter) {
        ++blocks_;
        if (!progress_.enabled()) return;
        const double fraction = total_bytes_ > 0 ? static_cast<double>(interpreter.main_program_offset()) /
                                                       static_cast<double>(total_bytes_)
                                                 : -1.0;
        progress_.update(blocks_, fraction);
    }
    void finish() { progress_.finish(); }

private:
    Progress progress_;
    std::uint64_t total_bytes_;
    std::int64_t blocks_ = 0;
};

}  // namespace nckit::cli
