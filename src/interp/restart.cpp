#include "nckit/interp/restart.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <filesystem>
#include <iterator>
#include <memory>
#include <optional>
#include <variant>

#include <fmt/format.h>

#include "nckit/core/format_exact.hpp"
#include "nckit/interp/arc_geometry.hpp"
#include "nckit/interp/block_counter.hpp"
#include "nckit/interp/move_gcode.hpp"
#include "restart_preamble.hpp"

namespace nckit {

using namespace restart_detail;

namespace {

std::uint32_t line_count(const std::string& text) {
    return static_cast<std::uint32_t>(std::count(text.begin(), text.end(), '\n'));
}

//! "#500 = 3" lines for the retained variables that differ between `from` and `to` (a
//! variable that became vacant is written `= #0`, the vacant variable).
//! In the LinuxCNC dialect the persistent parameters #5161-#5169 and #5210-#5390 are the G28
//! position, G92 and the work offsets, which the reader keeps itself: the frame blocks set them
//! again as G10 L2, G5x and G92 (an assignment would not move the frame).
bool set_by_frame(int number, const MachineConfig& machine) {
    return machine.dialect == Dialect::linuxcnc &&
           ((number >= 5161 && number <= 5169) || (number >= 5210 && number <= 5390));
}

void retained_assignments(std::string& out, const std::vector<RetainedVariable>& from,
                          const std::vector<RetainedVariable>& to, const MachineConfig& machine) {
    auto find = [](const std::vector<RetainedVariable>& in, int number) -> const RetainedVariable* {
        auto it = std::lower_bound(in.begin(), in.end(), number,
                                   [](const RetainedVariable& v, int n) { return v.number < n; });
        return it != in.end() && it->number == number ? &*it : nullptr;
    };
    for (const RetainedVariable& v : to) {
        if (set_by_frame(v.number, machine)) continue;
        const RetainedVariable* old = find(from, v.number);
        if (old != nullptr && std::bit_cast<std::uint64_t>(old->value) == std::bit_cast<std::uint64_t>(v.value)) {
            continue;
        }
        fmt::format_to(std::back_inserter(out), "#{} = ", v.number);
        append_exact(out, v.value);
        out += '\n';
    }
    for (const RetainedVariable& v : from) {
        if (find(to, v.number) == nullptr && !set_by_frame(v.number, machine))
            fmt::format_to(std::back_inserter(out), "#{} = #0\n", v.number);
    }
}

}  // namespace

Result<RestartReport> write_restart(Interpreter& interpreter, const RestartTarget& target,
                                    const std::string& source_name, std::string& out, const RestartSettings& settings) {
    const MachineConfig& machine = interpreter.machine();
    const int decimals = settings.decimals;
    RestartReport report;
    RestartState before(machine, interpreter.modal_view());
    BlockCounter blocks;
    std::int64_t hits = 0, records = 0;
    const std::string* main_file = nullptr;
    std::optional<Move> first;  // the target's first move
    // #500-#999 as the last block before the target left them (read when they were written).
    std::uint64_t retained_writes = interpreter.retained_writes();
    std::vector<RetainedVariable> retained = interpreter.retained_values();
    for (;;) {
        InterpResult result = interpreter.next();
        if (auto* error = std::get_if<Diagnostic>(&result)) return std::move(*error);
        if (std::holds_alternative<ProgramEnd>(result)) break;
        Move& move = std::get<Move>(result);
        if (main_file == nullptr) main_file = move.where.file.get();
        const ModalView view = interpreter.modal_view();
        if (blocks.note(move, interpreter.output_batch())) {
            bool hit = false;
            switch (target.kind) {
                case RestartTarget::Kind::block:
                    hit = blocks.count() == target.number;
                    break;
                case RestartTarget::Kind::line:
                    hit = move.where.file.get() == main_file && move.where.line == target.number &&
                          ++hits == target.occurrence;
                    break;
                case RestartTarget::Kind::sequence:
                    hit = move.sequence_number == target.number && ++hits == target.occurrence;
                    break;
            }
            if (hit) {
                if (auto refused = before.refuse(move, view)) return std::move(*refused);
                report.where = move.where;
                report.sequence_number = move.sequence_number;
                report.block = blocks.count();
                report.first_record = records;
                first = std::move(move);
                break;
            }
        }
        if (interpreter.retained_writes() != retained_writes) {
            retained_writes = interpreter.retained_writes();
            retained = interpreter.retained_values();
        }
        ++records;
        before.note(move, view);
    }
    if (!first) {
        const char* what = target.kind == RestartTarget::Kind::block  ? "block"
                           : target.kind == RestartTarget::Kind::line ? "line"
                                                                      : "N";
        std::string text =
            target.kind != RestartTarget::Kind::block
                ? fmt::format("{} {} is reached {} times, not {}", what, target.number, hits, target.occurrence)
                : fmt::format("block {} is not reached by a block that moves ({} blocks run)", target.number,
                              blocks.count());
        return error_at(make_location(std::make_shared<const std::string>(source_name), 1, 1), "restart-not-reached",
                        std::move(text));
    }
    // The block before the target left `retained` (its values once all moves before the target
    // were made); a journal's values must be the same, or the program or its inputs changed.
    report.state = before.modes();
    report.io = before.io();
    report.retained = retained;
    if (settings.retained_at_target && *settings.retained_at_target != retained) {
        return error_at(report.where, "restart-journal-mismatch",
                        "the run journal's #500-#999 at this block differ from those the program computes from "
                        "the journal's starting values: the program or its inputs changed since the run");
    }
    // The preamble and approach, then the target's moves and everything after them.
    GcodeWriter writer(machine);
    writer.round_to_decimals(decimals);
    bool preamble_written = false;
    std::optional<Move> pending = std::move(first);
    for (;;) {
        if (!pending) {
            InterpResult result = interpreter.next();
            if (auto* error = std::get_if<Diagnostic>(&result)) return std::move(*error);
            if (std::holds_alternative<ProgramEnd>(result)) break;
            pending = std::move(std::get<Move>(result));
        }
        if (!preamble_written) {
            preamble_written = true;
            report.approach = before.approach(*pending);
            RestartApproach& a = report.approach;
            fmt::format_to(std::back_inserter(out), "( {} restarted by nckit at {}{}, block {} )\n",
                           std::filesystem::path(source_name).filename().string(), location_text(report.where),
                           report.sequence_number >= 0 ? fmt::format(" N{}", report.sequence_number) : std::string(),
                           report.block);
            writer.append_header(out, source_name);
            const bool in_frame = frame_can_be_set(report.state);
            frame_comments(out, report.state, machine, in_frame);
            if (settings.retained_at_target) {
                out += machine.dialect == Dialect::linuxcnc
                           ? "( persistent parameters as the interrupted run left them )\n"
                           : "( retained variables as the interrupted run left them )\n";
                retained_assignments(out, {}, retained, machine);
            }
            io_blocks(out, report.io, machine);
            if (a.moves) approach_blocks(out, a, machine, decimals, report.worst_deviation_mm);
            const ModalView& s = report.state;
            if (in_frame) {
                frame_blocks(out, s, machine, a.moves ? &a.point : nullptr);
                transform_blocks(out, s, machine, a.moves ? &a.point : nullptr);
                // The header wrote radius mode (G8): the moves and offsets above are radii.
                if (s.diameter_mode) out += "G7\n";
            }
            for (int m : report.io.laser_on) fmt::format_to(std::back_inserter(out), "M{}\n", m);
            fmt::format_to(std::back_inserter(out), "{} {}", plane_code(s.plane), feed_mode_code(s.feed_mode, machine));
            // F0 too: the approach's feed must not stay in force.
            out += " F";
            append_exact(out, in_frame ? s.feed / s.length_factor_mm : s.feed);
            if (in_frame && s.incremental) out += " G91";
            if (s.path.exact_stop) {
                out += " G61";
            } else if (s.path.tolerance_mm > 0) {
                out += " G64 P";
                append_exact(out, s.path.tolerance_mm);
            } else {
                out += " G64";
            }
            out += "\n( the rest of the program from the target on )\n";
            writer.assume_modes(s.plane, s.feed_mode, s.feed, s.path);
            if (in_frame) writer.use_frame(program_frame(s, machine), a.point);
            report.rest_line = line_count(out) + 1;
        }
        // After a journal, #500-#999 go on changing as the original run changed them.
        if (settings.retained_at_target && interpreter.retained_writes() != retained_writes) {
            retained_writes = interpreter.retained_writes();
            std::vector<RetainedVariable> now = interpreter.retained_values();
            retained_assignments(out, retained, now, machine);
            retained = std::move(now);
        }
        writer.append(out, *pending);
        pending.reset();
    }
    writer.append_footer(out);
    report.worst_deviation_mm = std::max(report.worst_deviation_mm, writer.worst_deviation_mm());
    return report;
}

}  // namespace nckit
