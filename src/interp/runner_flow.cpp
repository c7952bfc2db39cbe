// Macro statements: assignments, IF, GOTO and WHILE/DO/END loops, with Fanuc's rules for loop
// numbers (1-3, nested without overlapping) and for jumps (out of a loop: allowed).
#include <fmt/format.h>

#include "nckit/gcode/macro_alarms.hpp"
#include "nckit/gcode/parser.hpp"
#include "program_runner.hpp"

namespace nckit::interp {

namespace {
constexpr std::size_t max_loop_depth = 3;
}  // namespace

std::optional<Diagnostic> ProgramRunner::condition(const Block& block, bool& holds) {
    MacroValue value;
    if (auto error = evaluate(block, block.statement.condition, variables_, eval_settings_, value)) return error;
    holds = value.or_zero() != 0.0;
    return std::nullopt;
}

std::optional<Diagnostic> ProgramRunner::assign(const Block& block) {
    const MacroStatement& s = block.statement;
    std::int64_t number = 0;
    if (auto error = variable_number(block, s.target, variables_, eval_settings_, number)) return error;
    MacroValue value;
    if (auto error = evaluate(block, s.value, variables_, eval_settings_, value)) return error;
    if (auto error = variables_.write(number, value)) {
        std::uint32_t column = block.exprs[static_cast<std::size_t>(s.target)].column;
        Diagnostic d = alarm_at(block, column, error->alarm, error->message);
        if (error->alarm >= alarm::user_base) d.code = "user-alarm";
        return d;
    }
    return std::nullopt;
}

std::optional<Diagnostic> ProgramRunner::run_statement(const Block& block) {
    const MacroStatement& s = block.statement;
    switch (s.kind) {
        case StatementKind::assign:
            return assign(block);
        case StatementKind::if_then: {
            bool holds = false;
            if (auto error = condition(block, holds)) return error;
            return holds ? assign(block) : std::nullopt;
        }
        case StatementKind::if_goto:
        case StatementKind::go_to: {
            if (s.kind == StatementKind::if_goto) {
                bool holds = false;
                if (auto error = condition(block, holds)) return error;
                if (!holds) return std::nullopt;
            }
            MacroValue target;
            if (auto error = evaluate(block, s.value, variables_, eval_settings_, target)) return error;
            std::uint32_t column = block.exprs[static_cast<std::size_t>(s.value)].column;
            double n = round_half_away(target.or_zero());
            if (target.vacant || n < 1 || n > 99999) {
                return alarm_at(block, column, alarm::sequence_not_found,
                                fmt::format("GOTO target {} is not a sequence number 1-99999", target.or_zero()));
            }
            return jump_to_sequence(block, column, static_cast<std::int64_t>(n));
        }
        case StatementKind::while_do: {
            bool holds = false;
            if (auto error = condition(block, holds)) return error;
            return start_loop(block, holds);
        }
        case StatementKind::do_loop:
            return start_loop(block, true);
        case StatementKind::end_loop:
            return end_loop(block);
        case StatementKind::none:
            break;
    }
    return std::nullopt;
}

std::optional<Diagnostic> ProgramRunner::start_loop(const Block& block, bool condition_holds) {
    Frame& f = frame();
    const int m = block.statement.loop;
    // ENDm brings the program back to its DOm block: the loop is already active then.
    bool reentry = !f.loops.empty() && f.loops.back().number == m && f.loops.back().line == block.location.line;
    if (!condition_holds) {
        if (reentry) f.loops.pop_back();
        return skip_past_end(block, m);
    }
    if (reentry) return std::nullopt;
    for (const LoopEntry& loop : f.loops) {
        if (loop.number == m) {
            return alarm_at(block, block.statement.column, alarm::loop_number,
                            fmt::format("DO{} inside a loop that already uses DO{}", m, m));
        }
    }
    if (f.loops.size() >= max_loop_depth) {
        return alarm_at(block, block.statement.column, alarm::loop_number, "loops nested deeper than 3");
    }
    f.loops.push_back(LoopEntry{m, line_offset_, block.location.line, block.statement.column});
    return std::nullopt;
}

std::optional<Diagnostic> ProgramRunner::end_loop(const Block& block) {
    Frame& f = frame();
    const int m = block.statement.loop;
    if (f.loops.empty() || f.loops.back().number != m) {
        bool active = false;
        for (const LoopEntry& loop : f.loops) active = active || loop.number == m;
        return alarm_at(block, block.statement.column, active ? alarm::loop_number : alarm::loop_mismatch,
                        active ? fmt::format("END{} closes DO{} across another loop: loops overlap", m, m)
                               : fmt::format("END{} without DO{}", m, m));
    }
    source().seek(f.loops.back().offset, f.loops.back().line);
    return std::nullopt;
}

InterpResult ProgramRunner::finish_main(std::vector<Move>& pending) {
    InterpResult result = end_of_main();
    if (std::holds_alternative<ProgramEnd>(result)) {
        if (auto error = executor_.end_program(pending)) return *error;
    }
    return result;
}

InterpResult ProgramRunner::end_of_main() const {
    // The main program ends (end of file, next O program, closing '%') inside a loop whose
    // condition held: its END is missing, as much as when the condition fails at the start.
    const Frame& f = frames_.back();
    if (f.loops.empty()) return ProgramEnd{};
    const LoopEntry& loop = f.loops.back();
    Diagnostic d = error_at(make_location(sources_[frames_.size() - 1].file(), loop.line, loop.column), "macro-alarm",
                            fmt::format("WHILE ... DO{} has no END{}", loop.number, loop.number));
    d.alarm = alarm::loop_mismatch;
    return d;
}

std::optional<Diagnostic> ProgramRunner::skip_past_end(const Block& block, int loop) {
    // Scan forward for ENDm; the program goes on after it.
    for (;;) {
        auto line = source().next();
        if (!line) return line.diagnostics().front();
        bool ends_program = !line.value();
        if (!ends_program) {
            const ProgramSource::Line& text = **line;
            if (program_number_of(text.text)) ends_program = true;
            scan_.location = make_location(source().file(), text.number, 1);
            if (!ends_program && !parse_block(text.text, scan_)) {
                if (scan_.tape_mark) ends_program = true;
                if (scan_.statement.kind == StatementKind::end_loop && scan_.statement.loop == loop) {
                    return std::nullopt;
                }
            }
        }
        if (ends_program) {
            return alarm_at(block, block.statement.column, alarm::loop_mismatch,
                            fmt::format("WHILE ... DO{} has no END{}", loop, loop));
        }
    }
}

const SequenceIndex* ProgramRunner::sequence_index() {
    ProgramSource& src = source();
    if (!src.rereadable()) return nullptr;
    const Frame& f = frame();
    auto key = std::make_pair(*src.file(), f.program.offset);
    if (auto known = sequence_indexes_.find(key); known != sequence_indexes_.end()) {
        return known->second ? &*known->second : nullptr;
    }
    const std::uint64_t here = src.next_offset();
    const std::uint32_t here_line = src.next_line_number();
    src.seek(f.program.offset, f.program.line);
    SequenceIndex index;
    bool too_many = false;
    bool seen_block = false;  // a leading '%' and the O line are the program's header
    for (;;) {
        auto line = src.next();
        if (!line || !line.value()) break;
        const ProgramSource::Line& text = **line;
        if (program_number_of(text.text)) {
            if (seen_block) break;  // the next program
            continue;
        }
        if (const auto n = sequence_number_of(text.text)) {
            if (index.full()) {
                too_many = true;
                break;
            }
            index.add_number(*n, text.offset, text.number);
            seen_block = true;
        }
        scan_.location = make_location(src.file(), text.number, 1);
        if (!parse_block(text.text, scan_)) {
            if (scan_.tape_mark) {
                if (seen_block) break;
                continue;
            }
            if (scan_.statement.kind == StatementKind::end_loop) index.add_loop_end(scan_.statement.loop, text.offset);
            if (!scan_.words.empty() || scan_.statement.kind != StatementKind::none) seen_block = true;
        }
    }
    src.seek(here, here_line);
    if (too_many) {
        sequence_indexes_.emplace(std::move(key), std::nullopt);
        return nullptr;
    }
    index.seal();
    auto placed = sequence_indexes_.emplace(std::move(key), std::move(index));
    return &*placed.first->second;
}

std::optional<Diagnostic> ProgramRunner::jump_to_sequence(const Block& block, std::uint32_t column,
                                                          std::int64_t number) {
    Frame& f = frame();
    ProgramSource& src = source();
    const std::uint64_t here = src.next_offset();
    const std::uint32_t here_line = src.next_line_number();
    auto runaway = [&] {
        src.seek(here, here_line);
        return alarm_at(block, column, alarm::too_many_blocks,
                        fmt::format("more than {} blocks run or searched in loops, jumps and calls: a runaway "
                                    "program? (raise the budget with --max-blocks)",
                                    options_.max_blocks));
    };
    if (const SequenceIndex* index = sequence_index()) {
        const std::optional<SequenceIndex::Target> target = index->find(number, here);
        if (!target) {
            return alarm_at(block, column, alarm::sequence_not_found,
                            fmt::format("sequence number N{} not found", number));
        }
        if (target->offset >= here) {
            // Leaving a loop forward passes its END: that loop and the ones inside it are over.
            for (std::size_t i = 0; i < f.loops.size(); ++i) {
                if (index->loop_end_between(f.loops[i].number, here, target->offset)) {
                    f.loops.resize(i);
                    break;
                }
            }
        } else {
            // Jumping back before a loop's DO leaves that loop.
            while (!f.loops.empty() && f.loops.back().offset > target->offset) f.loops.pop_back();
            f.jumped_back = true;
        }
        src.seek(target->offset, target->line);
        return std::nullopt;
    }
    // No index: forward from here to the end of this program, then from its start back to here.
    std::vector<int> ends_passed;
    bool budget_spent = false;
    auto search = [&](bool forward) -> std::optional<std::pair<std::uint64_t, std::uint32_t>> {
        for (;;) {
            auto line = src.next();
            if (!line || !line.value()) return std::nullopt;
            const ProgramSource::Line& text = **line;
            // Every line searched counts against the runaway budget, as a block run does: two
            // GOTOs jumping over each other across a long program are bounded in time too.
            if (++counted_blocks_ > options_.max_blocks) {
                budget_spent = true;
                return std::nullopt;
            }
            // Backward, everything before here is this program (its O line is its header);
            // forward, the next O line starts another program.
            if (!forward && text.offset >= here) return std::nullopt;
            if (forward && program_number_of(text.text)) return std::nullopt;
            if (sequence_number_of(text.text) == number) return std::make_pair(text.offset, text.number);
            if (forward) {
                scan_.location = make_location(src.file(), text.number, 1);
                if (!parse_block(text.text, scan_)) {
                    if (scan_.tape_mark) return std::nullopt;
                    if (scan_.statement.kind == StatementKind::end_loop) ends_passed.push_back(scan_.statement.loop);
                }
            }
        }
    };
    if (auto target = search(true)) {
        // Leaving a loop forward passes its END: those loops are over.
        for (int m : ends_passed) {
            for (std::size_t i = 0; i < f.loops.size(); ++i) {
                if (f.loops[i].number == m) {
                    f.loops.resize(i);
                    break;
                }
            }
        }
        src.seek(target->first, target->second);
        return std::nullopt;
    }
    if (budget_spent) return runaway();
    src.seek(f.program.offset, f.program.line);
    if (auto target = search(false)) {
        // Jumping back before a loop's DO leaves that loop.
        while (!f.loops.empty() && f.loops.back().offset > target->first) f.loops.pop_back();
        f.jumped_back = true;
        src.seek(target->first, target->second);
        return std::nullopt;
    }
    if (budget_spent) return runaway();
    src.seek(here, here_line);
    return alarm_at(block, column, alarm::sequence_not_found, fmt::format("sequence number N{} not found", number));
}

}  // namespace nckit::interp
