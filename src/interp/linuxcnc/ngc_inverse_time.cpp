// G93 inverse time as LinuxCNC reads it: F on a G1/G2/G3 block is 1 / (the move's minutes), and
// the feed the machine follows is F times the move's length (XYZ, else UVW with them, else the
// rotary axes alone; an arc's helical length) as programmed, before cutter compensation, at
// least 0.1 units/min. The Executor runs the block under G94 with the F as written; the feeds
// of the moves it makes are then set here to that one rate (a corner arc compensation adds
// feeds at it too). Compensation may hand a block's moves out a block later: each move finds
// its block's rate by its source line among the last few inverse-time blocks.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "ngc_block_words.hpp"
#include "ngc_runner.hpp"

namespace nckit::interp::ngc {

namespace {

constexpr std::size_t inverse_blocks_kept = 8;  // more than cutter compensation ever holds back

double line_length(const AxisVector& from, const AxisVector& to) {
    auto sum = [&](std::initializer_list<Axis> axes) {
        double s = 0;
        for (Axis a : axes) s += (to[a] - from[a]) * (to[a] - from[a]);
        return s;
    };
    const double linear = sum({Axis::X, Axis::Y, Axis::Z, Axis::U, Axis::V, Axis::W});
    return std::sqrt(linear > 0 ? linear : sum({Axis::A, Axis::B, Axis::C}));
}

double arc_length(const Arc& arc) {
    Axis first = Axis::X, second = Axis::Y, normal = Axis::Z;
    if (arc.plane == Plane::zx) first = Axis::Z, second = Axis::X, normal = Axis::Y;
    if (arc.plane == Plane::yz) first = Axis::Y, second = Axis::Z, normal = Axis::X;
    const double radius = std::hypot(arc.from[first] - arc.center[first], arc.from[second] - arc.center[second]);
    const double start = std::atan2(arc.from[second] - arc.center[second], arc.from[first] - arc.center[first]);
    const double end = std::atan2(arc.to[second] - arc.center[second], arc.to[first] - arc.center[first]);
    constexpr double turn = 2 * std::numbers::pi;
    double sweep = end - start;  // counter-clockwise, in (0, 2 pi]
    if (arc.direction == ArcDirection::counterclockwise) {
        while (sweep <= 0) sweep += turn;
    } else {
        sweep = -sweep;
        while (sweep <= 0) sweep += turn;
    }
    sweep += turn * arc.full_turns;
    return std::hypot(radius * sweep, arc.to[normal] - arc.from[normal]);
}

double word_or(const Block& block, char letter, double otherwise) {
    for (const Word& w : block.words) {
        if (w.letter == letter) return w.value;
    }
    return otherwise;
}

}  // namespace

std::optional<Diagnostic> NgcRunner::read_inverse_time() {
    if (has_g(block_, 93)) {
        inverse_time_ = true;
    } else if (has_g(block_, 94) || has_g(block_, 95)) {
        inverse_time_ = false;
    }
    for (Word& w : block_.words) {
        if (w.letter == 'G' && w.value == 93) w.value = 94;  // the Executor feeds per minute
    }
    if (!inverse_time_) return std::nullopt;
    const ModalView view = executor_.modal_view();
    int motion = -1;
    std::uint32_t column = 1;
    bool moves = false;
    for (const Word& w : block_.words) {
        if (w.letter == 'G' &&
            (w.value == 0 || w.value == 1 || w.value == 2 || w.value == 3 || (w.value >= 73 && w.value <= 89))) {
            motion = static_cast<int>(std::lround(w.value * 10));
            column = w.column;
        }
        if (is_axis_letter(w.letter) || w.letter == '@' || w.letter == '^') moves = true;
    }
    if (motion < 0) motion = view.motion_code;
    if (!moves || motion == 0) return std::nullopt;
    if (motion >= 730) return fail(column, "a drilling cycle under G93 inverse time is not supported");
    const Word* f = find_word(block_, 'F');
    if (f == nullptr) {
        return fail(column, motion == 10 ? "F word missing with inverse time g1 move"
                                         : "F word missing with inverse time arc move");
    }
    // The programmed move in program units (degrees for rotary axes).
    const bool incremental = has_g(block_, 91) || (view.incremental && !has_g(block_, 90));
    AxisVector from;
    AxisVector to;
    for (char a : std::string_view("XYZABCUVW")) {
        const auto axis = axis_from_letter(a);
        if (!axis) continue;
        from[*axis] = axis_position(a).value_or(0.0);
        const double word = word_or(block_, a, incremental ? 0.0 : from[*axis]);
        to[*axis] = incremental ? from[*axis] + word : word;
    }
    double length = 0;
    if (motion == 10) {
        length = line_length(from, to);
    } else {
        Arc arc;
        arc.from = from;
        arc.to = to;
        arc.center = from;
        arc.direction = motion == 20 ? ArcDirection::clockwise : ArcDirection::counterclockwise;
        Plane plane = view.plane;
        if (has_g(block_, 17)) plane = Plane::xy;
        if (has_g(block_, 18)) plane = Plane::zx;
        if (has_g(block_, 19)) plane = Plane::yz;
        arc.plane = plane;
        Axis first = Axis::X, second = Axis::Y;
        char first_offset = 'I', second_offset = 'J';
        if (plane == Plane::zx) first = Axis::Z, second = Axis::X, first_offset = 'K', second_offset = 'I';
        if (plane == Plane::yz) first = Axis::Y, second = Axis::Z, first_offset = 'J', second_offset = 'K';
        if (const Word* r = find_word(block_, 'R')) {
            // The centre on the side R's sign and the direction choose, as G2/G3 R.
            const double dx = to[first] - from[first], dy = to[second] - from[second];
            const double chord = std::hypot(dx, dy);
            const double half = chord / 2;
            const double rise = std::sqrt(std::max(0.0, r->value * r->value - half * half));
            const double side = (arc.direction == ArcDirection::clockwise) == (r->value > 0) ? -1.0 : 1.0;
            if (chord > 0) {
                arc.center[first] = from[first] + dx / 2 - side * rise * dy / chord;
                arc.center[second] = from[second] + dy / 2 + side * rise * dx / chord;
            }
        } else {
            arc.center[first] = from[first] + word_or(block_, first_offset, 0.0);
            arc.center[second] = from[second] + word_or(block_, second_offset, 0.0);
        }
        const double turns = word_or(block_, 'P', 1.0);
        arc.full_turns = turns >= 1 ? static_cast<int>(turns) - 1 : 0;
        length = arc_length(arc);
    }
    const bool linear = line_length(from, to) > 0 && [&] {
        for (Axis a : {Axis::X, Axis::Y, Axis::Z, Axis::U, Axis::V, Axis::W}) {
            if (to[a] != from[a]) return true;
        }
        return false;
    }();
    const double per_unit = linear || motion != 10 ? view.length_factor_mm : 1.0;  // mm, or deg alone
    const double rate = std::max(0.1 * view.length_factor_mm, f->value * length * per_unit);
    inverse_feeds_.push_back(InverseFeed{block_.location.file.get(), block_.location.line, rate});
    if (inverse_feeds_.size() > inverse_blocks_kept) inverse_feeds_.erase(inverse_feeds_.begin());
    return std::nullopt;
}

void NgcRunner::apply_inverse_time(std::vector<Move>& pending, std::size_t first_new) const {
    if (inverse_feeds_.empty()) return;
    for (std::size_t i = first_new; i < pending.size(); ++i) {
        const SourceLocation& where = pending[i].where;
        auto found = std::find_if(inverse_feeds_.rbegin(), inverse_feeds_.rend(), [&](const InverseFeed& b) {
            return b.file == where.file.get() && b.line == where.line;
        });
        if (found == inverse_feeds_.rend()) continue;
        if (auto* line = std::get_if<Line>(&pending[i].what); line != nullptr && !line->rapid) {
            line->feed.mm_per_min = found->mm_per_min;
        } else if (auto* arc = std::get_if<Arc>(&pending[i].what)) {
            arc->feed.mm_per_min = found->mm_per_min;
        }
    }
}

}  // namespace nckit::interp::ngc
