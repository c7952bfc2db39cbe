// LinuxCNC's lathe cycles in its own form: `G70`/`G71`/`G71.1`/`G71.2`/`G72`/`G72.1`/`G72.2 Q<n>
// X Z D I R ...`, the finished shape in the O-word subroutine `o<n> sub`. As LinuxCNC does: a
// rapid to the block's X Z first; then the subroutine is called and its lines are read, not run
// (O-word control flow and parameter settings do run; #<_x> and #<_z> follow the shape as it is
// read), each motion line adding a line or an arc, A a fillet and C a chamfer at its end; then the
// passes (ngc_g7x_path.cpp) run as G0/G1/G2/G3 blocks of the cycle's line.
#include <cmath>

#include <fmt/format.h>

#include "ngc_block_words.hpp"
#include "ngc_evaluate.hpp"
#include "ngc_runner.hpp"

namespace nckit::interp::ngc {

namespace {

//! The cycle's code x 10 (G71.1: 711), or 0 when the word is none of LinuxCNC's G7x.
int g7x_code(double value) {
    for (int code : {700, 710, 711, 712, 720, 721, 722}) {
        if (std::abs(value * 10.0 - code) < 1e-6) return code;
    }
    return 0;
}

std::optional<double> word_value(const Block& block, char letter) {
    for (const Word& w : block.words) {
        if (w.letter == letter) return w.value;
    }
    return std::nullopt;
}

}  // namespace

const Word* NgcRunner::g7x_word() const {
    for (const Word& w : block_.words) {
        if (w.letter == 'G' && g7x_code(w.value) != 0) return &w;
    }
    return nullptr;
}

std::optional<Diagnostic> NgcRunner::collect_profile_line() {
    // Parameter settings of the line take effect (LinuxCNC applies them as it reads the shape).
    for (const Setting& s : line_.settings) {
        const Node& target = line_.nodes[static_cast<std::size_t>(s.target)];
        double value = 0;
        if (auto error = evaluate(line_, s.value, parameters_, value)) return error;
        if (target.op == Op::named) {
            if (!parameters_.write_named(line_.names[static_cast<std::size_t>(target.name)], value)) {
                return fail(s.column, "cannot assign to a read-only parameter");
            }
        } else {
            std::int64_t number = 0;
            if (auto error = parameter_number(line_, s.target, parameters_, number)) return error;
            parameters_.write(number, value);
        }
    }
    if (auto error = resolve_block()) return error;
    ProfileReading& r = *profile_;
    for (const Word& w : block_.words) {
        if (w.letter != 'G') continue;
        if (g7x_code(w.value) != 0) return fail(w.column, "a lathe cycle inside the shape of another");
        for (int motion : {0, 1, 2, 3}) {
            if (w.value == motion) r.motion = motion;
        }
    }
    const auto x = word_value(block_, 'X'), z = word_value(block_, 'Z'), u = word_value(block_, 'U'),
               w = word_value(block_, 'W'), i = word_value(block_, 'I'), k = word_value(block_, 'K'),
               radius = word_value(block_, 'R'), fillet = word_value(block_, 'A'), chamfer = word_value(block_, 'C');
    ZX end = r.incremental ? ZX(0, 0) : r.at;
    if (u) {
        if (r.incremental) return fail(find_word(block_, 'U')->column, "G7x: cannot use U in incremental mode (G91)");
        if (x) return fail(find_word(block_, 'U')->column, "G7x: cannot use U and X in the same block");
        end.imag(end.imag() + *u);
    } else if (x) {
        end.imag(*x);
    }
    if (w) {
        if (r.incremental) return fail(find_word(block_, 'W')->column, "G7x: cannot use W in incremental mode (G91)");
        if (z) return fail(find_word(block_, 'W')->column, "G7x: cannot use W and Z in the same block");
        end.real(end.real() + *w);
    } else if (z) {
        end.real(*z);
    }
    if (r.incremental) end += r.at;
    if (end == r.at) return std::nullopt;
    ProfileSegment s;
    s.start = r.at;
    s.end = end;
    if (r.motion == 2 || r.motion == 3) {
        s.arc = true;
        s.ccw = r.motion == 3;
        if (radius) {
            if (i || k) return fail(find_word(block_, 'R')->column, "G7x: both R and I or K given for an arc");
            const ZX chord = end - r.at;
            const double square = (*radius * *radius - std::norm(chord) / 4) / std::norm(chord);
            if (square < 0) return fail(find_word(block_, 'R')->column, "G7x: arc radius too small for its end");
            const ZX to_center = ZX(0, 1) * std::sqrt(square) * chord;
            s.center = (r.at + end) / 2.0 + (s.ccw ? to_center : -to_center);
        } else {
            if (!i && !k) return fail(1, "G7x: an arc of the shape needs I or K");
            s.center = ZX(k.value_or(0.0), i.value_or(0.0));
            if (r.ijk_incremental) s.center += r.at;
        }
    }
    if (r.motion >= 0 && r.motion <= 3) {
        r.segments.push_back(s);
        if (fillet && chamfer) return fail(find_word(block_, 'A')->column, "G7x: both A and C on a corner");
        ProfileSegment corner;
        corner.start = corner.end = corner.center = end;
        if (fillet) {
            corner.arc = true;
            corner.corner = CornerFinish::fillet;
            corner.finish = *fillet;
            r.segments.push_back(corner);
        } else if (chamfer) {
            corner.corner = CornerFinish::chamfer;
            corner.finish = *chamfer;
            r.segments.push_back(corner);
        }
    }
    r.at = end;
    return std::nullopt;
}

std::optional<InterpResult> NgcRunner::run_g7x(std::vector<Move>& pending) {
    const Word cycle_word = *g7x_word();
    const int code = g7x_code(cycle_word.value);
    const int cycle = code / 10;
    const ModalView view = executor_.modal_view();
    const auto q = word_value(block_, 'Q');
    if (!q) return InterpResult(fail(cycle_word.column, fmt::format("G{} requires a Q word", cycle_word.value)));
    if (view.cutter_compensation) {
        return InterpResult(
            fail(cycle_word.column,
                 cycle == 70 ? "G70 with cutter compensation in force is not supported by nckit"
                             : fmt::format("G{} cannot be used with cutter compensation enabled", cycle_word.value)));
    }
    const bool zx_plane = has_g(block_, 18) || (view.plane == Plane::zx && !has_g(block_, 17) && !has_g(block_, 19));
    if (!zx_plane) {
        return InterpResult(
            fail(cycle_word.column, fmt::format("G{} can only be used in XZ plane (G18)", cycle_word.value)));
    }
    if (view.diameter_mode || has_g(block_, 7)) {
        return InterpResult(fail(cycle_word.column, "LinuxCNC's lathe cycles in diameter mode (G7) are not supported"));
    }
    const bool incremental = has_g(block_, 91) || (view.incremental && !has_g(block_, 90));
    const bool ijk_incremental = has_g(block_, 91.1) || (!view.arc_centers_absolute && !has_g(block_, 90.1));
    const std::optional<double> here_x = axis_position('X'), here_z = axis_position('Z');
    if (!here_x || !here_z) return InterpResult(fail(cycle_word.column, "a lathe cycle needs X and Z axes"));
    const auto bx = word_value(block_, 'X'), bz = word_value(block_, 'Z');
    G7xRequest request;
    request.cycle = cycle;
    request.variant = code % 10;
    request.start =
        ZX(bz ? (incremental ? *here_z + *bz : *bz) : *here_z, bx ? (incremental ? *here_x + *bx : *bx) : *here_x);
    request.d = word_value(block_, 'D').value_or(0.0);
    request.e = word_value(block_, 'E').value_or(0.0);
    request.i = word_value(block_, 'I').value_or(1.0);
    request.r = word_value(block_, 'R').value_or(0.5);
    request.u = word_value(block_, 'U').value_or(0.0);
    request.w = word_value(block_, 'W').value_or(0.0);
    request.passes = word_value(block_, 'P').value_or(1.0);
    const SourceLocation cycle_location = line_.location;

    // The block's other words, and the rapid to its X Z (read as absolute, as LinuxCNC reads them).
    std::erase_if(block_.words, [](const Word& w) {
        return (w.letter == 'G' && (g7x_code(w.value) != 0 || w.value == 90 || w.value == 91)) ||
               std::string_view("QDEIKPRUWAC").find(w.letter) != std::string_view::npos;
    });
    block_.words.push_back(Word{'G', 90.0, true, cycle_word.column, -1});
    block_.words.push_back(Word{'G', 0.0, true, cycle_word.column, -1});
    if (!bx && !bz) block_.words.push_back(Word{'X', *here_x, true, cycle_word.column, -1});
    if (auto error = translate_block()) return InterpResult(std::move(*error));
    bool program_end = false;
    for (const Block& b : run_list_) {
        if (auto error = executor_.run(b, pending, program_end)) return InterpResult(std::move(*error));
    }

    // The shape: the subroutine's lines read, not run.
    const NgcLine cycle_line = line_;
    const std::size_t depth = frames_.size();
    profile_.emplace();
    profile_->at = request.start;
    profile_->incremental = incremental;
    profile_->ijk_incremental = ijk_incremental;
    if (auto error = call_sub(fmt::format("{}", static_cast<std::int64_t>(*q)))) {
        profile_.reset();
        return InterpResult(std::move(*error));
    }
    while (frames_.size() > depth) {
        if (auto result = run_line(pending)) {
            profile_.reset();
            if (std::holds_alternative<Diagnostic>(*result)) return result;
            return InterpResult(fail(cycle_word.column, "the program ended inside a lathe cycle's shape"));
        }
    }
    ProfileReading shape = std::move(*profile_);
    profile_.reset();
    line_ = cycle_line;
    if (shape.segments.size() <= 1) return std::nullopt;
    if (auto error = check_g7x_words(request, cycle_word)) return InterpResult(std::move(*error));

    std::vector<ProfileMove> moves;
    if (auto fault = plan_g7x(std::move(shape.segments), request, moves)) {
        return InterpResult(fail(cycle_word.column, fmt::format("G7x error: {}", *fault)));
    }
    if (auto error = run_g7x_moves(moves, ZX(*here_z, *here_x), cycle_location, pending)) {
        return InterpResult(std::move(*error));
    }
    // The distance modes of before the cycle; the motion mode stays that of its last move.
    Block restore;
    restore.location = cycle_location;
    if (incremental) restore.words.push_back(Word{'G', 91.0, true, 1, -1});
    if (ijk_incremental) restore.words.push_back(Word{'G', 91.1, true, 1, -1});
    if (!restore.words.empty()) {
        if (auto error = executor_.run(restore, pending, program_end)) return InterpResult(std::move(*error));
    }
    return std::nullopt;
}

std::optional<Diagnostic> NgcRunner::check_g7x_words(const G7xRequest& request, const Word& cycle_word) const {
    if (request.i <= 0) return fail(cycle_word.column, "G7X error: I must be greater than zero");
    return std::nullopt;
}

std::optional<Diagnostic> NgcRunner::run_g7x_moves(const std::vector<ProfileMove>& moves, ZX from,
                                                   const SourceLocation& where, std::vector<Move>& pending) {
    bool program_end = false;
    ZX at = from;
    for (const ProfileMove& m : moves) {
        // LinuxCNC leaves out an arc ending where it starts (to its 0.0001 equality).
        if (m.kind == ProfileMove::Kind::arc && std::abs(m.end.real() - at.real()) < 1e-4 &&
            std::abs(m.end.imag() - at.imag()) < 1e-4) {
            continue;
        }
        Block b;
        b.location = where;
        const double g = m.kind == ProfileMove::Kind::rapid ? 0 : m.kind == ProfileMove::Kind::feed ? 1 : m.ccw ? 3 : 2;
        b.words = {Word{'G', 90.0, true, 1, -1}, Word{'G', 90.1, true, 1, -1}, Word{'G', g, true, 1, -1},
                   Word{'X', m.end.imag(), true, 1, -1}, Word{'Z', m.end.real(), true, 1, -1}};
        if (m.kind == ProfileMove::Kind::arc) {
            b.words.push_back(Word{'I', m.center.imag(), true, 1, -1});
            b.words.push_back(Word{'K', m.center.real(), true, 1, -1});
        }
        if (auto error = executor_.run(b, pending, program_end)) return error;
        at = m.end;
    }
    return std::nullopt;
}

}  // namespace nckit::interp::ngc
