// nckit expand FILE: the program with every macro resolved, as a plain program of one move per
// block. With -o the file appears only when the whole program ran clean.
#include <cstdio>
#include <variant>

#include <fmt/format.h>

#include "common.hpp"
#include "partial_file.hpp"
#include "nckit/interp/move_gcode.hpp"
#include "verbs.hpp"

namespace nckit::cli {

namespace {

struct ExpandOptions {
    std::string program;
    std::string output;
    MachineOptions machine;
};

int run_expand(const ExpandOptions& options) {
    // Expanding shows what a run would do; it is not a run, so #500-#999 stay as they were.
    auto interpreter = open_program_or_report(options.program, options.machine, false);
    if (!interpreter) return exit_bad_input;
    std::optional<PartialFile> file;
    if (!options.output.empty()) {
        file = PartialFile::create(options.output);
        if (!file) return exit_bad_input;
    }
    std::FILE* out = file ? file->get() : stdout;
    GcodeWriter writer(interpreter->machine());
    std::string buffer;
    writer.append_header(buffer, options.program);
    for (;;) {
        InterpResult result = interpreter->next();
        if (std::holds_alternative<ProgramEnd>(result)) break;
        if (const auto* diagnostic = std::get_if<Diagnostic>(&result)) {
            if (!file) std::fwrite(buffer.data(), 1, buffer.size(), out);
            print_diagnostic(*diagnostic);
            return exit_bad_input;  // an unfinished -o file goes with its PartialFile
        }
        writer.append(buffer, std::get<Move>(result));
        if (buffer.size() > (1 << 16)) {
            std::fwrite(buffer.data(), 1, buffer.size(), out);
            buffer.clear();
        }
    }
    writer.append_footer(buffer);
    std::fwrite(buffer.data(), 1, buffer.size(), out);
    if (file && !file->commit()) return exit_bad_input;
    return 0;
}

}  // namespace

void add_expand_verb(CLI::App& app, int& exit_status) {
    auto options = std::make_shared<ExpandOptions>();
    CLI::App* verb = app.add_subcommand("expand", "Resolve macros and calls into a plain program, one move per block");
    verb->add_option("FILE", options->program, "NC program ('-': standard input)")->required();
    verb->add_option("-o,--output", options->output, "write the program here (default: standard output)");
    add_machine_options(*verb, options->machine);
    verb->callback([options, &exit_status] { exit_status = run_expand(*options); });
}

}  // namespace nckit::cli
