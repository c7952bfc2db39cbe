// Fanuc-style subroutines inside a LinuxCNC program, as LinuxCNC 2.9 runs them: `M98 P<n> L<k>`
// calls the block `O<n>` (found by number, so O0002 answers P2) k times, and `M99` returns.
// Unlike `o<name> call`, the sub shares the caller's #1-#30 (they are not restored), while named
// locals start empty at the new call level, as in LinuxCNC. `M99`
// in the main program ends it, as in LinuxCNC's standalone interpreter (a running machine would
// start the program again). An `o... sub` must not end with M99, and a bare `O<n>` block cannot
// be reached by `call`: LinuxCNC refuses both.
#include <cmath>

#include <fmt/format.h>

#include "ngc_runner.hpp"

namespace nckit::interp::ngc {

namespace {
constexpr std::size_t max_call_levels = 10;  // LinuxCNC's INTERP_SUB_ROUTINE_LEVELS, as for `call`
constexpr double max_repeats = 9999;         // L: a bound for a mistyped count
}  // namespace

std::optional<InterpResult> NgcRunner::run_fanuc_sub_words(std::vector<Move>& pending) {
    const Word* m = nullptr;
    const Word* p = nullptr;
    const Word* l = nullptr;
    for (const Word& w : block_.words) {
        if (w.letter == 'M' && (w.value == 98 || w.value == 99)) m = &w;
    }
    const bool call = m->value == 98;
    const std::uint32_t m_column = m->column;
    for (const Word& w : block_.words) {
        if (call && w.letter == 'P') p = &w;
        if (call && w.letter == 'L') l = &w;
    }
    if (call && p == nullptr)
        return InterpResult(fail(m_column, "M98 with no P word (the number of the O-word to call)"));
    const double number = call ? p->value : 0;
    const double repeats = call && l != nullptr ? l->value : 1;
    const std::uint32_t p_column = call ? p->column : 0;
    const std::uint32_t l_column = l != nullptr ? l->column : 0;
    if (call && (number < 0 || number != std::floor(number) || number > 99999999)) {
        return InterpResult(fail(p_column, fmt::format("M98 P{} is no O-word number", number)));
    }
    if (call && (repeats < 0 || repeats != std::floor(repeats) || repeats > max_repeats)) {
        return InterpResult(
            fail(l_column, fmt::format("M98 L{}: the repeat count is a whole number 0-{}", repeats, max_repeats)));
    }
    // The block's other words run first, as in LinuxCNC, which calls or returns last.
    std::erase_if(block_.words, [&](const Word& w) {
        return (w.letter == 'M' && (w.value == 98 || w.value == 99)) || (call && (w.letter == 'P' || w.letter == 'L'));
    });
    if (!block_.words.empty()) {
        if (auto error = translate_block()) return InterpResult(std::move(*error));
        bool program_end = false;
        if (auto error = executor_.run(block_, pending, program_end)) return InterpResult(std::move(*error));
        if (program_end) return InterpResult(ProgramEnd{});
    }
    if (!call) {
        if (frames_.size() == 1) {
            if (auto error = executor_.end_program(pending)) return InterpResult(std::move(*error));
            return InterpResult(ProgramEnd{});
        }
        Frame& frame = frames_.back();
        if (!frame.fanuc) {
            return InterpResult(fail(m_column, fmt::format("M99 inside o<{}> sub: a sub called by `call` ends with "
                                                           "endsub or return",
                                                           frame.sub)));
        }
        if (frame.repeats_left > 0) {
            --frame.repeats_left;
            if (auto error = back_to(frame.sub)) return InterpResult(std::move(*error));
            return std::nullopt;
        }
        const Frame done = frame;
        frames_.pop_back();
        parameters_.leave_call();
        if (auto error = switch_to(done.return_file, done.return_offset, done.return_line)) {
            return InterpResult(std::move(*error));
        }
        return std::nullopt;
    }
    if (repeats == 0) return std::nullopt;
    if (frames_.size() >= max_call_levels) {
        return InterpResult(
            fail(m_column, fmt::format("too many nested subroutine calls (more than {})", max_call_levels - 1)));
    }
    const std::string name = fmt::format("{}", static_cast<std::int64_t>(number));
    Frame frame{name, *source().file(), source().next_offset(), source().next_line_number()};
    frame.fanuc = true;
    frame.repeats_left = static_cast<int>(repeats) - 1;
    frames_.push_back(std::move(frame));
    parameters_.enter_shared_call();
    repeating_ = true;
    call_location_ = line_.at(m_column);
    if (auto it = labels_.find(name); it != labels_.end() && it->second.kind == OKind::bare) {
        if (auto error = switch_to(it->second.file, it->second.offset, it->second.line)) {
            return InterpResult(std::move(*error));
        }
        return std::nullopt;
    }
    skipping_o_ = name;
    skipping_to_sub_ = true;
    fanuc_search_ = true;
    return std::nullopt;
}

}  // namespace nckit::interp::ngc
