#include "nckit/pipeline/journal_restart.hpp"

#include <cmath>

#include <fmt/format.h>

namespace nckit {

namespace {

Diagnostic mismatch_at(const SourceLocation& where, std::string why) {
    return error_at(where, "restart-journal-mismatch", std::move(why));
}

}  // namespace

std::optional<Diagnostic> check_journal_matches(const JournalContents& journal, const std::filesystem::path& program,
                                                const MachineConfig& machine) {
    const SourceLocation where = make_location(std::make_shared<const std::string>(program.string()), 1, 1);
    auto crc = file_crc32(program);
    if (!crc) return crc.diagnostics().front();
    if (crc->first != journal.header.program_bytes || crc->second != journal.header.program_crc) {
        return mismatch_at(
            where, fmt::format("the run journal was written for another version of this program ({} "
                               "bytes, CRC-32 {:08x}; the file has {} bytes, {:08x})",
                               journal.header.program_bytes, journal.header.program_crc, crc->first, crc->second));
    }
    std::string axes;
    for (const AxisConfig& axis : machine.axes) axes += letter(axis.axis);
    if (axes != journal.header.axes) {
        return mismatch_at(where, fmt::format("the run journal's machine has the axes {}, this machine {}",
                                              journal.header.axes, axes));
    }
    return std::nullopt;
}

Result<RestartReport> write_journal_restart(Interpreter& interpreter, const JournalContents& journal,
                                            const std::string& source_name, std::string& out, int decimals) {
    RestartTarget target;
    target.kind = RestartTarget::Kind::block;
    target.number = journal.records + 1;
    RestartSettings settings;
    settings.decimals = decimals;
    settings.retained_at_target = journal.retained_at_last;
    Result<RestartReport> report = write_restart(interpreter, target, source_name, out, settings);
    if (!report) {
        const Diagnostic& d = report.diagnostics().front();
        if (d.code == "restart-not-reached") {
            return error_at(d.location, "restart-run-complete",
                            fmt::format("the run journal records all {} blocks of the run as done: nothing is left "
                                        "to restart",
                                        journal.records));
        }
        return report;
    }
    // The search must stand where the journal says the machine stood after its last block.
    const RestartApproach& a = report->approach;
    if (journal.last && journal.last->position && a.moves) {
        const MachineConfig& machine = interpreter.machine();
        for (std::size_t i = 0; i < machine.axes.size() && i < journal.last->position->size(); ++i) {
            const double recorded = (*journal.last->position)[i];
            const double searched = a.point[machine.axes[i].axis];
            if (!(std::abs(recorded - searched) <= 1e-9 * std::max(1.0, std::abs(recorded)))) {
                return mismatch_at(report->where,
                                   fmt::format("the run journal has {} at {} after block {}, the program gives {}: "
                                               "the program, its machine, tools or offsets changed since the run",
                                               letter(machine.axes[i].axis), recorded, journal.last->block, searched));
            }
        }
    }
    return report;
}

}  // namespace nckit
