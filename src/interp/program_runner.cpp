#include "program_runner.hpp"

#include <cmath>

#include <fmt/format.h>

#include "macro/retained_store.hpp"
#include "nckit/gcode/macro_alarms.hpp"
#include "nckit/gcode/parser.hpp"

namespace nckit::interp {

namespace {
//! O and N numbers have at most 8 digits (as the library and GOTO searches read them).
constexpr double max_label_number = 99999999;
}  // namespace

namespace {

constexpr std::size_t max_call_depth = 10;  // subprogram levels, macros included
constexpr double seconds_per_hour = 3600.0;
constexpr double timer_wrap_ms = 4294967296.0;  // #3001 wraps like a 32-bit millisecond counter
constexpr int max_user_alarm = 9999;            // #3000 = n, n up to this

bool starts_with_block_delete(std::string_view line) {
    std::size_t i = line.find_first_not_of(" \t");
    return i != std::string_view::npos && line[i] == '/';
}

bool is_axis_or_offset_letter(char letter) {
    return axis_from_letter(letter).has_value() || letter == 'I' || letter == 'J' || letter == 'K' || letter == 'R';
}

//! Addresses whose least increment is 1: M S T D H L N O.
bool is_whole_number_letter(char letter) {
    return letter == 'M' || letter == 'S' || letter == 'T' || letter == 'D' || letter == 'H' || letter == 'L' ||
           letter == 'N' || letter == 'O';
}

//! The text of an operator message comment `(MSG, text)` (MSG in any case, blanks allowed
//! before it and after the comma, as LinuxCNC reads it), or nothing for any other comment.
std::optional<std::string> operator_message(std::string_view comment) {
    std::size_t i = comment.find_first_not_of(" \t");
    if (i == std::string_view::npos || comment.size() < i + 4) return std::nullopt;
    for (std::size_t k = 0; k < 3; ++k) {
        const char c = comment[i + k];
        if (c != "MSG"[k] && c != "msg"[k]) return std::nullopt;
    }
    if (comment[i + 3] != ',') return std::nullopt;
    std::string_view text = comment.substr(i + 4);
    const std::size_t start = text.find_first_not_of(" \t");
    return std::string(start == std::string_view::npos ? std::string_view{} : text.substr(start));
}

}  // namespace

ProgramRunner::ProgramRunner(const MachineConfig& machine, ProgramSource main, const InterpreterOptions& options)
    : machine_(machine), options_(options), executor_(machine, options_), library_(options.library_dir) {
    eval_settings_.least_increment_input = machine.decimal_point_input == DecimalPointInput::least_increment;
    variables_.set_system(this);
    sources_.reserve(max_call_depth + 1);
    ProgramLocation location{*main.file(), true, 0, 1};
    sources_.push_back(std::move(main));
    Frame main_frame;
    main_frame.program = location;
    frames_.push_back(std::move(main_frame));
    executor_.set_sequence_reader(
        [this](std::int64_t p, std::int64_t q, std::vector<Block>& out) { return read_sequence(p, q, out); });
    if (auto error = executor_.start()) startup_error_ = std::move(*error);
    if (!startup_error_ && options_.retained_start) {
        RetainedValues values{};
        for (const RetainedVariable& v : *options_.retained_start) {
            if (v.number >= first_retained && v.number <= last_retained) {
                values[static_cast<std::size_t>(v.number - first_retained)] = MacroValue::of(v.value);
            }
        }
        variables_.set_retained(values);
    } else if (!startup_error_ && !options_.retained_file.empty()) {
        auto retained = load_retained(options_.retained_file);
        if (retained) {
            variables_.set_retained(*retained);
        } else {
            startup_error_ = retained.diagnostics().front();
        }
    }
}

Diagnostic ProgramRunner::alarm_at(const Block& block, std::uint32_t column, int alarm, std::string message) const {
    Diagnostic d = error_at(block.at_column(column == 0 ? 1 : column), "macro-alarm", std::move(message));
    d.alarm = alarm;
    return d;
}

std::vector<RetainedVariable> ProgramRunner::retained_values() const {
    std::vector<RetainedVariable> out;
    const RetainedValues& values = variables_.retained();
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (!values[i].vacant) out.push_back({first_retained + static_cast<int>(i), values[i].number});
    }
    return out;
}

std::optional<Diagnostic> ProgramRunner::save_retained() const {
    if (options_.retained_start || options_.retained_file.empty() || !options_.save_retained ||
        !variables_.retained_changed()) {
        return std::nullopt;
    }
    return interp::save_retained(options_.retained_file, variables_.retained());
}

bool ProgramRunner::repeating() const {
    const Frame& f = frames_.back();
    return frames_.size() > 1 || !f.loops.empty() || f.jumped_back;
}

const Block* ProgramRunner::cached_block() {
    auto it = block_cache_.find(CacheKey{source().file().get(), source().next_offset()});
    if (it == block_cache_.end()) return nullptr;
    line_offset_ = it->first.offset;
    source().seek(it->second.next_offset, it->second.next_line);
    return &it->second.block;
}

