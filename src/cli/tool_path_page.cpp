#include "tool_path_page.hpp"

#include <fstream>
#include <sstream>

#include "nckit/plan/planner.hpp"
#include "partial_file.hpp"
#include "plan_stream.hpp"

namespace nckit::cli {

namespace {

std::optional<ToolPathSection> record(Interpreter& interpreter, const ToolPathOptions& options,
                                      const std::string* text_of_first_file, ProgramProgress* progress) {
    const MachineConfig& config = interpreter.machine();
    Planner planner(config);
    ToolPathRecorder recorder(config, config.profile, options);
    if (!plan_program(
            interpreter, planner, [&](const TrajectoryPiece& piece) { recorder.add_piece(piece); },
            [&](const Move& move) { recorder.add_move(move); }, progress)) {
        return std::nullopt;
    }
    ToolPathSection section{recorder.finish(), config, {}};
    for (std::size_t i = 0; i < section.report.files.size(); ++i) {
        if (i == 0 && text_of_first_file != nullptr) {
            section.sources.push_back(*text_of_first_file);
            continue;
        }
        std::ifstream in(section.report.files[i], std::ios::binary);
        std::ostringstream text;
        text << in.rdbuf();
        section.sources.push_back(std::move(text).str());
    }
    return section;
}

}  // namespace

std::optional<ToolPathSection> plan_tool_path(const std::string& program, const MachineOptions& machine,
                                              const ToolPathOptions& options) {
    // A report looks at a run; it keeps #500-#999 as they were, as `nckit check` does.
    auto interpreter = open_program_or_report(program, machine, false);
    if (!interpreter) return std::nullopt;
    ToolPathOptions with_program = options;
    with_program.first_file = program;
    // Blocks done, rate and time left on stderr when it is a terminal (--quiet silences it).
    ProgramProgress progress("report", program, machine.quiet);
    auto section = record(*interpreter, with_program, nullptr, &progress);
    progress.finish();
    return section;
}

std::optional<ToolPathSection> plan_tool_path_text(const std::string& text, const std::string& name,
                                                   const MachineConfig& machine, const ToolPathOptions& options) {
    InterpreterOptions interpreter_options;
    interpreter_options.save_retained = false;
    Interpreter interpreter(machine, ProgramSource::from_string(text, name), interpreter_options);
    ToolPathOptions with_program = options;
    with_program.first_file = name;
    return record(interpreter, with_program, &text, nullptr);
}

bool write_page(const ReportPage& page, const std::string& path) {
    const std::string html = render_report_html(page);
    auto file = PartialFile::create(path);
    if (!file) return false;
    file->write(html);
    return file->commit();
}

}  // namespace nckit::cli
