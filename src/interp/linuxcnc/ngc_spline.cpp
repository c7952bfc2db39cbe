// LinuxCNC's splines: G5 (cubic), G5.1 (quadratic), G5.2 ... G5.3 (NURBS). The interpreter
// gathers the control points; the curve becomes the biarcs of ngc_nurbs.hpp, run as G2/G3/G1
// blocks in the plane, as LinuxCNC's motion controller runs it. G5 and G5.1 are not modal in
// LinuxCNC: the motion mode of before stays (a bare `X Y` after a G5 is a G1 there, and a
// `P Q` on it an error); G5.2 is, until G5.3, after which there is no motion mode.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "ngc_block_words.hpp"
#include "ngc_nurbs.hpp"
#include "ngc_runner.hpp"

namespace nckit::interp::ngc {
namespace {

//! The plane's axis letters (first, second) and the letters of their centre offsets.
struct PlaneLetters {
    char first;
    char second;
    char first_offset;
    char second_offset;
};

PlaneLetters letters_of(Plane plane) {
    switch (plane) {
        case Plane::yz:
            return {'Y', 'Z', 'J', 'K'};
        case Plane::zx:
            return {'Z', 'X', 'K', 'I'};
        case Plane::xy:
        default:
            return {'X', 'Y', 'I', 'J'};
    }
}

bool is_motion_code(double g) {
    constexpr double codes[] = {0,  1,  2,  3,  33, 33.1, 38.2, 38.3, 38.4, 38.5, 73, 74,
                                76, 80, 81, 82, 83, 84,   85,   86,   87,   88,   89};
    return std::any_of(std::begin(codes), std::end(codes), [g](double c) { return std::abs(g - c) < 1e-9; });
}

int spline_code(double g) {
    for (int code : {50, 51, 52, 53}) {
        if (std::abs(g * 10 - code) < 1e-6) return code;
    }
    return 0;
}

}  // namespace

bool NgcRunner::take_spline_block() {
    bool motion = false;
    for (const Word& w : block_.words) {
        if (w.letter != 'G') continue;
        if (spline_code(w.value) != 0) return true;
        motion = motion || is_motion_code(w.value);
    }
    if (motion) {
        spline_mode_ = 0;
        return false;
    }
    if (spline_mode_ != 52 && spline_mode_ != 53) return false;
    const PlaneLetters l = letters_of(executor_.modal_view().plane);
    return std::any_of(block_.words.begin(), block_.words.end(), [&](const Word& w) {
        if (spline_mode_ == 52) return w.letter == l.first || w.letter == l.second || w.letter == 'P';
        return is_axis_letter(w.letter);
    });
}

std::optional<InterpResult> NgcRunner::run_spline(std::vector<Move>& pending) {
    int code = spline_mode_;
    std::uint32_t column = 1;
    bool named = false;  // the block names G5.x itself (not only modal)
    for (const Word& w : block_.words) {
        if (w.letter == 'G' && spline_code(w.value) != 0) {
            code = spline_code(w.value);
            column = w.column;
            named = true;
        }
    }
    if (code == 53 && !named) {
        // After G5.3 LinuxCNC has no motion mode: axis words alone are an error.
        return InterpResult(fail(1, "cannot use axis values without a G code that uses them (G5.3 ended the NURBS)"));
    }
    // The block's other words (F, S, M, G90/G91, the plane ...) run first, as LinuxCNC orders them.
    Block rest;
    rest.location = block_.location;
    Block spline;
    for (const Word& w : block_.words) {
        const bool own = (w.letter == 'G' && spline_code(w.value) != 0) || w.letter == 'P' || w.letter == 'Q' ||
                         w.letter == 'L' || w.letter == 'I' || w.letter == 'J' || w.letter == 'K' ||
                         is_axis_letter(w.letter);
        (own ? spline.words : rest.words).push_back(w);
    }
    bool program_end = false;
    if (!rest.words.empty()) {
        if (auto error = executor_.run(rest, pending, program_end)) return InterpResult(std::move(*error));
    }
    const ModalView view = executor_.modal_view();
    const PlaneLetters l = letters_of(view.plane);
    if (view.cutter_compensation)
        return InterpResult(fail(column, "cannot convert spline with cutter radius compensation"));
    if (inverse_time_) return InterpResult(fail(column, "nckit does not run splines under G93 inverse time"));
    if ((code == 50 || code == 51) && view.plane != Plane::xy) {
        return InterpResult(fail(column, "splines must be in the XY plane"));
    }
    auto word = [&](char letter) -> const Word* {
        for (const Word& w : spline.words) {
            if (w.letter == letter) return &w;
        }
        return nullptr;
    };
    for (const Word& w : spline.words) {
        if (!is_axis_letter(w.letter) || w.letter == l.first || w.letter == l.second) continue;
        if (code == 50 || code == 51) {
            return InterpResult(fail(w.column, "splines may not have motion in Z, A, B, or C"));
        }
    }
    const double here_first = axis_position(l.first).value_or(0.0);
    const double here_second = axis_position(l.second).value_or(0.0);
    auto end_of = [&](char letter, double here) {
        const Word* w = word(letter);
        if (w == nullptr) return here;
        return view.incremental ? here + w->value : w->value;
    };
    const Word* p = word('P');
    std::vector<NurbsControlPoint> points;
    unsigned order = 0;
    if (code == 50 || code == 51) {
        const Word* i = word('I');
        const Word* j = word('J');
        double di = 0;
        double dj = 0;
        if (code == 51 && (i == nullptr || j == nullptr))
            return InterpResult(fail(column, "must specify both I and J with G5.1"));
        if (i == nullptr && j == nullptr) {
            di = spline_next_ij_[0];  // a G5 without I J starts along the end of the G5 before
            dj = spline_next_ij_[1];
        } else if (i == nullptr || j == nullptr) {
            return InterpResult(fail(column, "must specify both I and J, or neither"));
        } else {
            di = i->value;
            dj = j->value;
        }
        const double end_first = end_of(l.first, here_first);
        const double end_second = end_of(l.second, here_second);
        points.push_back({here_first, here_second, 1});
        points.push_back({here_first + di, here_second + dj, 1});
        if (code == 50) {
            const Word* q = word('Q');
            if (p == nullptr || q == nullptr) return InterpResult(fail(column, "must specify both P and Q with G5"));
            points.push_back({end_first + p->value, end_second + q->value, 1});
            spline_next_ij_[0] = -p->value;
            spline_next_ij_[1] = -q->value;
        }
        points.push_back({end_first, end_second, 1});
        order = code == 50 ? 4 : 3;
        spline_mode_ = 0;
    } else if (code == 52) {
        const Word* a = word(l.first);
        const Word* b = word(l.second);
        if ((a == nullptr) != (b == nullptr)) {
            return InterpResult(
                fail(column,
                     fmt::format("you must specify both {} and {} coordinates for control points", l.first, l.second)));
        }
        if (view.feed_mode == FeedMode::per_minute && view.feed == 0) {
            return InterpResult(fail(column, "cannot make a NURBS with 0 feedrate"));
        }
        if (spline_mode_ != 52) nurbs_points_.clear();
        if (a == nullptr && p != nullptr && p->value > 0 && !nurbs_points_.empty()) {
            return InterpResult(fail(
                p->column,
                fmt::format("can specify P without {} and {} only for the first control point", l.first, l.second)));
        }
        if ((p == nullptr || p->value <= 0) && (!nurbs_points_.empty() || a != nullptr)) {
            return InterpResult(fail(column, "must specify positive weight P for every control point"));
        }
        if (nurbs_points_.empty()) {
            const double weight = a == nullptr && p != nullptr && p->value > 0 ? p->value : 1.0;
            nurbs_points_.push_back({here_first, here_second, weight});
            nurbs_order_ = 3;
        }
        if (const Word* order_word = word('L'); order_word != nullptr && order_word->value > 3) {
            if (order_word->value > max_nurbs_order || order_word->value != std::floor(order_word->value)) {
                return InterpResult(fail(
                    order_word->column, fmt::format("NURBS order L must be a whole number up to {}", max_nurbs_order)));
            }
            nurbs_order_ = static_cast<unsigned>(order_word->value);
        }
        if (a != nullptr) {
            // Incremental points count from where the curve starts: the tool has not moved yet.
            if (nurbs_points_.size() >= max_nurbs_points) {
                return InterpResult(fail(column, fmt::format("more than {} NURBS control points", max_nurbs_points)));
            }
            nurbs_points_.push_back({end_of(l.first, here_first), end_of(l.second, here_second), p->value});
        }
        spline_mode_ = 52;
        return program_end ? std::optional<InterpResult>(ProgramEnd{}) : std::nullopt;
    } else {
        if (spline_mode_ != 52) return InterpResult(fail(column, "cannot use G5.3 without G5.2 first"));
        if (nurbs_points_.size() < nurbs_order_) {
            return InterpResult(fail(
                column, fmt::format("you must specify a number of control points at least equal to the order L = {}",
                                    nurbs_order_)));
        }
        points = std::move(nurbs_points_);
        nurbs_points_.clear();
        order = nurbs_order_;
        spline_mode_ = 53;
    }
    if (auto error = run_spline_elements(nurbs_biarcs(points, order), view.plane, pending, program_end)) {
        return InterpResult(std::move(*error));
    }
    return program_end ? std::optional<InterpResult>(ProgramEnd{}) : std::nullopt;
}

std::optional<Diagnostic> NgcRunner::run_spline_elements(const std::vector<SplineElement>& elements, Plane plane,
                                                         std::vector<Move>& pending, bool& program_end) {
    const ModalView view = executor_.modal_view();
    const PlaneLetters l = letters_of(plane);
    const GCode motion_before = executor_.motion_mode();
    for (const SplineElement& e : elements) {
        if (!std::isfinite(e.end_first) || !std::isfinite(e.end_second) || !std::isfinite(e.center_first) ||
            !std::isfinite(e.center_second)) {
            return fail(1, "the spline has no finite point here: check its control points and weights");
        }
        Block b;
        b.location = block_.location;
        const std::uint32_t at = block_.words.empty() ? 1 : block_.words.front().column;
        if (view.incremental) b.words.push_back(Word{'G', 90.0, true, at, -1});
        b.words.push_back(Word{'G', e.arc ? (e.counterclockwise ? 3.0 : 2.0) : 1.0, true, at, -1});
        b.words.push_back(Word{l.first, e.end_first, true, at, -1});
        b.words.push_back(Word{l.second, e.end_second, true, at, -1});
        if (e.arc) {
            const double from_first = view.arc_centers_absolute ? 0.0 : axis_position(l.first).value_or(0.0);
            const double from_second = view.arc_centers_absolute ? 0.0 : axis_position(l.second).value_or(0.0);
            b.words.push_back(Word{l.first_offset, e.center_first - from_first, true, at, -1});
            b.words.push_back(Word{l.second_offset, e.center_second - from_second, true, at, -1});
        }
        if (auto error = executor_.run(b, pending, program_end)) return error;
    }
    if (view.incremental) {
        Block back;
        back.location = block_.location;
        back.words.push_back(Word{'G', 91.0, true, 1, -1});
        if (auto error = executor_.run(back, pending, program_end)) return error;
    }
    executor_.restore_motion_mode(motion_before);
    return std::nullopt;
}

}  // namespace nckit::interp::ngc
