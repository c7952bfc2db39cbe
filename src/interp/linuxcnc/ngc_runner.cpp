#include "ngc_runner.hpp"

#include <cmath>
#include <type_traits>

#include <fmt/format.h>

#include "ngc_evaluate.hpp"

namespace nckit::interp::ngc {

namespace {

//! A staged parameter setting: LinuxCNC applies a line's settings together, after reading it.
struct Staged {
    std::int64_t number = 0;  // 0: named
    std::string name;
    double value = 0;
    std::uint32_t column = 0;
};

constexpr std::string_view axis_letters_ngc = "XYZABCUVW";  // LinuxCNC's order of #5061-#5069

}  // namespace

NgcRunner::NgcRunner(const MachineConfig& machine, ProgramSource main, const InterpreterOptions& options)
    : machine_(machine), options_(options), executor_(machine, options_) {
    main_file_ = *main.file();
    auto reader = std::make_unique<ProgramSource>(std::move(main));
    current_ = reader.get();
    files_.emplace(main_file_, std::move(reader));
    frames_.push_back(Frame{});
    connect_live_parameters();
    parameters_.write(5599, 1.0);  // (DEBUG,...) shown, as LinuxCNC starts; its file may say otherwise
    // As LinuxCNC starts: the parameter file first, then RS274NGC_STARTUP_CODE (here the machine
    // file's `startup_gcodes`), whose G54-G59 wins over the file's #5220.
    if (auto error = load_parameter_file()) {
        startup_error_ = std::move(error);
    } else if (auto start_error = executor_.start()) {
        startup_error_ = std::move(start_error);
    }
}

Diagnostic NgcRunner::fail(std::uint32_t column, std::string message) const {
    return error_at(line_.at(column), "ngc-error", std::move(message));
}

std::optional<Diagnostic> NgcRunner::switch_to(const std::string& file, std::uint64_t offset, std::uint32_t line) {
    auto it = files_.find(file);
    if (it == files_.end()) {
        auto opened = ProgramSource::open(file);
        if (!opened) return opened.diagnostics().front();
        it = files_.emplace(file, std::make_unique<ProgramSource>(std::move(opened).value())).first;
    }
    current_ = it->second.get();
    current_->seek(offset, line);
    return std::nullopt;
}

std::optional<InterpResult> NgcRunner::fill(std::vector<Move>& pending) {
    if (startup_error_) return InterpResult(*startup_error_);
    error_is_recoverable_ = false;
    while (pending.empty()) {
        if (auto result = run_line(pending)) return result;
    }
    return std::nullopt;
}

std::optional<InterpResult> NgcRunner::run_line(std::vector<Move>& pending) {
    auto next = source().next();
    if (!next) return InterpResult(next.diagnostics().front());
    const bool in_main = *source().file() == main_file_;
    if (!next.value()) {
        line_.location = make_location(source().file(), source().next_line_number() - 1, 1);
        if (skipping_to_sub_) {
            Diagnostic d = error_at(call_location_, "ngc-error",
                                    fmt::format("subroutine o<{}> not found: not defined before the call, not after "
                                                "it in this file, and no file {}.ngc in the library folders",
                                                skipping_o_, skipping_o_));
            return InterpResult(std::move(d));
        }
        if (!skipping_o_.empty()) {
            return InterpResult(fail(1, fmt::format("file ended while looking for o<{}>: its {} is missing",
                                                    skipping_o_, skipping_to_sub_ ? "sub" : "closing O-word")));
        }
        if (frames_.size() > 1) {
            return InterpResult(fail(1, fmt::format("file ended inside o<{}>: endsub missing", frames_.back().sub)));
        }
        return InterpResult(fail(1, seen_percent_ ? "file ended with no percent sign"
                                                  : "file ended with no percent sign or program end (M2 or M30)"));
    }
    const ProgramSource::Line& text = **next;
    if (in_main && frames_.size() == 1) main_offset_ = source().next_offset();
    if (frames_.size() > 1 || repeating_) {
        if (++counted_lines_ > options_.max_blocks) {
            line_.location = make_location(source().file(), text.number, 1);
            return InterpResult(fail(1, fmt::format("more than {} lines run in loops and calls: a runaway program? "
                                                    "(raise the budget with --max-blocks)",
                                                    options_.max_blocks)));
        }
    }
    line_.location = make_location(source().file(), text.number, 1);
    line_offset_ = text.offset;
    if (auto error = parse_ngc_line(text.text, line_)) {
        // Skipped lines are not read beyond their O-word, as in LinuxCNC.
        if (!skipping_o_.empty() && line_.oword.column == 0) return std::nullopt;
        error_is_recoverable_ = frames_.size() == 1 && skipping_o_.empty();
        return InterpResult(std::move(*error));
    }
    if (line_.percent) {
        if (!seen_line_ && !seen_percent_) {
            seen_percent_ = true;
            return std::nullopt;
        }
        if (skipping_to_sub_) {
            // Nothing after the closing % is read: a sub defined there is not found.
            return InterpResult(error_at(call_location_, "ngc-error",
                                         fmt::format("subroutine {} not found before the closing %",
                                                     fanuc_search_ ? "O" + skipping_o_ : "o<" + skipping_o_ + ">")));
        }
        if (auto error = executor_.end_program(pending)) return InterpResult(std::move(*error));
        return InterpResult(ProgramEnd{});
    }
    if (line_.block_delete && options_.block_delete) return std::nullopt;
    if (line_.empty()) return std::nullopt;
    seen_line_ = true;
    if (line_.oword.label_expr >= 0) {
        // o[expr]: LinuxCNC computes the number as it reads the line. Passing over a sub's
        // definition or a false `if` it leaves the line alone; reading on to find a called sub it
        // computes it, and an undefined parameter there is an error, as in LinuxCNC.
        if (!skipping_o_.empty() && !skipping_to_sub_) return std::nullopt;
        double number = 0;
        if (auto error = evaluate(line_, line_.oword.label_expr, parameters_, number)) {
            return InterpResult(std::move(*error));
        }
        line_.oword.label = fmt::format("{}", static_cast<std::int64_t>(std::lround(number)));
    }
    if (line_.oword.kind != OKind::none) {
        if (auto error = run_oword()) return InterpResult(std::move(*error));
        return std::nullopt;
    }
    if (!skipping_o_.empty()) return std::nullopt;
    if (profile_) {
        if (auto error = collect_profile_line()) return InterpResult(std::move(*error));
        return std::nullopt;
    }
    auto result = run_ordinary(pending);
    if (result && std::holds_alternative<Diagnostic>(*result)) error_is_recoverable_ = frames_.size() == 1;
    return result;
}

std::optional<InterpResult> NgcRunner::run_ordinary(std::vector<Move>& pending) {
    std::vector<Staged> staged;
    for (const Setting& s : line_.settings) {
        Staged out;
        out.column = s.column;
        const Node& target = line_.nodes[static_cast<std::size_t>(s.target)];
        if (target.op == Op::named) {
            out.name = line_.names[static_cast<std::size_t>(target.name)];
        } else if (auto error = parameter_number(line_, s.target, parameters_, out.number)) {
            return InterpResult(std::move(*error));
        }
        if (auto error = evaluate(line_, s.value, parameters_, out.value)) return InterpResult(std::move(*error));
        staged.push_back(std::move(out));
    }
    if (auto error = resolve_block()) return InterpResult(std::move(*error));
    if (auto error = comments()) return InterpResult(std::move(*error));
    for (const Staged& s : staged) {
        if (s.number != 0) {
            parameters_.write(s.number, s.value);
        } else if (!parameters_.write_named(s.name, s.value)) {
            return InterpResult(fail(s.column, fmt::format("cannot assign to read-only parameter #<{}>", s.name)));
        }
    }
    if (block_.words.empty()) return std::nullopt;
    for (const Word& w : block_.words) {
        if (w.letter == 'M' && (w.value == 98 || w.value == 99)) return run_fanuc_sub_words(pending);
    }
    // G38.2-G38.5 probe as LinuxCNC's rs274 simulates it: a straight feed to the programmed
    // point (nothing trips on the way) that leaves that point in #5061-#5069 and 0 in #5070.
    bool probing = false;
    bool probe_must_move = false;  // G38.2 and G38.4 (not G38.3, G38.5) refuse a probe to where they stand
    for (Word& w : block_.words) {
        if (w.letter == 'G' && w.value >= 38.15 && w.value <= 38.55) {
            probe_must_move = std::abs(w.value - 38.2) < 1e-6 || std::abs(w.value - 38.4) < 1e-6;
            w.value = 1;
            probing = true;
        }
    }
    if (g7x_word() != nullptr) return run_g7x(pending);
    if (take_spline_block()) return run_spline(pending);
    if (auto error = read_inverse_time()) return InterpResult(std::move(*error));
    if (auto error = translate_g92_kept()) return InterpResult(std::move(*error));
    if (auto error = translate_block()) return InterpResult(std::move(*error));
    bool program_end = false;
    const std::size_t first_new = pending.size();
    for (std::size_t i = 0; i < run_list_.size() && !program_end; ++i) {
        const std::size_t mark = pending.size();
        if (auto error = executor_.run(run_list_[i], pending, program_end)) return InterpResult(std::move(*error));
        // A polar cycle's repeat is one turn of LinuxCNC's L loop, which does not rise to R
        // again: the Executor, seeing a new block, does (a move of no length); it goes.
        const Line* rise =
            i >= repeats_from_ && mark < pending.size() ? std::get_if<Line>(&pending[mark].what) : nullptr;
        if (rise != nullptr && rise->rapid && rise->from == rise->to) {
            pending.erase(pending.begin() + static_cast<std::ptrdiff_t>(mark));
        }
    }
    apply_inverse_time(pending, first_new);
    if (probing && probe_must_move) {
        // LinuxCNC 2.9 refuses G38.2/G38.4 to the very point where its interpreter stands (every
        // axis equal); G38.3/G38.5 there, and any probe of some length, run. After a probe that
        // point is the backed-off one, not the tool's (below), so the check comes before the
        // move is made to start where the tool is.
        for (std::size_t i = first_new; i < pending.size(); ++i) {
            const auto* line = std::get_if<Line>(&pending[i].what);
            if (line != nullptr && line->to == line->from) {
                return InterpResult(fail(1, "start point too close to probe point (G38.2/G38.4 to where the tool is)"));
            }
        }
    }
    // The probe's start as the interpreter knows it (backed off after an earlier probe): rs274
    // backs off along the probe's direction from there, not from where the tool stands.
    probe_start_.reset();
    for (std::size_t i = first_new; probing && i < pending.size(); ++i) {
        if (const auto* line = std::get_if<Line>(&pending[i].what)) probe_start_ = line->from;
    }
    follow_linuxcnc_tapping(pending, first_new);
    if (probing) {
        // Plain parameters from here on, as LinuxCNC sets them after a probe: a program may
        // set #5070 itself (to 1 before a `while [#5070 NE 0]` loop of probes).
        for (std::size_t i = 0; i < axis_letters_ngc.size(); ++i) {
            parameters_.write(5061 + static_cast<std::int64_t>(i), axis_position(axis_letters_ngc[i]).value_or(0.0));
        }
        parameters_.write(5070, 0.0);  // rs274 simulates a probe that never trips
        if (auto error = back_off_after_probe(pending, first_new)) return InterpResult(std::move(*error));
    }
    if (program_end) return InterpResult(ProgramEnd{});
    return std::nullopt;
}

std::optional<Diagnostic> NgcRunner::back_off_after_probe(std::vector<Move>& pending, std::size_t first_new) {
    // rs274 goes on from 0.01 in (0.254 mm) short of the probed point, back along the probe's
    // direction, though the tool stands at the point: nckit's position moves there without a
    // move (an incremental rapid run and dropped), and the next move starts at the point.
    const Line* probe = nullptr;
    for (std::size_t i = first_new; i < pending.size(); ++i) {
        if (const auto* line = std::get_if<Line>(&pending[i].what)) probe = line;
    }
    if (probe == nullptr) return std::nullopt;
    const AxisVector point = probe->to;
    const AxisVector start = probe_start_.value_or(probe->from);
    double back[3] = {start[Axis::X] - point[Axis::X], start[Axis::Y] - point[Axis::Y],
                      start[Axis::Z] - point[Axis::Z]};
    const double length = std::sqrt(back[0] * back[0] + back[1] * back[1] + back[2] * back[2]);
    if (length == 0) {  // a probe of no length in X Y Z backs off nowhere (rs274's canon)
        tool_at_ = point;
        return std::nullopt;
    }
    const ModalView view = executor_.modal_view();
    Block shift;
    shift.location = line_.location;
    shift.words = {Word{'G', 91.0, true, 1, -1}, Word{'G', 0.0, true, 1, -1}};
    const char letters[3] = {'X', 'Y', 'Z'};
    for (int a = 0; a < 3; ++a) {
        const double by_mm = 0.254 * back[a] / length;
        if (by_mm != 0.0) shift.words.push_back(Word{letters[a], by_mm / view.length_factor_mm, true, 1, -1});
    }
    const std::size_t mark = pending.size();
    bool program_end = false;
    if (auto error = executor_.run(shift, pending, program_end)) return error;
    pending.erase(pending.begin() + static_cast<std::ptrdiff_t>(mark), pending.end());
    Block restore;
    restore.location = line_.location;
    restore.words = {Word{'G', 1.0, true, 1, -1}};
    if (!view.incremental) restore.words.push_back(Word{'G', 90.0, true, 1, -1});
    if (auto error = executor_.run(restore, pending, program_end)) return error;
    tool_at_ = point;
    return std::nullopt;
}

void NgcRunner::follow_linuxcnc_tapping(std::vector<Move>& pending, std::size_t first_new) {
    // LinuxCNC 2.9 sends G74/G84's two feeds under G18 and G19 to the point with X, Y, Z turned
    // round (G18: X gets the Y value, Y the Z value, Z the X value; G19: X gets Z, Y gets X, Z
    // gets Y) while its interpreter goes on from the point the cycle meant. The moves here are
    // LinuxCNC's: those feeds turned, and the move after each starting where the tool then is.
    const ModalView view = executor_.modal_view();
    const bool tapping = (view.motion_code == 840 || view.motion_code == 740) && view.plane != Plane::xy;
    for (std::size_t i = first_new; i < pending.size(); ++i) {
        std::visit(
            [&](auto& m) {
                if constexpr (requires { m.from; }) {
                    if (tool_at_) m.from = *tool_at_;
                    tool_at_.reset();
                }
                if constexpr (std::is_same_v<std::decay_t<decltype(m)>, Line>) {
                    if (!tapping || m.rapid) return;
                    const AxisVector meant = m.to;
                    const bool zx = view.plane == Plane::zx;
                    m.to[Axis::X] = zx ? meant[Axis::Y] : meant[Axis::Z];
                    m.to[Axis::Y] = zx ? meant[Axis::Z] : meant[Axis::X];
                    m.to[Axis::Z] = zx ? meant[Axis::X] : meant[Axis::Y];
                    tool_at_ = m.to;
                }
            },
            pending[i].what);
    }
}

std::optional<Diagnostic> NgcRunner::resolve_block() {
    block_.clear();
    block_.location = line_.location;
    for (const NgcWord& w : line_.words) {
        double value = 0;
        if (auto error = evaluate(line_, w.expr, parameters_, value)) return error;
        if (w.letter == 'G') {
            // G codes are read to a tenth: G38.2 is 382 tenths; G1.23 is no code.
            double tenths = std::round(value * 10.0);
            if (std::abs(value * 10.0 - tenths) > 1e-4) {
                return fail(w.column, fmt::format("G{} is no G code (G codes are read to a tenth)", value));
            }
            value = tenths / 10.0;
        }
        block_.words.push_back(Word{w.letter, value, true, w.column, -1});
    }
    return std::nullopt;
}

std::optional<Diagnostic> NgcRunner::comments() {
    for (const Comment& c : line_.comments) {
        if (c.kind == CommentKind::plain) continue;
        std::string text = c.text;
        if (c.kind == CommentKind::print || c.kind == CommentKind::debug || c.kind == CommentKind::abort) {
            text = substitute_parameters(text);
        }
        if (c.kind == CommentKind::abort) return fail(c.column, fmt::format("abort: {}", text));
        // LinuxCNC shows (MSG,...) to the operator, and (DEBUG,...) as well while #5599 (its
        // debug switch, 1 at start-up) is above 0; (PRINT,...) goes to its standard output only.
        const bool shown = c.kind == CommentKind::msg || (c.kind == CommentKind::debug && parameters_.read(5599) > 0);
        if (shown && options_.on_message) options_.on_message(line_.at(c.column), text);
        if (options_.on_warning) {
            Diagnostic note = error_at(line_.at(c.column), c.kind == CommentKind::msg ? "ngc-msg" : "ngc-print", text);
            note.severity = Severity::note;
            options_.on_warning(note);
        }
    }
    return std::nullopt;
}

}  // namespace nckit::interp::ngc
