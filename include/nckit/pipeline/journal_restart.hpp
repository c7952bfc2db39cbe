#pragma once
// `nckit restart --journal`: the restart program from a run journal (docs/restart.md): the
// target is the block after the last one the journal records as complete, #500-#999 are those
// the journal kept, and the journal must belong to this program and machine.
#include <filesystem>
#include <string>

#include "nckit/core/result.hpp"
#include "nckit/interp/interpreter.hpp"
#include "nckit/interp/restart.hpp"
#include "nckit/interp/run_journal.hpp"

namespace nckit {

//! The journal's run was of this program file (same size and CRC-32) on a machine with the
//! same axes; otherwise `restart-journal-mismatch` naming what differs.
[[nodiscard]] std::optional<Diagnostic> check_journal_matches(const JournalContents& journal,
                                                              const std::filesystem::path& program,
                                                              const MachineConfig& machine);

//! Writes the restart program of `journal`'s run into `out`. `interpreter` must have been
//! opened on the program with InterpreterOptions::retained_start = the journal's
//! header.retained_start. The search must arrive at the journal's position and retained values
//! at its last block (`restart-journal-mismatch` otherwise); a journal whose run completed
//! every block is `restart-run-complete`.
[[nodiscard]] Result<RestartReport> write_journal_restart(Interpreter& interpreter, const JournalContents& journal,
                                                          const std::string& source_name, std::string& out,
                                                          int decimals = -1);

}  // namespace nckit
