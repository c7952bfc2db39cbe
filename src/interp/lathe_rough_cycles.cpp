// Stock removal G71 (turning: levels of X, cuts along Z) and G72 (facing: levels of Z, cuts along
// X). With A the start point, A' where the P block goes and the shape moved by the finishing
// allowance (U/2 in X as a radius, W in Z), the cycle cuts levels from A by the depth of cut
// (G71 U / G72 W) and ends with a pass along the moved shape, which leaves exactly the allowance
// for G70; the tool then returns to A at rapid. Rapids at the end of the shape (a retract in the
// Q block) are not part of what is roughed.
//   Type I (the P block names only the depth axis, X for G71): the shape runs one way in both
//   axes; each pass goes in at A's length, cuts until it meets the moved shape, escapes at 45
//   degrees by R and returns at rapid.
//   Type II (the P block names both axes): the shape runs one way along the length axis only and
//   may dip into pockets; each level is cut wherever the moved shape lies below it
//   (lathe_rough_pockets.cpp).
#include <cmath>

#include <fmt/format.h>

#include "executor.hpp"
#include "nckit/interp/arc_geometry.hpp"
#include "lathe_codes.hpp"
#include "lathe_contour.hpp"

namespace nckit::interp {

namespace {
constexpr double flat_mm = 1e-9;  // rounding between the shape's own end points
constexpr int max_rough_passes = 100000;

double sign_of(double value) {
    return value > 0 ? 1.0 : value < 0 ? -1.0 : 0.0;
}
}  // namespace

std::optional<Diagnostic> Executor::rough_cycle(std::vector<Move>& out) {
    const GCode cycle = words_.group(ModalGroup::non_modal);
    const std::string name = lathe_code_name(machine_.gcode_system, cycle);
    const bool facing = cycle == lathe_rough_facing;
    const ContourAxes axes = facing ? ContourAxes{Axis::Z, Axis::X} : ContourAxes{Axis::X, Axis::Z};
    const char depth_letter = facing ? 'W' : 'U';
    const LatheCycleSettings& settings = modal_.lathe.settings;
    double depth_mm = settings.rough_depth_mm;
    if (const Word* d = words_.word('D')) depth_mm = offset_value(*d);  // the one-block form's D
    if (depth_mm <= 0) {
        return error(words_.group_column(ModalGroup::non_modal), "missing-word",
                     fmt::format("{} needs its depth of cut first: a block {} {}.. R..", name, name, depth_letter));
    }
    AxisVector allowance;
    const Word* u = cycle_word('U');
    const Word* w = cycle_word('W');
    if (u != nullptr) allowance[Axis::X] = axis_value(Axis::X, *u);
    if (w != nullptr) allowance[Axis::Z] = axis_value(Axis::Z, *w);

    const AxisVector start = position_;
    PqShape pq;
    if (auto e = run_pq_blocks(pq)) return e;
    const std::vector<Move>& shape = pq.moves;
    const std::size_t approach = pq.approach_moves;
    // Fanuc's rule: the P block that names the length axis (Z or W for G71) makes type II.
    const char length_word = letter(axes.length);
    const char length_incremental = facing ? 'U' : 'W';
    // R1 in the P Q block selects type II as well: Haas's one-block form (its "YASNAC type II").
    const Word* type_word = words_.word('R');
    if (type_word != nullptr && type_word->value != 1) {
        return error(type_word->column, "bad-value",
                     fmt::format("{} P Q takes R1 only (type II roughing); the escape R goes in the block {} {} R",
                                 name, name, depth_letter));
    }
    const bool pockets = type_word != nullptr || pq.p_letters.find(length_word) != std::string::npos ||
                         pq.p_letters.find(length_incremental) != std::string::npos;
    const char* type = pockets ? "type II" : "type I";
    // The P block's move (its S, T or M events aside: they count only for G70).
    const Line* approach_line = nullptr;
    std::size_t approach_lines = 0;
    for (std::size_t i = 0; i < approach; ++i) {
        if (std::holds_alternative<Arc>(shape[i].what) || std::holds_alternative<SyncMove>(shape[i].what))
            ++approach_lines;
        if (const auto* line = std::get_if<Line>(&shape[i].what)) {
            approach_line = line;
            ++approach_lines;
        }
    }
    if (approach_lines != 1 || approach_line == nullptr) {
        return error(column_of('P'), "bad-cycle", fmt::format("{}: the P block must make one G0 or G1 move", name));
    }
    const Line& in = *approach_line;
    std::vector<Move> profile;
    for (std::size_t i = approach; i < shape.size(); ++i) {
        if (std::holds_alternative<SyncMove>(shape[i].what)) {
            return error_at(shape[i].where, "bad-cycle", fmt::format("{}: no threading in the finishing shape", name));
        }
        if (std::holds_alternative<Line>(shape[i].what) || std::holds_alternative<Arc>(shape[i].what)) {
            profile.push_back(shape[i]);
        }
    }
    // Rapids that close the shape (the Q block's retract, often with G40) cut nothing: the shape
    // to rough ends with its last feed move.
    while (!profile.empty() && std::holds_alternative<Line>(profile.back().what) &&
           std::get<Line>(profile.back().what).rapid) {
        profile.pop_back();
    }
    if (profile.empty()) {
        return error(column_of('Q'), "bad-cycle",
                     fmt::format("{}: no finishing shape between P and Q: its blocks make no G1, G2 or G3 move", name));
    }
    const double a_d = start[axes.depth];
    const double a_l = start[axes.length];
    const double up = sign_of(a_d - in.to[axes.depth]);  // from the shape towards A
    if (up == 0) {
        return error(column_of('P'), "bad-cycle",
                     fmt::format("{}: the P block must move in {} from the start point", name, letter(axes.depth)));
    }
    const Word* depth_allowance = facing ? w : u;
    if (depth_allowance != nullptr && allowance[axes.depth] * up < 0) {
        // The allowance would move the shape into the part: Fanuc leaves it on the side the tool
        // comes from, and that side is where the start point lies.
        const char side = up > 0 ? '+' : '-';
        return error(depth_allowance->column, "bad-cycle",
                     fmt::format("finishing allowance {} has the wrong sign: the start point lies at {}{} of the P "
                                 "block's point, so the shape is cut from {}{}; to cut from {}{}, start at {}{} of it",
                                 depth_allowance->letter, side, letter(axes.depth), side, letter(axes.depth),
                                 up > 0 ? '-' : '+', letter(axes.depth), up > 0 ? '-' : '+', letter(axes.depth)));
    }
    // Type I: the shape runs one way in both axes (Fanuc alarm PS0064 otherwise).
    double along = 0;
    for (const Move& element : profile) {
        const AxisVector from = *move_start(element);
        const AxisVector to = *move_end(element);
        const Extent d = extent_along(element, axes.depth);
        const Extent l = extent_along(element, axes.length);
        const double step_l = to[axes.length] - from[axes.length];
        if (along == 0 && std::abs(step_l) > flat_mm) along = sign_of(step_l);
        // An arc whose end point is rounded (CAM output to 4 decimals) ends a little off its start
        // radius; its bulge may pass the end point by that much without the shape turning back.
        const auto* arc = std::get_if<Arc>(&element.what);
        const double bulge = flat_mm + (arc ? std::abs(arc_end_radius(*arc) - arc_start_radius(*arc)) : 0.0);
        const bool d_ok = pockets || (up * (to[axes.depth] - from[axes.depth]) >= -flat_mm &&
                                      d.low >= std::min(from[axes.depth], to[axes.depth]) - bulge &&
                                      d.high <= std::max(from[axes.depth], to[axes.depth]) + bulge);
        const bool l_ok = along * step_l >= -flat_mm && l.low >= std::min(from[axes.length], to[axes.length]) - bulge &&
                          l.high <= std::max(from[axes.length], to[axes.length]) + bulge;
        if (!d_ok || !l_ok) {
            const std::string one_way = pockets ? std::string(1, letter(axes.length))
                                                : fmt::format("{} and in {}", letter(axes.depth), letter(axes.length));
            return error_at(
                element.where, "bad-cycle",
                fmt::format("{} {}: the finishing shape must run one way in {} (this block turns back in {})", name,
                            type, one_way, letter(d_ok ? axes.length : axes.depth)));
        }
    }
    if (along == 0) {
        return error(column_of('Q'), "bad-cycle",
                     fmt::format("{}: the finishing shape has no length in {}", name, letter(axes.length)));
    }
    std::vector<Move> moved;
    for (const Move& element : profile) moved.push_back(shifted(element, allowance));
    // The deepest point of the moved shape: where the P block goes for type I, the bottom of the
    // deepest pocket for type II.
    double floor_d = in.to[axes.depth] + allowance[axes.depth];
    if (pockets) {
        for (const Move& element : moved) {
            const Extent d = extent_along(element, axes.depth);
            floor_d = up > 0 ? std::min(floor_d, d.low) : std::max(floor_d, d.high);
        }
    }
    const double end_l = (*move_end(moved.back()))[axes.length];
    const double level_count = std::floor((a_d - floor_d) * up / depth_mm - flat_mm);
    if ((a_d - floor_d) * up <= flat_mm) {
        const std::uint32_t column =
            depth_allowance != nullptr ? depth_allowance->column : words_.group_column(ModalGroup::non_modal);
        return error(column, "bad-cycle", fmt::format("{}: the start point lies inside the finishing allowance", name));
    }
    if (level_count > max_rough_passes) {
        return error(words_.group_column(ModalGroup::non_modal), "bad-value",
                     fmt::format("{}: the depth of cut needs more than {} passes", name, max_rough_passes));
    }
    const int levels = static_cast<int>(level_count);
    const GCode infeed = in.rapid ? g(0) : g(1);
    auto point = [&](double d, double l) {
        AxisVector p = position_;
        p[axes.depth] = d;
        p[axes.length] = l;
        return p;
    };
    const double escape = settings.retract_mm;
    if (pockets) {
        const RoughLevels plan{axes, up, along, a_d, a_l, depth_mm, escape, levels, in.rapid};
        if (auto e = rough_pocket_levels(plan, moved, out)) return e;
    }
    for (int k = 1; k <= (pockets ? 0 : levels); ++k) {
        const double level = a_d - up * k * depth_mm;
        double cut_end = end_l;
        for (const Move& element : moved) {
            if (auto l = level_crossing(element, axes, level)) {
                cut_end = *l;
                break;
            }
        }
        if (along * (cut_end - a_l) <= flat_mm) continue;  // nothing to cut at this level
        if (auto e = straight(infeed, point(level, a_l), out)) return e;
        if (auto e = straight(g(1), point(level, cut_end), out)) return e;
        if (escape > 0) {
            if (auto e = straight(g(1), point(level + up * escape, cut_end - along * escape), out)) return e;
        }
        if (auto e = straight(g(0), point(position_[axes.depth], a_l), out)) return e;
    }
    // The last pass: along the shape moved by the allowance.
    if (auto e = straight(infeed, *move_start(moved.front()), out)) return e;
    for (const Move& element : moved) {
        if (const auto* line = std::get_if<Line>(&element.what)) {
            if (auto e = straight(line->rapid ? g(0) : g(1), line->to, out)) return e;
        } else if (auto e = feed_arc(std::get<Arc>(element.what), out)) {
            return e;
        }
    }
    const double clear_d = up > 0 ? std::max(a_d, position_[axes.depth]) : std::min(a_d, position_[axes.depth]);
    for (const AxisVector& back : {point(clear_d, position_[axes.length]), point(clear_d, a_l), start}) {
        if (back == position_) continue;
        if (auto e = straight(g(0), back, out)) return e;
    }
    skip_past_sequence_ = true;
    return std::nullopt;
}

}  // namespace nckit::interp