const Block* ProgramRunner::remember(const Block& block) {
    // Bounded: a program that runs through more distinct looping blocks than this starts over.
    if (block_cache_.size() >= max_cached_blocks) block_cache_.clear();
    CachedBlock& entry = block_cache_[CacheKey{source().file().get(), line_offset_}];
    entry.file = source().file();
    entry.block = block;
    entry.next_offset = source().next_offset();
    entry.next_line = source().next_line_number();
    return &entry.block;
}

std::optional<InterpResult> ProgramRunner::fill(std::vector<Move>& pending) {
    if (startup_error_) return InterpResult(*startup_error_);
    error_is_recoverable_ = false;
    while (pending.empty()) {
        // Blocks run again (loops, jumps back, calls) come parsed from the cache.
        const Block* block = repeating() ? cached_block() : nullptr;
        if (block == nullptr) {
            auto line = source().next();
            if (!line) return InterpResult(line.diagnostics().front());
            const bool in_call = frames_.size() > 1;
            if (!line.value()) {
                if (!in_call) return finish_main(pending);
                block_.location = make_location(source().file(), source().next_line_number(), 1);
                return InterpResult(alarm_at(block_, 1, alarm::format,
                                             fmt::format("program O{} ends without M99", frame().program_number)));
            }
            if (!leader_checked_ && !in_call) {
                leader_checked_ = true;
                if ((**line).number == 1 && source().rereadable()) {
                    if (is_leader(**line)) continue;
                    line = source().next();  // line 1 again: is_leader() read past it
                    if (!line) return InterpResult(line.diagnostics().front());
                    if (!line.value()) return finish_main(pending);
                }
            }
            const ProgramSource::Line& text = **line;
            if (options_.block_delete && starts_with_block_delete(text.text)) {
                seen_block_ = true;
                continue;  // skipped unread: a deleted block is not part of the program
            }
            block_.location = make_location(source().file(), text.number, 1);
            line_offset_ = text.offset;
            if (auto error = parse_block(text.text, block_)) {
                error_is_recoverable_ = !in_call;  // the reader stands at the next line
                return InterpResult(std::move(*error));
            }
            if (block_.tape_mark) {
                if (in_call) {
                    // A library file may open with '%', as a punched tape does: it comes before the program.
                    if (!frame().started) continue;
                    return InterpResult(alarm_at(block_, 1, alarm::format, "'%' inside a called program: M99 missing"));
                }
                // A leading '%' opens the tape; any later one closes it and ends the program.
                if (seen_tape_mark_ || seen_block_) return finish_main(pending);
                seen_tape_mark_ = true;
                // The program proper starts after the tape mark: M99 in the main program restarts here.
                frames_[0].program.offset = source().next_offset();
                frames_[0].program.line = source().next_line_number();
                continue;
            }
            if (block_.words.empty() && block_.statement.kind == StatementKind::none) {
                // A block of only a comment does nothing, unless it is an operator message.
                if (options_.on_message) {
                    if (auto message = operator_message(block_.comment)) options_.on_message(block_.location, *message);
                }
                continue;
            }
            block = repeating() ? remember(block_) : &block_;
        }
        seen_block_ = true;
        current_block_ = block;
        if (auto result = run_block(*block, pending)) {
            const auto* error = std::get_if<Diagnostic>(&*result);
            error_is_recoverable_ = error != nullptr && frames_.size() == 1 && error->alarm != alarm::too_many_blocks;
            return result;
        }
    }
    return std::nullopt;
}

std::optional<InterpResult> ProgramRunner::run_block(const Block& block, std::vector<Move>& pending) {
    Frame& current = frame();
    if (!block.words.empty() && (block.words.front().letter == 'O' || block.words.front().letter == 'N')) {
        // Checked before any cast to an integer: O and N numbers have at most 8 digits.
        const Word& first = block.words.front();
        if (!(first.value >= 0 && first.value <= max_label_number) || first.value != std::floor(first.value)) {
            return InterpResult(alarm_at(
                block, first.column, alarm::format,
                fmt::format("{} number {} is not a whole number 0-{}", first.letter, first.value, max_label_number)));
        }
    }
    if (!block.words.empty() && block.words.front().letter == 'O') {
        // A program's own O line is its header; reaching the next program's ends this one.
        if (!current.started) {
            current.started = true;
            current.program_number = static_cast<std::int64_t>(block.words.front().value);
            return std::nullopt;
        }
        if (frames_.size() == 1) return finish_main(pending);
        return InterpResult(
            alarm_at(block, 1, alarm::format,
                     fmt::format("program O{} runs into the next program without M99", current.program_number)));
    }
    current.started = true;
    if (frames_.size() > 1 || !current.loops.empty() || current.jumped_back) {
        if (++counted_blocks_ > options_.max_blocks) {
            return InterpResult(alarm_at(block, 1, alarm::too_many_blocks,
                                         fmt::format("more than {} blocks run in loops and calls: a runaway "
                                                     "program? (raise the budget with --max-blocks)",
                                                     options_.max_blocks)));
        }
    }
    if (!block.words.empty() && block.words.front().letter == 'N') {
        last_sequence_ = static_cast<std::int64_t>(block.words.front().value);
    }
    if (options_.on_message) {
        if (auto text = operator_message(block.comment)) options_.on_message(block.location, *text);
    }
    if (block.statement.kind != StatementKind::none) {
        if (auto error = run_statement(block)) return InterpResult(std::move(*error));
        if (stop_requested_) program_stop(block, pending);
        return std::nullopt;
    }
    return run_nc_block(block, pending);
}

