// Motion: the block's target in machine coordinates, then a Line, Arc or SyncMove to it, each
// checked against the machine's travel before it is queued.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "executor.hpp"
#include "lathe_codes.hpp"
#include "nckit/interp/arc_geometry.hpp"

namespace nckit::interp {

namespace {
// Arc end points closer than this in the plane make a full circle (mm).
constexpr double full_circle_mm = 1e-9;
// Relative radius mismatch allowed on top of the absolute tolerance, as LinuxCNC allows.
constexpr double radius_relative_tolerance = 0.001;
}  // namespace

AxisVector Executor::target_from_words(bool machine_coordinates) const {
    AxisVector target = position_;
    AxisVector offset = program_offset();
    for (const AxisConfig& axis : machine_.axes) {
        const Word* word = words_.word(letter(axis.axis));
        if (word == nullptr) continue;
        double value = axis_value(axis.axis, *word);
        if (machine_coordinates) {
            target[axis.axis] = value;
        } else if (modal_.incremental || words_.incremental_letter[letter(axis.axis) - 'A']) {
            target[axis.axis] = position_[axis.axis] + value;
        } else {
            target[axis.axis] = value + offset[axis.axis];
        }
    }
    return target;
}

double Executor::spindle_rpm_at(double work_x_radius_mm) const {
    const SpindleState& spindle = modal_.spindle;
    if (!spindle.constant_surface_speed) return spindle.rpm;
    double limit = machine_.spindle.max_rpm;
    if (spindle.rpm_clamp > 0) limit = std::min(limit, spindle.rpm_clamp);
    double radius_m = std::abs(work_x_radius_mm) / 1000.0;
    if (radius_m <= 0) return limit;
    return std::min(limit, spindle.surface_speed_m_min / (2.0 * std::numbers::pi * radius_m));
}

double Executor::work_x() const {
    return position_[Axis::X] - program_offset()[Axis::X];
}

Feed Executor::current_feed() const {
    Feed feed;
    feed.mode = modal_.feed_mode;
    if (feed.mode == FeedMode::per_minute) {
        feed.mm_per_min = modal_.feed;
    } else {
        feed.mm_per_rev = modal_.feed;
        feed.mm_per_min = modal_.feed * spindle_rpm_at(work_x());
    }
    return feed;
}

std::optional<Diagnostic> Executor::check_travel(const AxisVector& low, const AxisVector& high) const {
    for (const AxisConfig& axis : machine_.axes) {
        double lo = low[axis.axis];
        double hi = high[axis.axis];
        if (lo >= axis.min - 1e-9 && hi <= axis.max + 1e-9) continue;
        bool below = lo < axis.min - 1e-9;
        const char* unit = axis.kind == AxisKind::rotary ? "deg" : "mm";
        return error(column_of(letter(axis.axis)), "travel-limit",
                     fmt::format("{} would move to {:.4f} {}, beyond its travel limit {:.4f} {}", letter(axis.axis),
                                 below ? lo : hi, unit, below ? axis.min : axis.max, unit));
    }
    return std::nullopt;
}

std::optional<Diagnostic> Executor::check_line_travel(const AxisVector& target) const {
    // A straight move stays inside the box of its end points, so they are all there is to check.
    AxisVector low;
    AxisVector high;
    for (std::size_t i = 0; i < axis_count; ++i) {
        low[i] = std::min(position_[i], target[i]);
        high[i] = std::max(position_[i], target[i]);
    }
    return check_travel(low, high);
}

std::optional<Diagnostic> Executor::move(std::vector<Move>& out) {
    GCode non_modal = words_.group(ModalGroup::non_modal);
    if (non_modal == g(28) || non_modal == g(30)) return home(out);
    if (!is_lathe_single_cycle(motion_)) modal_.lathe.single = LatheSingleCycle{};
    if (is_lathe_repetitive_cycle(non_modal)) return lathe_repetitive_cycle(out);
    if (is_lathe_single_cycle(motion_)) {
        if (!block_has_axis_words()) return std::nullopt;
        return lathe_single_cycle(out);
    }
    if (non_modal == g(31)) return probe(out);
    // G92.1 takes no axis words: check_words() gave any to the motion mode, so they move.
    if (non_modal == g(4) || non_modal == g(10) || non_modal == g(52) || non_modal == g(92) || non_modal == g(50) ||
        motion_ == g(80) || words_.group(ModalGroup::length_comp) == g(43, 1)) {
        return std::nullopt;
    }
    if (is_drilling_cycle(motion_)) {
        if (!block_has_axis_words()) return std::nullopt;
        return drill(out);
    }
    bool arc_offsets = words_.has('I') || words_.has('J') || words_.has('K') || words_.has('R');
    bool is_arc = motion_ == g(2) || motion_ == g(3);
    if (!block_has_axis_words() && !(is_arc && arc_offsets)) return std::nullopt;
    AxisVector target = target_from_words(non_modal == g(53));
    if (is_arc) return arc(motion_, target, out);
    if (motion_ == g(32) || motion_ == g(33)) return sync(target, out);
    return straight(motion_, target, out);
}

std::optional<Diagnostic> Executor::straight(GCode motion, const AxisVector& target, std::vector<Move>& out) {
    if (auto e = check_line_travel(target)) return e;
    Line line{position_, target, Feed{}, motion == g(0), modal_.path};
    // A drilling cycle's moves end at rest: each is a reversal or a change of kind.
    if (is_drilling_cycle(motion_)) line.path.exact_stop = true;
    if (!line.rapid) line.feed = current_feed();
    if (words_.group(ModalGroup::exact_stop) >= 0) line.path.exact_stop = true;
    push(out, line);
    position_ = target;
    return std::nullopt;
}

std::optional<Diagnostic> Executor::home(std::vector<Move>& out) {
    // Fanuc and LinuxCNC: through the intermediate point the axis words give (in the active
    // distance mode), then to the reference point, each by rapid; with no axis words, every axis
    // goes straight to its reference point.
    // G30: the second reference point, the machine's tool-change position where it has one.
    const bool second = words_.group(ModalGroup::non_modal) == g(30);
    AxisVector reference = position_;
    bool any_word = block_has_axis_words();
    for (const AxisConfig& axis : machine_.axes) {
        double point = second && axis.tool_change ? *axis.tool_change : axis.home;
        if (!any_word || words_.has(letter(axis.axis))) reference[axis.axis] = point;
    }
    if (any_word) {
        if (auto e = straight(g(0), target_from_words(false), out)) return e;
    }
    return straight(g(0), reference, out);
}

std::optional<Diagnostic> Executor::sync(const AxisVector& target, std::vector<Move>& out) {
    const Word* lead_word = words_.has('K') ? words_.word('K') : words_.has('E') ? words_.word('E') : words_.word('F');
    if (lead_word == nullptr) {
        return error(motion_column(), "missing-word", "thread needs its lead (F, E or K, mm per revolution)");
    }
    double lead = offset_value(*lead_word);
    if (lead <= 0) return error(lead_word->column, "bad-value", "thread lead must be positive");
    double start_angle_deg = 0;
    if (const Word* q = words_.word('Q')) {
        if (auto e = thread_start_angle(*q, start_angle_deg)) return e;
    }
    if (auto e = check_line_travel(target)) return e;
    Feed feed;
    feed.mode = FeedMode::per_revolution;
    feed.mm_per_rev = lead;
    // Under G96 the speed is the surface speed's rpm at the start, as for G95 feeds.
    feed.mm_per_min = lead * spindle_rpm_at(work_x());
    push(out, SyncMove{position_, target, feed, start_angle_deg});
    position_ = target;
    return std::nullopt;
}

void Executor::warn_if_implausibly_small(const Arc& arc) {
    // A circle under 0.2 mm across is no bore or pocket a mill cuts: most often an inch program
    // read in mm (G20 missing; a 0.092 in bore is 2.34 mm). A warning, once a run: it still runs.
    constexpr double smallest_plausible_diameter_mm = 0.2;
    const double diameter_mm = 2.0 * arc_start_radius(arc);
    if (warned_small_arc_ || inch_units() || !options_.on_warning || !(diameter_mm < smallest_plausible_diameter_mm)) {
        return;
    }
    warned_small_arc_ = true;
    warn(motion_column(), "implausible-size",
         fmt::format("an arc of {:.4g} mm diameter: implausibly small for a cut; is the program "
                     "in inches (G20 missing)?",
                     diameter_mm));
}

std::optional<Diagnostic> Executor::arc(GCode motion, const AxisVector& target, std::vector<Move>& out) {
    Arc arc;
    arc.from = position_;
    arc.to = target;
    arc.plane = modal_.plane;
    arc.direction = motion == g(2) ? ArcDirection::clockwise : ArcDirection::counterclockwise;
    arc.feed = current_feed();
    arc.path = modal_.path;
    if (words_.group(ModalGroup::exact_stop) >= 0) arc.path.exact_stop = true;
    arc.center = position_;
    PlaneAxes p = plane_axes(arc.plane);
    double d1 = target[p.first] - position_[p.first];
    double d2 = target[p.second] - position_[p.second];
    double chord = std::hypot(d1, d2);

    if (const Word* r_word = words_.word('R')) {
        double r = offset_value(*r_word);
        if (chord < full_circle_mm) {
            return error(r_word->column, "bad-arc", "an R arc cannot be a full circle: give I/J/K");
        }
        double half = chord / 2.0;
        double radius = std::abs(r);
        if (radius < half) {
            if (half - radius > options_.r_arc_tolerance_mm) {
                return error(r_word->column, "bad-arc",
                             fmt::format("radius {:.4f} mm is too small to reach the end point "
                                         "({:.4f} mm away)",
                                         radius, chord));
            }
            radius = half;
        }
        double rise = std::sqrt(std::max(0.0, radius * radius - half * half));
        double side = (arc.direction == ArcDirection::counterclockwise ? 1.0 : -1.0) * (r > 0 ? 1.0 : -1.0);
        arc.center[p.first] = position_[p.first] + d1 / 2.0 - side * rise * d2 / chord;
        arc.center[p.second] = position_[p.second] + d2 / 2.0 + side * rise * d1 / chord;
    } else {
        auto offset = [&](char letter) {
            const Word* w = words_.word(letter);
            return w != nullptr ? offset_value(*w) : 0.0;
        };
        const char first = arc.plane == Plane::yz ? 'J' : 'I';
        const char second = arc.plane == Plane::xy ? 'J' : 'K';
        // G18's plane runs Z then X, but its offsets are still named I (X) and K (Z).
        double o1 = arc.plane == Plane::zx ? offset('K') : offset(first);
        double o2 = arc.plane == Plane::zx ? offset('I') : offset(second);
        if (modal_.arc_centers_absolute) {
            // G90.1: I J K are the centre's coordinates in the work system (absent: 0).
            AxisVector origin = program_offset();
            arc.center[p.first] = origin[p.first] + o1;
            arc.center[p.second] = origin[p.second] + o2;
        } else {
            arc.center[p.first] = position_[p.first] + o1;
            arc.center[p.second] = position_[p.second] + o2;
        }
        double r0 = arc_start_radius(arc);
        double r1 = arc_end_radius(arc);
        if (r0 < full_circle_mm) return error(motion_column(), "bad-arc", "arc has zero radius");
        double mismatch = std::abs(r1 - r0);
        // LinuxCNC's inch tolerance is ten times its metric one in its own unit: 2.54 times in mm.
        const double tolerance = options_.arc_radius_tolerance_mm * (modal_.length_factor_mm != 1.0 ? 2.54 : 1.0);
        const double relative = mismatch / std::max(r0, r1);
        if (mismatch > 100.0 * tolerance || (mismatch > tolerance && relative > radius_relative_tolerance)) {
            return error(motion_column(), "bad-arc",
                         fmt::format("end point is not on the arc: radius {:.4f} mm at the start, "
                                     "{:.4f} mm at the end",
                                     r0, r1));
        }
    }
    AxisBox box = arc_bounds(arc);
    if (auto e = check_travel(box.low, box.high)) return e;
    warn_if_implausibly_small(arc);
    push(out, arc);
    position_ = target;
    return std::nullopt;
}

}  // namespace nckit::interp
