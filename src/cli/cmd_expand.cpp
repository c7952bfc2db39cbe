// nckit expand FILE: the program with every macro resolved, as a plain program of one move per
// block. With -o the file appears only when the whole program ran clean.
#include <cstdint>
#include <cstdio>
#include <string>
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
    int decimals = -1;  //!< --decimals; -1: exact
    bool json = false;
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
    writer.round_to_decimals(options.decimals);
    std::int64_t moves = 0;
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
        ++moves;
        if (buffer.size() > (1 << 16)) {
            std::fwrite(buffer.data(), 1, buffer.size(), out);
            buffer.clear();
        }
    }
    writer.append_footer(buffer);
    std::fwrite(buffer.data(), 1, buffer.size(), out);
    if (file && !file->commit()) return exit_bad_input;
    if (options.json) {
        fmt::print("{{\"moves\":{},\"decimals\":{},\"worst_deviation_mm\":{}}}\n", moves,
                   options.decimals < 0 ? std::string("null") : std::to_string(options.decimals),
                   json_number(writer.worst_deviation_mm()));
    } else if (options.decimals >= 0) {
        fmt::print(stderr, "expand: coordinates rounded to {} decimals, worst deviation {} mm\n", options.decimals,
                   json_number(writer.worst_deviation_mm()));
    }
    return 0;
}

}  // namespace

void add_expand_verb(CLI::App& app, int& exit_status) {
    auto options = std::make_shared<ExpandOptions>();
    CLI::App* verb = app.add_subcommand("expand", "Resolve macros and calls into a plain program, one move per block");
    verb->add_option("FILE", options->program, "NC program ('-': standard input)")->required();
    verb->add_option("-o,--output", options->output, "write the program here (default: standard output)");
    verb->add_option("--decimals", options->decimals,
                     "round coordinates to N decimals for a control that reads fewer (default: exact)")
        ->check(CLI::Range(0, 17));
    CLI::Option* output = verb->get_option("--output");
    verb->add_flag("--json", options->json, "print a JSON summary (moves, worst deviation); needs -o")->needs(output);
    add_machine_options(*verb, options->machine);
    verb->callback([options, &exit_status] { exit_status = run_expand(*options); });
}

}  // namespace nckit::cli
