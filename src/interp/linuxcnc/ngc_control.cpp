// O-word subroutines and control flow with LinuxCNC's semantics: a label is recorded when its
// line is first read; a false condition, `break` or a call to a sub not yet seen skips forward
// to the matching label; a loop's end and a call to a recorded sub seek back to it. Labels of
// control statements are local to the sub they stand in (`sub#label`), sub names are global.
#include <fmt/format.h>

#include "ngc_evaluate.hpp"
#include "ngc_runner.hpp"

namespace nckit::interp::ngc {

namespace {

constexpr std::size_t max_call_levels = 10;  // LinuxCNC's INTERP_SUB_ROUTINE_LEVELS

std::string_view kind_name(OKind kind) {
    switch (kind) {
        case OKind::sub:
            return "sub";
        case OKind::do_:
            return "do";
        case OKind::while_:
            return "while";
        case OKind::repeat:
            return "repeat";
        case OKind::if_:
            return "if";
        default:
            return "label";
    }
}

bool is_global(OKind kind) {
    return kind == OKind::sub || kind == OKind::endsub || kind == OKind::call || kind == OKind::return_ ||
           kind == OKind::bare;
}

}  // namespace

std::string NgcRunner::full_name() const {
    const OWord& o = line_.oword;
    if (o.kind == OKind::bare && !o.named) {
        // A Fanuc-style O number: O0002 is the block M98 P2 calls.
        const std::size_t digit = o.label.find_first_not_of('0');
        return digit == std::string::npos ? std::string("0") : o.label.substr(digit);
    }
    if (is_global(o.kind)) return o.label;
    const std::string& prefix = frames_.size() > 1 ? frames_.back().sub : defining_sub_ ? sub_name_ : std::string();
    return prefix + "#" + o.label;
}

std::optional<Diagnostic> NgcRunner::condition(double& value) {
    return evaluate(line_, line_.oword.expr, parameters_, value);
}

std::optional<Diagnostic> NgcRunner::save_label(const std::string& name) {
    if (auto it = labels_.find(name); it != labels_.end()) {
        const Label& seen = it->second;
        if (seen.file == *source().file() && seen.line == line_.location.line) return std::nullopt;
        return fail(line_.oword.column,
                    fmt::format("redefining {}: already defined at {}:{}", line_.oword.shown(), seen.file, seen.line));
    }
    labels_[name] = Label{line_.oword.kind, *source().file(), line_offset_, line_.location.line, -1};
    return std::nullopt;
}

std::optional<Diagnostic> NgcRunner::check_label(const std::string& name, std::initializer_list<OKind> kinds,
                                                 Label*& out) {
    auto it = labels_.find(name);
    const std::string label = line_.oword.shown();
    if (it == labels_.end()) return fail(line_.oword.column, fmt::format("undefined O-word label: {}", label));
    for (OKind k : kinds) {
        if (it->second.kind == k) {
            out = &it->second;
            return std::nullopt;
        }
    }
    return fail(line_.oword.column,
                fmt::format("no matching {} for {}: that label is a '{}' at line {}", kind_name(*kinds.begin()), label,
                            kind_name(it->second.kind), it->second.line));
}

std::optional<Diagnostic> NgcRunner::back_to(const std::string& name) {
    const Label& label = labels_.at(name);
    repeating_ = true;
    return switch_to(label.file, label.offset, label.line);
}

std::optional<std::filesystem::path> NgcRunner::find_sub_file(const std::string& name) const {
    std::vector<std::filesystem::path> dirs;
    if (!options_.library_dir.empty()) dirs.push_back(options_.library_dir);
    for (const auto& dir : options_.subroutine_path) dirs.push_back(dir);
    dirs.push_back(std::filesystem::path(main_file_).parent_path());
    for (const auto& dir : dirs) {
        std::filesystem::path candidate = (dir.empty() ? std::filesystem::path(".") : dir) / (name + ".ngc");
        std::error_code ec;
        if (std::filesystem::is_regular_file(candidate, ec)) return candidate;
    }
    return std::nullopt;
}

std::optional<Diagnostic> NgcRunner::call_sub(const std::string& name) {
    if (frames_.size() >= max_call_levels) {
        return fail(line_.oword.column,
                    fmt::format("too many nested subroutine calls (more than {})", max_call_levels - 1));
    }
    std::vector<double> arguments;
    for (std::int32_t arg : line_.oword.args) {
        double v = 0;
        if (auto error = evaluate(line_, arg, parameters_, v)) return error;
        arguments.push_back(v);
    }
    if (arguments.size() > call_arguments) {
        return fail(line_.oword.column, fmt::format("too many subroutine parameters (at most {})", call_arguments));
    }
    Frame frame{name, *source().file(), source().next_offset(), source().next_line_number()};
    const bool from_main_file = *source().file() == main_file_;
    parameters_.enter_call(arguments);
    frames_.push_back(std::move(frame));
    parameters_.set_return_value(std::nullopt);
    repeating_ = true;
    call_location_ = line_.at(line_.oword.column);
    if (auto it = labels_.find(name); it != labels_.end() && it->second.kind == OKind::sub) {
        return switch_to(it->second.file, it->second.offset, it->second.line);
    }
    if (auto file = find_sub_file(name)) {
        if (auto error = switch_to(file->string(), 0, 1)) return error;
    } else if (!from_main_file) {
        return fail(line_.oword.column, fmt::format("subroutine {} not found: not defined before and no file {}.ngc "
                                                    "in the library folders",
                                                    line_.oword.shown(), name));
    }
    skipping_o_ = name;
    skipping_to_sub_ = true;
    return std::nullopt;
}

std::optional<Diagnostic> NgcRunner::return_from_sub() {
    Frame frame = frames_.back();
    frames_.pop_back();
    parameters_.leave_call();
    return switch_to(frame.return_file, frame.return_offset, frame.return_line);
}

std::optional<Diagnostic> NgcRunner::run_oword() {
    const OWord& o = line_.oword;
    const std::string name = full_name();
    const bool skipping = !skipping_o_.empty();
    const bool skipping_other = skipping && skipping_o_ != name;
    switch (o.kind) {
        case OKind::sub:
        case OKind::bare: {
            if (defining_sub_) {
                return fail(o.column, fmt::format("nested subroutine definition: {} inside {}", o.shown(), sub_name_));
            }
            if (frames_.size() > 1 && !skipping && frames_.back().sub != name) {
                return fail(o.column, fmt::format("nested subroutine definition: {} sub found inside the called "
                                                  "subroutine {}",
                                                  o.shown(), frames_.back().sub));
            }
            if (skipping_other) return std::nullopt;
            if (o.kind == OKind::bare) {
                // A Fanuc-style program number: nothing to do, unless a call is looking for it.
                if (!skipping || !skipping_to_sub_) return std::nullopt;
                if (!fanuc_search_) {
                    return fail(o.column, fmt::format("{} is a Fanuc-style sub: call it with M98 P{}, not with "
                                                      "`call`",
                                                      o.shown(), name));
                }
                if (auto error = save_label(name)) return error;
                skipping_o_.clear();
                skipping_to_sub_ = false;
                fanuc_search_ = false;
                return std::nullopt;
            }
            if (skipping && fanuc_search_) {
                return fail(o.column,
                            fmt::format("{} sub is called with `{} call`, not with M98", o.shown(), o.shown()));
            }
            if (skipping) {
                // The forward search for a call's sub ends here: record it, run its body.
                if (auto error = save_label(name)) return error;
                skipping_o_.clear();
                skipping_to_sub_ = false;
                return std::nullopt;
            }
            if (frames_.size() > 1) return std::nullopt;  // a call came back to the recorded sub line
            if (auto error = save_label(name)) return error;
            skipping_o_ = name;
            defining_sub_ = true;
            sub_name_ = name;
            return std::nullopt;
        }
        case OKind::endsub:
        case OKind::return_: {
            if (skipping_other) return std::nullopt;
            // Passing over a definition evaluates nothing: `endsub [#<result>]` names parameters
            // that exist only once the sub runs, as in LinuxCNC.
            if (!skipping) {
                std::optional<double> value;
                if (o.expr >= 0) {
                    double v = 0;
                    if (auto error = condition(v)) return error;
                    value = v;
                }
                parameters_.set_return_value(value);
            }
            if (frames_.size() == 1 && sub_name_.empty()) {
                return fail(o.column, fmt::format("not in a subroutine definition: {} {}", o.shown(),
                                                  o.kind == OKind::endsub ? "endsub" : "return"));
            }
            if (skipping && o.kind == OKind::endsub) skipping_o_.clear();
            if (frames_.size() > 1) return return_from_sub();
            if (o.kind == OKind::endsub) {
                defining_sub_ = false;
                sub_name_.clear();
                skipping_o_.clear();
            }
            return std::nullopt;
        }
        case OKind::call:
            if (skipping) return std::nullopt;
            return call_sub(name);
        default:
            break;
    }
    if (skipping_other || (skipping_to_sub_ && skipping)) return std::nullopt;
    auto here = [&](const Label& label) { return label.file == *source().file() && label.line == line_.location.line; };
    auto duplicate = [&](const Label& label) {
        return fail(o.column, fmt::format("duplicate O-word label {}: already used at line {}", o.shown(), label.line));
    };
    Label* label = nullptr;
    switch (o.kind) {
        case OKind::do_:
            skipping_o_.clear();
            if (!labels_.contains(name)) return save_label(name);
            return std::nullopt;
        case OKind::while_: {
            double holds = 0;
            if (auto error = condition(holds)) return error;
            auto it = labels_.find(name);
            if (it != labels_.end() && it->second.kind != OKind::do_ && !here(it->second)) return duplicate(it->second);
            if (it == labels_.end()) {
                if (auto error = save_label(name)) return error;
                it = labels_.find(name);
            }
            skipping_o_.clear();
            if (it->second.kind == OKind::while_) {
                if (holds == 0) skipping_o_ = name;
                return std::nullopt;
            }
            // The `while` closing a `do`: go round again while the condition holds.
            doing_continue_ = false;
            if (holds != 0 && !doing_break_) return back_to(name);
            doing_break_ = false;
            return std::nullopt;
        }
        case OKind::repeat: {
            double count = 0;
            if (auto error = condition(count)) return error;
            auto it = labels_.find(name);
            if (it != labels_.end() && !here(it->second)) return duplicate(it->second);
            if (it == labels_.end()) {
                if (auto error = save_label(name)) return error;
                it = labels_.find(name);
            }
            skipping_o_.clear();
            Label& loop = it->second;
            if (loop.repeat_count == -1) loop.repeat_count = static_cast<int>(std::lround(std::max(count, -1.0)));
            if (loop.repeat_count > 0) {
                --loop.repeat_count;
            } else {
                skipping_o_ = name;
                loop.repeat_count = -1;
            }
            return std::nullopt;
        }
        case OKind::if_: {
            double holds = 0;
            if (auto error = condition(holds)) return error;
            auto it = labels_.find(name);
            if (it != labels_.end() && !here(it->second)) return duplicate(it->second);
            if (it == labels_.end()) {
                if (auto error = save_label(name)) return error;
            }
            executed_if_ = holds != 0;
            skipping_o_ = executed_if_ ? std::string() : name;
            return std::nullopt;
        }
        case OKind::elseif: {
            if (auto error = check_label(name, {OKind::if_}, label)) return error;
            double holds = 0;
            if (auto error = condition(holds)) return error;
            if (executed_if_) {
                skipping_o_ = name;
            } else if (holds != 0) {
                skipping_o_.clear();
                executed_if_ = true;
            }
            return std::nullopt;
        }
        case OKind::else_:
            if (auto error = check_label(name, {OKind::if_}, label)) return error;
            if (executed_if_) {
                skipping_o_ = name;
            } else if (skipping_o_ == name) {
                skipping_o_.clear();
                executed_if_ = true;
            }
            return std::nullopt;
        case OKind::endif:
            if (auto error = check_label(name, {OKind::if_}, label)) return error;
            skipping_o_.clear();
            executed_if_ = true;
            return std::nullopt;
        case OKind::break_:
            if (auto error = check_label(name, {OKind::while_, OKind::do_}, label)) return error;
            skipping_o_ = name;
            doing_break_ = true;
            return std::nullopt;
        case OKind::continue_:
            if (auto error = check_label(name, {OKind::while_, OKind::do_}, label)) return error;
            if (skipping_o_ != name) {
                skipping_o_ = name;
                doing_continue_ = true;
            }
            return std::nullopt;
        case OKind::endwhile:
        case OKind::endrepeat: {
            const OKind opener = o.kind == OKind::endwhile ? OKind::while_ : OKind::repeat;
            if (auto error = check_label(name, {opener}, label)) return error;
            if (skipping_o_ == name) {
                skipping_o_.clear();
                doing_break_ = false;
                if (!doing_continue_) return std::nullopt;  // the loop is over
                doing_continue_ = false;
            }
            return back_to(name);
        }
        default:
            break;
    }
    return std::nullopt;
}

}  // namespace nckit::interp::ngc