std::optional<Diagnostic> ProgramRunner::resolve_words(const Block& block, Block& resolved) {
    resolved.clear();
    resolved.location = block.location;
    resolved.comment = block.comment;
    resolved.corner = block.corner;
    const bool inch = executor_.inch_units();
    for (const Word& word : block.words) {
        if (word.expr < 0) {
            resolved.words.push_back(word);
            continue;
        }
        MacroValue value;
        if (auto error = evaluate(block, word.expr, variables_, eval_settings_, value)) return error;
        if (value.vacant) continue;  // a word whose variable is vacant is left out
        Word out = word;
        out.expr = -1;
        double v = value.number;
        // Rounded to the address's least input increment, as the control does; only G takes
        // the integer part (G#10 with #10 = 1.7 is G1, but M#10 is M2).
        if (word.letter == 'G') {
            v = std::trunc(v);
        } else if (is_whole_number_letter(word.letter)) {
            v = round_half_away(v);
        } else if (is_axis_or_offset_letter(word.letter)) {
            auto axis = axis_from_letter(word.letter);
            const AxisConfig* config = axis ? machine_.find(*axis) : nullptr;
            bool rotary = config != nullptr && config->kind == AxisKind::rotary;
            // Dividing by the count per unit (1000 exactly) gives the very double `X1.235` reads
            // as; multiplying by 0.001 is one bit off for many values (X0.009).
            double per_unit = (inch && !rotary) ? 1e4 : 1e3;
            v = round_half_away(v * per_unit) / per_unit;
        }
        out.value = v;
        resolved.words.push_back(out);
    }
    return std::nullopt;
}

void ProgramRunner::program_stop(const Block& block, std::vector<Move>& pending) {
    stop_requested_ = false;
    Io stop{IoKind::mcode, 0, 0};
    stop.waits = true;
    // The message first: it is shown when the program stops.
    if (options_.on_message) options_.on_message(block.location, block.comment);
    pending.push_back(Move{stop, block.location, last_sequence_});
    if (options_.on_warning) {
        Diagnostic note = error_at(block.at_column(block.statement.column), "program-stop",
                                   fmt::format("#3006 program stop: {}", block.comment));
        note.severity = Severity::warning;
        options_.on_warning(note);
    }
}

std::optional<MacroValue> ProgramRunner::read_system(std::int64_t number) const {
    switch (number) {
        case 3000:
            return MacroValue{};
        case 3001: {
            double ms = (executor_.elapsed_s() - timer_ms_base_s_) * 1000.0;
            return MacroValue::of(std::fmod(std::floor(ms), timer_wrap_ms));
        }
        case 3002:
            return MacroValue::of((executor_.elapsed_s() - timer_hours_base_s_) / seconds_per_hour);
        case 4012:
            return MacroValue::of(modal_call_.program >= 0 ? 66 : 67);
        case 4114:
            return MacroValue::of(static_cast<double>(last_sequence_));
        case 4115:
            return MacroValue::of(static_cast<double>(frames_.back().program_number));
        default:
            return executor_.read_system(number);
    }
}

std::optional<SystemVariables::WriteError> ProgramRunner::write_system(std::int64_t number, double value) {
    switch (number) {
        case 3000: {
            // #3000 = n (MESSAGE) stops the program with alarm 3000 + n and the message. A negative
            // n would read as another alarm (2999, ...); controls take 0 up to 200 .. 9999.
            double rounded = round_half_away(value);
            if (!(rounded >= 0 && rounded <= max_user_alarm)) {
                return WriteError{alarm::argument_range, fmt::format("#3000 = {}: the user alarm number must be "
                                                                     "0 to {}",
                                                                     value, max_user_alarm)};
            }
            auto n = static_cast<int>(rounded);
            const std::string& comment = current_block_->comment;
            std::string message = comment.empty() ? "user alarm" : comment;
            return WriteError{alarm::user_base + n, message};
        }
        case 3001:
            timer_ms_base_s_ = executor_.elapsed_s() - value / 1000.0;
            return std::nullopt;
        case 3002:
            timer_hours_base_s_ = executor_.elapsed_s() - value * seconds_per_hour;
            return std::nullopt;
        case 3003:
        case 3004:
            return std::nullopt;  // single-block / feed-hold suppression: nothing to suppress here
        case 3006: {
            // #3006 = 1 (MESSAGE): stop as M0 does, showing the message; cycle start goes on.
            if (current_block_->comment.empty()) {
                return WriteError{alarm::format, "#3006 needs its message in a comment: #3006 = 1 (TEXT)"};
            }
            stop_requested_ = true;
            return std::nullopt;
        }
        default:
            return executor_.write_system(number, value);
    }
}

}  // namespace nckit::interp
