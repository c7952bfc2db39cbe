#include "journal_options.hpp"

#include <fmt/format.h>

#include "common.hpp"

namespace nckit::cli {

void add_journal_options(CLI::App& verb, JournalCliOptions& options) {
    verb.add_option("--journal", options.path,
                    "write a crash-safe run journal here: one checksummed record per completed block "
                    "(nckit restart --journal resumes from it)");
    verb.add_option("--journal-fsync-ms", options.fsync_interval_ms,
                    "sync the journal to disk at least every MS milliseconds; 0: after every block (default 250)")
        ->check(CLI::Range(std::int64_t{0}, std::int64_t{3'600'000}));
}

bool open_journal_or_report(const JournalCliOptions& options, const Interpreter& interpreter,
                            const std::string& program, std::optional<RunJournal>& journal) {
    if (options.path.empty()) return true;
    if (program == "-") {
        fmt::print(stderr,
                   "nckit: error: --journal needs the program as a file, not standard input (a restart "
                   "reads the program again)\n");
        return false;
    }
    auto created = RunJournal::create(options.path, interpreter, program, JournalOptions{options.fsync_interval_ms});
    if (!created) {
        print_diagnostics(created.diagnostics());
        return false;
    }
    journal.emplace(std::move(created).value());
    return true;
}

ProgramPlanCallbacks journal_callbacks(std::optional<RunJournal>& journal, const Interpreter& interpreter,
                                       std::function<void(const TrajectoryPiece&)> on_piece) {
    ProgramPlanCallbacks callbacks;
    if (!journal) {
        callbacks.on_piece = std::move(on_piece);
        return callbacks;
    }
    callbacks.on_piece = [&journal, on_piece = std::move(on_piece)](const TrajectoryPiece& piece) {
        on_piece(piece);
        journal->on_reached(piece.where);
    };
    callbacks.on_move = [&journal, &interpreter](const Move& move) { journal->on_move(interpreter, move); };
    return callbacks;
}

bool finish_journal_or_report(std::optional<RunJournal>& journal) {
    if (!journal) return true;
    journal->finish();
    if (journal->error()) {
        print_diagnostic(*journal->error());
        return false;
    }
    return true;
}

}  // namespace nckit::cli
