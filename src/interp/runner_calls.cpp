// Calls: G65 (macro call with arguments), G66/G67 (modal macro call after every move), M98
// (subprogram, sharing the caller's variables), M99 (return, or restart of the main program).
#include <array>
#include <cmath>

#include <fmt/format.h>

#include "nckit/gcode/macro_alarms.hpp"
#include "program_runner.hpp"

namespace nckit::interp {

namespace {

constexpr std::size_t max_call_depth = 10;  // subprogram levels in all, macros included
constexpr std::size_t max_macro_depth = 4;  // G65/G66 levels
constexpr int max_repeats = 9999;
constexpr int max_ijk_sets = 10;  // argument specification II: I1 J1 K1 .. I10 J10 K10

//! Argument specification I: the local variable each letter fills (0: not an argument).
constexpr std::array<int, 26> argument_variable = {
    1, 2, 3, 7,  8,  9,  0,  11, 4,  5,  6,  0,  13,  // A B C D E F G H I J K L M
    0, 0, 0, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26   // N O P Q R S T U V W X Y Z
};

//! The whole number a P or L word names: rounded, so that a computed P[#1*1000] of
//! 1000.9999999999999 calls O1001; -1 outside 0..99999999, where no program or count lies.
std::int64_t code_number(const Word& word) {
    double rounded = round_half_away(word.value);
    return rounded >= 0 && rounded <= 99999999 ? static_cast<std::int64_t>(rounded) : -1;
}

bool moved(const std::vector<Move>& pending, std::size_t from) {
    for (std::size_t i = from; i < pending.size(); ++i) {
        const auto& what = pending[i].what;
        if (std::holds_alternative<Line>(what) || std::holds_alternative<Arc>(what) ||
            std::holds_alternative<SyncMove>(what)) {
            return true;
        }
    }
    return false;
}

}  // namespace

std::optional<Diagnostic> ProgramRunner::arguments_of(const Block& block, Variables::Locals& arguments) const {
    arguments = Variables::Locals{};
    const bool least_increment = eval_settings_.least_increment_input;
    int set = 0;
    char previous_ijk = 0;
    for (const Word& word : block.words) {
        char c = word.letter;
        int variable = argument_variable[static_cast<std::size_t>(c - 'A')];
        if (variable == 0) continue;  // G L N O P are the call's own words
        if (c == 'I' || c == 'J' || c == 'K') {
            // Specification II: a new I J K set starts when a letter does not follow the last.
            if (previous_ijk != 0 && c <= previous_ijk) ++set;
            previous_ijk = c;
            if (set >= max_ijk_sets) {
                return alarm_at(block, word.column, alarm::call_format, "more than ten I J K argument sets");
            }
            variable = 4 + 3 * set + (c - 'I');
        }
        double value = word.value;
        bool scaled_letter = axis_from_letter(c).has_value() || c == 'I' || c == 'J' || c == 'K' || c == 'R';
        if (least_increment && scaled_letter && !word.has_decimal_point) {
            value *= executor_.inch_units() && !(c == 'A' || c == 'B' || c == 'C') ? 1e-4 : 1e-3;
        }
        arguments[static_cast<std::size_t>(variable)] = MacroValue::of(value);
    }
    return std::nullopt;
}

std::optional<Diagnostic> ProgramRunner::call(const Block& block, std::uint32_t column, std::int64_t program,
                                              int repeats, bool own_locals, const Variables::Locals* arguments,
                                              bool modal) {
    if (frames_.size() > max_call_depth) {
        return alarm_at(block, column, alarm::call_nesting,
                        fmt::format("calls nested deeper than {} levels", max_call_depth));
    }
    if (own_locals) {
        std::size_t macros = 0;
        for (const Frame& f : frames_) macros += f.own_locals ? 1 : 0;
        if (macros >= max_macro_depth) {
            return alarm_at(block, column, alarm::call_nesting,
                            fmt::format("macro calls nested deeper than {} levels", max_macro_depth));
        }
    }
    if (repeats < 1 || repeats > max_repeats) {
        return alarm_at(block, column, alarm::call_format, fmt::format("repeat count L{} is not 1 to 9999", repeats));
    }
    auto found = library_.find(program, sources_[0]);
    if (!found) return found.diagnostics().front();
    if (!found.value()) {
        // Say where it looked: the usual cause is a library folder not given or the wrong one.
        const std::string where =
            options_.library_dir.empty()
                ? fmt::format(
                      "looked in {}; no --library folder given (give one with --library DIR: files "
                      "O{:04d}.nc, {:04d}.ngc or O{:04d})",
                      *sources_[0].file(), program, program, program)
                : fmt::format("looked in {} and in the library folder {} (files O{:04d}.nc, {:04d}.ngc, O{:04d})",
                              *sources_[0].file(), options_.library_dir.string(), program, program, program);
        return alarm_at(block, column, alarm::program_not_found,
                        fmt::format("program O{:04d} not found: {}", program, where));
    }
    const ProgramLocation& location = **found;
    const std::size_t depth = frames_.size();
    if (sources_.size() <= depth || *sources_[depth].file() != location.file) {
        auto reader = location.in_main_file ? sources_[0].reopen() : ProgramSource::open(location.file);
        if (!reader) return reader.diagnostics().front();
        if (sources_.size() <= depth) {
            sources_.push_back(std::move(reader).value());
        } else {
            sources_[depth] = std::move(reader).value();
        }
    }
    Frame callee;
    callee.program = location;
    callee.program_number = program;
    callee.return_offset = source().next_offset();
    callee.return_line = source().next_line_number();
    callee.repeats_left = repeats;
    callee.own_locals = own_locals;
    callee.modal_call = modal;
    sources_[depth].seek(location.offset, location.line);
    frames_.push_back(std::move(callee));
    if (own_locals) variables_.push_locals(*arguments);
    return std::nullopt;
}

std::optional<Diagnostic> ProgramRunner::return_from_call(const Block& block, std::int64_t sequence) {
    Frame& f = frame();
    std::uint32_t column = 1;
    for (const Word& w : block.words) {
        if (w.letter == 'M') column = w.column;
    }
    // M99 P<n> goes back to the caller's N<n> at once: the repeats still to run are dropped,
    // since N<n> is no line of the called program.
    bool again = frames_.size() == 1 || (f.repeats_left > 1 && sequence < 0);
    if (frames_.size() == 1) {
        // A pass of the main program that made no move and no output would repeat itself for
        // ever (nothing outside the program changes in a simulation): stop it at once.
        if (moves_made_ == moves_at_main_pass_) {
            return alarm_at(block, column, alarm::too_many_blocks,
                            "M99 restarts the main program, whose last pass made no move or output: an endless loop");
        }
        moves_at_main_pass_ = moves_made_;
    }
    if (again) {
        // M99 in the main program starts it again; in a called one it runs the next repeat.
        if (frames_.size() > 1) --f.repeats_left;
        f.loops.clear();
        f.started = false;
        f.jumped_back = true;
        source().seek(f.program.offset, f.program.line);
    } else {
        bool own_locals = f.own_locals;
        std::uint64_t offset = f.return_offset;
        std::uint32_t line = f.return_line;
        frames_.pop_back();
        if (own_locals) variables_.pop_locals();
        source().seek(offset, line);
    }
    if (sequence >= 0) return jump_to_sequence(block, column, sequence);
    return std::nullopt;
}

std::optional<InterpResult> ProgramRunner::run_nc_block(const Block& block, std::vector<Move>& pending) {
    const Block* nc = &block;
    if (!block.exprs.empty()) {
        if (auto error = resolve_words(block, resolved_)) return InterpResult(std::move(*error));
        nc = &resolved_;
    }
    int call_code = 0;
    std::uint32_t call_column = 0;
    const Word* m98 = nullptr;
    const Word* m99 = nullptr;
    int other_g = 0;
    for (const Word& w : nc->words) {
        if (w.letter == 'G' && (w.value == 65 || w.value == 66 || w.value == 67)) {
            if (call_code != 0)
                return InterpResult(alarm_at(*nc, w.column, alarm::call_format, "two of G65 G66 G67 in one block"));
            call_code = static_cast<int>(w.value);
            call_column = w.column;
        } else if (w.letter == 'G') {
            ++other_g;
        } else if (w.letter == 'M' && (w.value == 98 || w.value == 99)) {
            if (m98 != nullptr || m99 != nullptr)
                return InterpResult(alarm_at(*nc, w.column, alarm::format, "M98 and M99 in one block"));
            (w.value == 98 ? m98 : m99) = &w;
        }
    }
    if (call_code == 65 || call_code == 66) {
        if (other_g > 0) {
            return InterpResult(alarm_at(*nc, call_column, alarm::call_format,
                                         fmt::format("G{} cannot share its block with other G codes", call_code)));
        }
        const Word* p = nullptr;
        const Word* l = nullptr;
        for (const Word& w : nc->words) {
            if (w.letter == 'P') p = &w;
            if (w.letter == 'L') l = &w;
        }
        if (p == nullptr) {
            return InterpResult(alarm_at(*nc, call_column, alarm::address_p_missing,
                                         fmt::format("G{} needs P, the program number", call_code)));
        }
        Variables::Locals arguments;
        if (auto error = arguments_of(*nc, arguments)) return InterpResult(std::move(*error));
        int repeats = l != nullptr ? static_cast<int>(code_number(*l)) : 1;
        std::int64_t program = code_number(*p);
        if (call_code == 66) {
            modal_call_ = ModalCall{program, repeats, arguments};
            return std::nullopt;
        }
        if (auto error = call(*nc, call_column, program, repeats, true, &arguments, false))
            return InterpResult(std::move(*error));
        return std::nullopt;
    }
    if (call_code == 67) modal_call_.program = -1;

    // The rest of the block runs first; a call or return it holds follows its motion.
    scan_.clear();
    scan_.location = nc->location;
    scan_.corner = nc->corner;
    const Word* p = nullptr;
    const Word* l = nullptr;
    for (const Word& w : nc->words) {
        bool call_word = &w == m98 || &w == m99 || (w.letter == 'G' && w.value == 67);
        bool call_argument = (m98 != nullptr || m99 != nullptr) && (w.letter == 'P' || w.letter == 'L');
        if (call_argument) (w.letter == 'P' ? p : l) = &w;
        if (!call_word && !call_argument) scan_.words.push_back(w);
    }
    std::size_t before = pending.size();
    bool program_end = false;
    if (!scan_.words.empty()) {
        if (auto error = executor_.run(scan_, pending, program_end)) return InterpResult(std::move(*error));
        moves_made_ += pending.size() - before;
        // G71/G72/G73 used the blocks up to N q: the program goes on after them.
        if (executor_.take_skip_past_sequence() && sequence_end_.offset > source().next_offset()) {
            source().seek(sequence_end_.offset, sequence_end_.line);
        }
    }
    if (program_end) return InterpResult(ProgramEnd{});
    if (m98 != nullptr) {
        if (p == nullptr)
            return InterpResult(
                alarm_at(*nc, m98->column, alarm::address_p_missing, "M98 needs P, the program number"));
        std::int64_t program = code_number(*p);
        int repeats = 1;
        if (l != nullptr) {
            repeats = static_cast<int>(code_number(*l));
        } else if (program >= 10000) {
            // The packed form M98 P<repeats><program>: the last four digits name the program.
            repeats = static_cast<int>(program / 10000);
            program %= 10000;
        }
        if (auto error = call(*nc, m98->column, program, repeats, false, nullptr, false))
            return InterpResult(std::move(*error));
        return std::nullopt;
    }
    if (m99 != nullptr) {
        std::int64_t sequence = p != nullptr ? code_number(*p) : -1;
        if (auto error = return_from_call(*nc, sequence)) return InterpResult(std::move(*error));
        return std::nullopt;
    }
    bool inside_modal_call = false;
    for (const Frame& f : frames_) inside_modal_call = inside_modal_call || f.modal_call;
    if (modal_call_.program >= 0 && !inside_modal_call && moved(pending, before)) {
        if (auto error = call(*nc, 1, modal_call_.program, modal_call_.repeats, true, &modal_call_.arguments, true)) {
            return InterpResult(std::move(*error));
        }
    }
    return std::nullopt;
}

}  // namespace nckit::interp
