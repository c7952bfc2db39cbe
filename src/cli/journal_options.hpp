#pragma once
// --journal FILE and --journal-fsync-ms MS of the verbs that run a machine (steps, servo): the
// crash-safe run journal that `nckit restart --journal` resumes from (docs/restart.md).
#include <CLI/CLI.hpp>

#include <optional>
#include <string>

#include "nckit/pipeline/plan_program.hpp"
#include "nckit/interp/run_journal.hpp"

namespace nckit::cli {

struct JournalCliOptions {
    std::string path;  //!< empty: no journal
    std::int64_t fsync_interval_ms = JournalOptions{}.fsync_interval_ms;
};

void add_journal_options(CLI::App& verb, JournalCliOptions& options);

//! The journal of this run, created before the run starts; nothing when none was asked for.
//! False (the error printed) when it cannot be created.
[[nodiscard]] bool open_journal_or_report(const JournalCliOptions& options, const Interpreter& interpreter,
                                          const std::string& program, std::optional<RunJournal>& journal);

//! Wraps a verb's piece callback so that the journal sees every move and every piece after the
//! verb has taken it.
[[nodiscard]] ProgramPlanCallbacks journal_callbacks(std::optional<RunJournal>& journal, const Interpreter& interpreter,
                                                     std::function<void(const TrajectoryPiece&)> on_piece);

//! Ends the journal after a clean run; false (the error printed) when a write or sync failed.
[[nodiscard]] bool finish_journal_or_report(std::optional<RunJournal>& journal);

}  // namespace nckit::cli
