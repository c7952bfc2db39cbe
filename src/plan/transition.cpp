#include "transition.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "chain_state.hpp"
#include "chord_distance.hpp"
#include "hull_verdict.hpp"
#include "quintic_bounds.hpp"
#include "ramp_transition.hpp"

namespace nckit::plan_detail {

namespace {

// The deviation is measured at this many points of the curve; the target leaves a margin for
// what lies between them (the curve is smooth and its points move by < 1/64 of it per step).
constexpr int deviation_samples = 32;
constexpr double deviation_target = 0.95;
// The curve must keep moving forward: |dp/ds| at least this everywhere sampled (no cusp or loop).
constexpr double min_parametric_speed = 0.3;
constexpr int max_attempts = 48;
constexpr double min_trim_mm = 1e-7;
// Bisection steps of widen_quintic.
constexpr int widen_steps = 8;
// A ramp transition replaces the single quintic only where its turning speed (ramp_transition.hpp)
// is higher by this factor: the estimate leaves out the path's own acceleration and jerk and the
// run boundaries its extra quintics add, so a ramp that is barely faster by it is slower in the
// plan. Measured on the 100 semicircles at j 5,000 (both held near 20 mm/s by the curvature
// rate): 46.677 s with no margin, 46.364 s with 1.005, 46.431 s with 1.01 to 1.03 (a single
// quintic everywhere: 46.441 s); 1.03 also gave up the slots' gain at j 50,000 (1.604 -> 1.628 s
// at F6000).
constexpr double ramp_speed_margin = 1.005;
// Chained transitions take an arc-length parameter up to this half turn between their ends.
constexpr double chained_max_half_turn_rad = 0.5;

//! What point_at takes for a line: no circular and no polynomial part.
bool is_line(const PathSegment& g) {
    return g.shape != SegmentShape::quintic && !(g.radius_mm > 0);
}

//! point_at(g, s) written to `out`; a line's directly (the value point_at returns would be
//! copied again).
void point_into(PathPoint& out, const PathSegment& g, double s) {
    if (!is_line(g)) {
        out = point_at(g, s);
        return;
    }
    for (std::size_t i = 0; i < axis_count; ++i) {
        out.position[i] = g.origin[i] + g.rate[i] * s;
        out.d1[i] = g.rate[i];
        out.d2[i] = 0;
        out.d3[i] = 0;
    }
}

double distance3(const AxisVector& a, const AxisVector& b) {
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

//! Distance from p to the XYZ chord a–b.
double to_chord(const AxisVector& p, const AxisVector& a, const AxisVector& b) {
    return std::sqrt(distance2_to_chord(p, a, b));
}

//! Points along s in [s0, s1] of a segment, as chords; a line is its own chord, an arc gets
//! enough chords that their sagitta stays far below any tolerance, and that sagitta is added.
struct Piece {
    std::array<AxisVector, 33> points{};
    int count = 0;
    double sagitta = 0;
};

Piece piece_of(const PathSegment& g, double s0, double s1) {
    Piece out;
    const int chords = g.radius_mm > 0 ? 32 : 1;
    for (int k = 0; k <= chords; ++k) out.points[k] = position_at(g, s0 + (s1 - s0) * k / chords);
    out.count = chords + 1;
    if (g.radius_mm > 0) {
        const double half_angle = 0.5 * std::abs(g.angle_rate) * (s1 - s0) / chords;
        out.sagitta = g.radius_mm * (1 - std::cos(half_angle));
    }
    return out;
}

double to_piece(const AxisVector& p, const Piece& piece) {
    double best = piece.count == 1 ? distance3(p, piece.points[0]) : 1e300;
    for (int k = 0; k + 1 < piece.count; ++k) best = std::min(best, to_chord(p, piece.points[k], piece.points[k + 1]));
    return best + piece.sagitta;
}

void measure_into(const PathSegment& curve, const Piece& tail, const Piece& head, double stop_above_mm,
                  CurveDeviation& out);

}  // namespace

void trim_start_into(PathSegment& out, const PathSegment& g, double trim) {
    if (!is_line(g)) {
        out = trim_start(g, trim);
        return;
    }
    const AxisVector origin = position_at(g, trim);
    if (&out != &g) out = g;
    out.length = g.length - trim;
    out.origin = origin;
}

bool smooth_join(const PathSegment& before, const PathSegment& after, double direction_tolerance, bool curvature_too) {
    if (is_line(before) && is_line(after)) {
        // A line's direction is its rate everywhere and its curvature 0 (point_at).
        for (std::size_t i = 0; i < axis_count; ++i) {
            if (std::abs(before.rate[i] - after.rate[i]) > direction_tolerance) return false;
        }
        return true;
    }
    const PathPoint e = point_at(before, before.length);
    const PathPoint s = point_at(after, 0.0);
    for (std::size_t i = 0; i < axis_count; ++i) {
        if (std::abs(e.d1[i] - s.d1[i]) > direction_tolerance) return false;
        if (curvature_too && std::abs(e.d2[i] - s.d2[i]) > smooth_curvature_tolerance) return false;
    }
    return true;
}

CurveDeviation measure_deviation(const PathSegment& curve, const Transition& replaced, double stop_above_mm) {
    return measure_deviation(&curve, 1, replaced, stop_above_mm);
}

CurveDeviation measure_deviation(const PathSegment* curves, std::size_t count, const Transition& replaced,
                                 double stop_above_mm) {
    const Piece tail = piece_of(replaced.replaced_before, 0.0, replaced.replaced_before.length);
    const Piece head = piece_of(replaced.replaced_after, 0.0, replaced.replaced_after.length);
    CurveDeviation out;
    out.slowest = 1e300;
    for (std::size_t c = 0; c < count && out.deviation_mm <= stop_above_mm; ++c) {
        const PathSegment& curve = curves[c];
        measure_into(curve, tail, head, stop_above_mm, out);
    }
    return out;
}

namespace {

void measure_into(const PathSegment& curve, const Piece& tail, const Piece& head, double stop_above_mm,
                  CurveDeviation& out) {
    const double length = curve.length;
    for (int k = 0; k <= deviation_samples; ++k) {
        // XYZ position and slope only (point_at would do every axis and two more derivatives).
        const double s = length * k / deviation_samples;
        AxisVector q;
        double speed2 = 0;
        for (std::size_t i = 0; i < 3; ++i) {
            const double c1 = curve.rate[i];
            const double c2 = curve.poly[0][i];
            const double c3 = curve.poly[1][i];
            const double c4 = curve.poly[2][i];
            const double c5 = curve.poly[3][i];
            q[i] = curve.origin[i] + s * (c1 + s * (c2 + s * (c3 + s * (c4 + s * c5))));
            const double d1 = c1 + s * (2 * c2 + s * (3 * c3 + s * (4 * c4 + s * 5 * c5)));
            speed2 += d1 * d1;
        }
        out.deviation_mm = std::max(out.deviation_mm, std::min(to_piece(q, tail), to_piece(q, head)));
        out.slowest = std::min(out.slowest, std::sqrt(speed2));
        if (out.deviation_mm > stop_above_mm) break;
    }
}

}  // namespace

namespace {

//! The parameter length of the curve between the states: the mean of its chord and the trims,
//! or, `chained` between two lines, the arc length of the circle with the end directions.
double curve_length(const Transition& t, const PathPoint& a, const PathPoint& b, bool chained) {
    const double chord = distance3(a.position, b.position);
    double length = 0.5 * (chord + t.trim_before + t.trim_after);
    if (chained && t.replaced_before.shape == SegmentShape::line && t.replaced_after.shape == SegmentShape::line) {
        // On a chain of lines the curve samples a smooth path: its parameter length is that path's arc
        // length, estimated by the circular arc with the end directions, chord·(φ/2)/sin(φ/2).
        // Any other length makes |q'| vary along the quintic, which adds to its third derivative
        // (a jerk term, times the speed cubed) in proportion to the length error over L³: on
        // the 0.06 mm chords of an r 20 circle the mean of chord and trims is short by about the
        // arc's excess over its chord, h³/(24·r²) = 2.6e-8 mm, and the third derivative along
        // the path came to 0.0056 /mm² where the circle has 1/r² = 0.0025.
        const double c = std::clamp(a.d1[0] * b.d1[0] + a.d1[1] * b.d1[1] + a.d1[2] * b.d1[2], -1.0, 1.0);
        const double half_turn = 0.5 * std::acos(c);
        if (half_turn < chained_max_half_turn_rad) {
            length = half_turn > 1e-12 ? chord * half_turn / std::sin(half_turn) : chord;
        }
    }
    return length;
}

//! Builds the curve of parameter length `length` between the states and measures it against the
//! replaced path; false when it leaves the tolerance (target fraction) or nearly stops moving
//! along its parameter. The curve goes to `curve` and its measured deviation to `deviation_mm`
//! (also on failure).
bool build_of_length(const Transition& t, const PathPoint& a, const PathPoint& b, double length, double tolerance_mm,
                     PathSegment& curve, double& deviation_mm) {
    write_quintic(curve, a, b, length, AxisVector{});
    const double bound = hull_verdict(curve, t, a.position, b.position, min_parametric_speed);
    if (bound >= 0 && bound <= deviation_target * tolerance_mm) {
        deviation_mm = bound;
        return true;
    }
    const CurveDeviation measured = measure_deviation(curve, t, tolerance_mm);
    deviation_mm = measured.deviation_mm;
    return measured.deviation_mm <= deviation_target * tolerance_mm && measured.slowest >= min_parametric_speed;
}

//! build_of_length with the curve_length.
bool build(const Transition& t, const PathPoint& a, const PathPoint& b, double tolerance_mm, PathSegment& curve,
           double& deviation_mm, bool chained = false) {
    return build_of_length(t, a, b, curve_length(t, a, b, chained), tolerance_mm, curve, deviation_mm);
}

}  // namespace

namespace {

//! Sets the trims of `out` and the points its curve runs between (not the curve itself).
void set_trims(Transition& out, const PathSegment& before, double trim_a, const PathSegment& after, double trim_b) {
    out.trim_before = trim_a;
    out.trim_after = trim_b;
    trim_start_into(out.replaced_before, before, before.length - trim_a);
    out.replaced_after = after;
    out.replaced_after.length = trim_b;
    point_into(out.start, before, before.length - trim_a);
    point_into(out.end, after, trim_b);
    out.chained = false;
}

//! Whether the curvature jumps where `before` meets `after`, an arc on at least one side: by
//! more than half of the larger curvature (a line into an arc, arcs turning opposite ways, not
//! two arcs of one circle whose rounded end points leave a kink).
bool curvature_jumps(const PathSegment& before, const PathSegment& after) {
    if (before.shape != SegmentShape::arc && after.shape != SegmentShape::arc) return false;
    const PathPoint a = point_at(before, before.length);
    const PathPoint b = point_at(after, 0.0);
    double jump2 = 0;
    double a2 = 0;
    double b2 = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        jump2 += (a.d2[i] - b.d2[i]) * (a.d2[i] - b.d2[i]);
        a2 += a.d2[i] * a.d2[i];
        b2 += b.d2[i] * b.d2[i];
    }
    return jump2 > 0.25 * std::max(a2, b2);
}

//! The trim of `before` for a trim t on both sides: at most its room, and all of it where less
//! than a sliver would be left.
double before_trim(const PathSegment& before, double before_room, double t) {
    const double trim = std::min(t, before_room);
    return before.length - trim < min_leftover_mm ? before.length : trim;
}

//! `out` (built with the trim ok_t on both sides, within each side's room) widened towards
//! failed_t, whose curve left the tolerance, by bisection: the widest trim keeps the curvature's
//! rate lowest, and under a jerk limit that rate sets the speed at a join of arcs
//! (docs/planner.md, "The widest trims at joins of arcs").
void widen_quintic(const PathSegment& before, double before_room, const PathSegment& after, double after_room,
                   double tolerance_mm, double ok_t, double failed_t, Transition& out) {
    Transition trial = out;
    for (int step = 0; step < widen_steps; ++step) {
        const double t = 0.5 * (ok_t + failed_t);
        set_trims(trial, before, before_trim(before, before_room, t), after, std::min(t, after_room));
        if (build(trial, trial.start, trial.end, tolerance_mm, trial.curve, trial.deviation_mm)) {
            ok_t = t;
            out = trial;
        } else {
            failed_t = t;
        }
    }
}

bool single_quintic(const PathSegment& before, double before_room, const PathSegment& after, double after_room,
                    double tolerance_mm, Transition& out, const ChainStart* chain, bool widest) {
    if (!(tolerance_mm > 0) || before.shape == SegmentShape::quintic || after.shape == SegmentShape::quintic) {
        return false;
    }
    // The quintic covers XYZ; any other axis would arrive at the wrong place (its length differs
    // from the trims), so they must stand.
    for (std::size_t i = 3; i < axis_count; ++i) {
        if (before.rate[i] != 0 || after.rate[i] != 0) return false;
    }
    before_room = std::min(before_room, before.length);
    after_room = std::min(after_room, after.length);
    // A sliver of `before` left over would be a segment of its own: take it into the curve.
    if (before.length - before_room < min_leftover_mm) before_room = before.length;
    // The first attempt takes all the room on both sides, even when it differs: on a chain of
    // short lines of unequal lengths, equal trims would leave a piece of every longer line, a
    // straight piece (curvature 0) between two transitions, where the jerk terms must pay for
    // the curvature pulse. Taking the whole room lets the transitions meet at the lines' middles
    // with a common curvature (ChainStart). Failing the tolerance, both shrink alike.
    double t = std::max(before_room, after_room);
    double failed_t = 0;  // the last trim whose curve left the tolerance
    for (int attempt = 0; attempt < max_attempts; ++attempt) {
        const double trim_a = before_trim(before, before_room, t);
        const double trim_b = std::min(t, after_room);
        if (!(trim_a > min_trim_mm && trim_b > min_trim_mm)) return false;
        set_trims(out, before, trim_a, after, trim_b);
        if (chain != nullptr && trim_a == before.length) {
            // `before` is eaten: start with the curvature of the turn between the outer ends of
            // the two transitions that meet on it (see ChainStart).
            // The start moves onto the curve the chain samples (chain_state.hpp), with its
            // direction and curvature; it is set in place, and put back when the curve fails.
            const double length = 0.5 * (distance3(out.start.position, out.end.position) + trim_a + trim_b);
            const std::array<double, 3> own_position{out.start.position[0], out.start.position[1],
                                                     out.start.position[2]};
            const std::array<double, 3> own_d1{out.start.d1[0], out.start.d1[1], out.start.d1[2]};
            const std::array<double, 3> own_d2{out.start.d2[0], out.start.d2[1], out.start.d2[2]};
            const ChainMidState mid = chain_mid_state(chain->entry_start_d1, chain->entry_length, own_d1, 2 * trim_a,
                                                      {out.end.d1[0], out.end.d1[1], out.end.d1[2]}, length);
            for (std::size_t i = 0; i < 3; ++i) {
                out.start.position[i] += mid.offset[i];
                out.start.d1[i] = mid.d1[i];
                out.start.d2[i] = mid.d2[i];
            }
            if (build(out, out.start, out.end, tolerance_mm, out.curve, out.deviation_mm, true)) {
                out.chained = true;
                return true;
            }
            for (std::size_t i = 0; i < 3; ++i) {
                out.start.position[i] = own_position[i];
                out.start.d1[i] = own_d1[i];
                out.start.d2[i] = own_d2[i];
            }
        }
        if (build(out, out.start, out.end, tolerance_mm, out.curve, out.deviation_mm)) {
            // Under a jerk limit the curve at a join of arcs is as wide as the tolerance allows.
            if (widest && failed_t > t)
                widen_quintic(before, before_room, after, after_room, tolerance_mm, t, failed_t, out);
            return true;
        }
        failed_t = t;
        const double target = deviation_target * tolerance_mm;
        const double shrink = out.deviation_mm > target ? 0.9 * target / out.deviation_mm : 0.5;
        t = std::max(trim_a, trim_b) * std::clamp(shrink, 0.05, 0.8);
    }
    return false;
}

}  // namespace

bool make_transition(const PathSegment& before, double before_room, const PathSegment& after, double after_room,
                     double tolerance_mm, Transition& out, const ChainStart* chain, const TurningLimits* turning) {
    const bool quintic = single_quintic(before, before_room, after, after_room, tolerance_mm, out, chain,
                                        turning != nullptr && curvature_jumps(before, after));
    out.more.clear();
    if (turning == nullptr || (quintic && out.chained) ||
        (before.shape != SegmentShape::arc && after.shape != SegmentShape::arc)) {
        return quintic;
    }
    // Arcs joined tangentially with a jump in curvature: the ramp transition curves less near its
    // ends; it is kept when its curves allow the higher speed (ramp_transition.hpp).
    Transition ramp;
    if (!make_ramp_transition(before, before_room, after, after_room, tolerance_mm, *turning, ramp)) return quintic;
    if (quintic && !(turning_speed(ramp, *turning) > ramp_speed_margin * turning_speed(out, *turning))) return true;
    out = std::move(ramp);
    return true;
}

namespace {

//! rebuild_with_end_state's build in place; failing, the end state is put back, and the curve
//! holds whatever the failed build left.
bool build_end_state(Transition& transition, const std::array<double, 3>& end_position,
                     const std::array<double, 3>& end_d1, const std::array<double, 3>& end_d2, double tolerance_mm) {
    PathPoint& end = transition.end;
    const std::array<double, 3> old_position{end.position[0], end.position[1], end.position[2]};
    const std::array<double, 3> old_d1{end.d1[0], end.d1[1], end.d1[2]};
    const std::array<double, 3> old_d2{end.d2[0], end.d2[1], end.d2[2]};
    // A chained transition that keeps its end point and direction keeps the length curve_length
    // gave it (which needs no trigonometry again).
    const bool same_length = transition.chained && end_position == old_position && end_d1 == old_d1;
    auto set_end = [&](const std::array<double, 3>& position, const std::array<double, 3>& d1,
                       const std::array<double, 3>& d2) {
        for (std::size_t i = 0; i < 3; ++i) {
            end.position[i] = position[i];
            end.d1[i] = d1[i];
            end.d2[i] = d2[i];
        }
    };
    const double old_length = transition.curve.length;
    set_end(end_position, end_d1, end_d2);
    const double length = same_length ? old_length : curve_length(transition, transition.start, end, true);
    double deviation_mm = 0;
    if (build_of_length(transition, transition.start, end, length, tolerance_mm, transition.curve, deviation_mm)) {
        transition.deviation_mm = deviation_mm;
        return true;
    }
    set_end(old_position, old_d1, old_d2);
    return false;
}

}  // namespace

bool rebuild_with_end_state(Transition& transition, const std::array<double, 3>& end_position,
                            const std::array<double, 3>& end_d1, const std::array<double, 3>& end_d2,
                            double tolerance_mm) {
    // Built in place. Failing, the end state is put back and the curve with it: a chained curve
    // is the quintic between its states with its own length (single_quintic), so building it
    // again gives the same numbers; any other curve is kept as a copy (a local of its own: an
    // optional copy was zeroed on every call, chained or not).
    if (!transition.chained) {
        const PathSegment kept = transition.curve;
        if (build_end_state(transition, end_position, end_d1, end_d2, tolerance_mm)) return true;
        transition.curve = kept;
        return false;
    }
    const double old_length = transition.curve.length;
    if (build_end_state(transition, end_position, end_d1, end_d2, tolerance_mm)) return true;
    write_quintic(transition.curve, transition.start, transition.end, old_length, AxisVector{});
    return false;
}

std::optional<Rebuilt> with_end_states(const Transition& transition, const std::array<double, 3>& start_d1,
                                       const std::array<double, 3>& start_d2, const std::array<double, 3>& end_d1,
                                       const std::array<double, 3>& end_d2, double tolerance_mm) {
    Rebuilt out;
    out.start = transition.start;
    out.end = transition.end;
    for (std::size_t i = 0; i < 3; ++i) {
        out.start.d1[i] = start_d1[i];
        out.start.d2[i] = start_d2[i];
        out.end.d1[i] = end_d1[i];
        out.end.d2[i] = end_d2[i];
    }
    if (!build(transition, out.start, out.end, tolerance_mm, out.curve, out.deviation_mm, true)) return std::nullopt;
    return out;
}

void apply(Transition& transition, const Rebuilt& rebuilt) {
    transition.curve = rebuilt.curve;
    transition.start = rebuilt.start;
    transition.end = rebuilt.end;
    transition.deviation_mm = rebuilt.deviation_mm;
}

}  // namespace nckit::plan_detail
