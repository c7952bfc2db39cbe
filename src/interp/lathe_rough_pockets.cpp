// The roughing levels of G71/G72 type II, whose finishing shape runs one way along the length
// axis (Z for G71) but may go down and up again in depth: pockets. Level k lies k depths of cut
// below the start point A. At each level the cut runs wherever the moved shape lies below the
// level: from A's length to the first place the shape rises through the level, then again from
// where it falls through the level (a pocket's near wall) to where it rises again (its far wall),
// and so on to the shape's end.
//   Every stretch starts in air: the first at A's length, the others at a point of the wall
//   where the shape crosses the level, whose column down to the level above was cleared by the
//   levels before (the shape there lies below each of them). So the tool comes down at rapid to
//   the level above (to A's depth for the first level) and feeds the last depth of cut.
//   Every stretch ends on the moved shape, escapes at 45 degrees by R (less on a stretch shorter
//   than R, so the escape stays above what was just cut) and goes up at rapid to the clearance
//   depth, A's depth or the highest point of the moved shape if that is higher: between two
//   pockets the shape may stand higher than the level, so the tool never travels along a level.
#include <algorithm>
#include <cmath>

#include "executor.hpp"
#include "lathe_contour.hpp"

namespace nckit::interp {

namespace {
constexpr double flat_mm = 1e-9;

//! The stretches [from, to] (in cutting order) along which `moved` lies below `level`.
std::vector<std::pair<double, double>> stretches_below(const std::vector<Move>& moved, const RoughLevels& plan,
                                                       double level) {
    const ContourAxes axes = plan.axes;
    const double first = (*move_start(moved.front()))[axes.length];
    const double last = (*move_end(moved.back()))[axes.length];
    std::vector<double> marks{first, last};
    for (const Move& element : moved) {
        for (double at : level_crossings(element, axes, level)) marks.push_back(at);
    }
    const double along = plan.along;
    std::sort(marks.begin(), marks.end(), [along](double a, double b) { return along * a < along * b; });
    std::vector<std::pair<double, double>> found;
    for (std::size_t i = 0; i + 1 < marks.size(); ++i) {
        const double from = marks[i];
        const double to = marks[i + 1];
        if (along * (from - first) < -flat_mm || along * (to - last) > flat_mm) continue;
        if (along * (to - from) <= flat_mm) continue;
        const auto depth = depth_at(moved, axes, 0.5 * (from + to));
        if (!depth || plan.up * (level - *depth) <= flat_mm) continue;
        if (!found.empty() && std::abs(found.back().second - from) <= flat_mm) {
            found.back().second = to;  // the shape only touched the level here
        } else {
            found.emplace_back(from, to);
        }
    }
    return found;
}
}  // namespace

std::optional<Diagnostic> Executor::rough_pocket_levels(const RoughLevels& plan, const std::vector<Move>& moved,
                                                        std::vector<Move>& out) {
    const ContourAxes axes = plan.axes;
    const double up = plan.up;
    const double along = plan.along;
    double clear_d = plan.start_depth_mm;
    for (const Move& element : moved) {
        const Extent d = extent_along(element, axes.depth);
        clear_d = up > 0 ? std::max(clear_d, d.high) : std::min(clear_d, d.low);
    }
    const double shape_first = (*move_start(moved.front()))[axes.length];
    auto point = [&](double d, double l) {
        AxisVector p = position_;
        p[axes.depth] = d;
        p[axes.length] = l;
        return p;
    };
    auto rapid_to = [&](double d, double l) -> std::optional<Diagnostic> {
        if (point(d, l) == position_) return std::nullopt;
        return straight(g(0), point(d, l), out);
    };
    for (int k = 1; k <= plan.levels; ++k) {
        const double level = plan.start_depth_mm - up * k * plan.depth_of_cut_mm;
        const double level_above = level + up * plan.depth_of_cut_mm;
        for (const auto& [from, to] : stretches_below(moved, plan, level)) {
            const bool at_start = std::abs(from - shape_first) <= flat_mm;
            const double enter_l = at_start ? plan.start_length_mm : from;
            if (auto e = rapid_to(clear_d, position_[axes.length])) return e;
            if (auto e = rapid_to(clear_d, enter_l)) return e;
            if (at_start) {
                // As type I: in from A's length at the P block's speed.
                if (auto e = straight(plan.rapid_infeed ? g(0) : g(1), point(level, enter_l), out)) return e;
            } else {
                if (auto e = rapid_to(level_above, enter_l)) return e;
                if (auto e = straight(g(1), point(level, enter_l), out)) return e;
            }
            if (auto e = straight(g(1), point(level, to), out)) return e;
            const double escape = std::min(plan.escape_mm, std::abs(to - enter_l));
            if (escape > 0) {
                if (auto e = straight(g(1), point(level + up * escape, to - along * escape), out)) return e;
            }
            if (auto e = rapid_to(clear_d, position_[axes.length])) return e;
        }
    }
    if (auto e = rapid_to(clear_d, position_[axes.length])) return e;
    return rapid_to(clear_d, plan.start_length_mm);
}

}  // namespace nckit::interp
