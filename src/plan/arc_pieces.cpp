#include "arc_pieces.hpp"

#include "nckit/plan/segment_limits.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace nckit::plan_detail {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();
//! An arc whose curvature term d2·F² takes at most this share of every axis's acceleration
//! stays whole: its speed is the feed almost everywhere, and its acceleration most of amax.
constexpr double split_normal_share = 0.1;
//! Each piece keeps at least this share of the path acceleration its axes allow (so a > 0 and
//! the speed can still change on it): its speed limit is then about 0.99 of the pointwise one.
constexpr double floor_tangential_share = 0.02;

struct PieceBounds {
    DerivativeBounds b;
    double length = 0;
    double v = 0;  //!< mm/s, the speed limit being chosen
};

//! The speed the feed and the axes' speeds allow on a segment with bounds b (d1·v <= vmax on
//! every axis), before any curvature term.
double feed_and_axes_speed(const DerivativeBounds& b, const MachineConfig& machine, double feed_mm_s) {
    double v = feed_mm_s / b.speed_factor;
    for (const AxisConfig& axis : machine.axes) {
        const std::size_t i = index(axis.axis);
        if (b.d1[i] > 0) v = std::min(v, axis.max_velocity / b.d1[i]);
    }
    return v;
}

//! The path acceleration piece `p` allows at speed v: min over axes of (amax − d2·v²)/d1.
double acceleration_at(const PieceBounds& p, const MachineConfig& machine, double v) {
    double a = inf;
    for (const AxisConfig& axis : machine.axes) {
        const std::size_t i = index(axis.axis);
        if (p.b.d1[i] > 0) a = std::min(a, (axis.max_acceleration - p.b.d2[i] * v * v) / p.b.d1[i]);
    }
    return a;
}

//! The highest v² reachable over the piece from (or braking to) the speed whose square is
//! `edge2`, when the piece's acceleration is what its own limit v leaves:
//! v² <= edge2 + 2·len·(amax − d2·v²)/d1 on every axis, i.e.
//! v² <= (edge2 + 2·len·amax/d1) / (1 + 2·len·d2/d1).
double reachable_speed2(const PieceBounds& p, const MachineConfig& machine, double edge2) {
    double v2 = inf;
    for (const AxisConfig& axis : machine.axes) {
        const std::size_t i = index(axis.axis);
        const double d1 = p.b.d1[i];
        if (d1 > 0) {
            const double twice = 2.0 * p.length;
            v2 = std::min(v2, (edge2 + twice * axis.max_acceleration / d1) / (1.0 + twice * p.b.d2[i] / d1));
        }
    }
    return v2;
}

//! The speed limit of a piece before the passes: feed, axis speeds, and the curvature term
//! leaving floor_tangential_share of the path acceleration.
double top_speed(const DerivativeBounds& b, const MachineConfig& machine, double feed_mm_s) {
    double v = feed_mm_s / b.speed_factor;
    double a_floor = inf;
    for (const AxisConfig& axis : machine.axes) {
        const std::size_t i = index(axis.axis);
        if (b.d1[i] > 0) {
            v = std::min(v, axis.max_velocity / b.d1[i]);
            a_floor = std::min(a_floor, floor_tangential_share * axis.max_acceleration / b.d1[i]);
        }
    }
    for (const AxisConfig& axis : machine.axes) {
        const std::size_t i = index(axis.axis);
        if (b.d2[i] > 0) {
            const double room = axis.max_acceleration - b.d1[i] * a_floor;
            v = std::min(v, std::sqrt(std::max(0.0, room) / b.d2[i]));
        }
    }
    return std::isfinite(v) ? v : 0.0;
}

//! The highest v >= 0 with d3·v³ + p·v <= room (d3, p >= 0): the one real root of
//! v³ + P·v − Q = 0 (P = p/d3, Q = room/d3) in a form without cancellation: with
//! u = cbrt(Q/2 + sqrt(Q²/4 + P³/27)) and w = P/(3u), v = u − w = Q/(u² + u·w + w²).
double cubic_speed(double d3, double p, double room) {
    if (!(room > 0)) return 0.0;
    if (!(d3 > 0)) return p > 0 ? room / p : inf;
    const double big_p = p / d3;
    const double big_q = room / d3;
    const double u = std::cbrt(0.5 * big_q + std::sqrt(0.25 * big_q * big_q + big_p * big_p * big_p / 27.0));
    const double w = big_p / (3.0 * u);
    // The last factor keeps rounding on the safe side of the bound.
    return big_q / (u * u + u * w + w * w) * (1.0 - 1e-12);
}

//! Whether an axis with bounds d1, d2, d3 keeps amax and jmax on a piece with speed limit v_top,
//! acceleration a and jerk j, counting the S-curve's knee: at speed v below v_top the profile's
//! |s̈| is at most min(a, sqrt(2·j·(v_top − v))) (it must come back to 0 before the speed
//! reaches its peak <= v_top, which takes a²/(2j) of speed). Checked over intervals of
//! δ = v_top − v, each bounded by its highest speed and its highest acceleration, so the test
//! errs on the safe side.
bool knee_fits(double d1, double d2, double d3, double v_top, double a, double j, double amax, double jmax) {
    constexpr int intervals = 16;
    const double reach = a * a / (2.0 * j);  // δ at which the knee reaches a
    auto fits = [&](double v, double acc) {
        v = std::max(0.0, v);
        return d2 * v * v + d1 * acc <= amax && d3 * v * v * v + 3.0 * d2 * v * acc + d1 * j <= jmax;
    };
    if (!fits(v_top - reach, a)) return false;
    const double rate = std::sqrt(2.0 * j * reach);  // = a
    for (int k = 0; k < intervals; ++k) {
        const double lo = reach * k * k / (intervals * intervals);
        const double hi_root = static_cast<double>(k + 1) / intervals;
        if (!fits(v_top - lo, rate * hi_root)) return false;
    }
    return true;
}

//! A jerk-limited piece's speed limit with path acceleration a and jerk j kept: the feed, each
//! axis's speed, d2·v² + d1·a <= amax and d3·v³ + 3·d2·v·a + d1·j <= jmax, raised where the
//! S-curve's knee allows it (knee_fits).
double jerk_limited_speed(const DerivativeBounds& b, const MachineConfig& machine, double feed_mm_s, double a,
                          double j) {
    double v = feed_and_axes_speed(b, machine, feed_mm_s);
    for (const AxisConfig& axis : machine.axes) {
        const std::size_t i = index(axis.axis);
        if (!(b.d2[i] > 0 || b.d3[i] > 0)) continue;
        const double amax = axis.max_acceleration;
        const double jmax = axis.max_jerk;
        double lo = b.d2[i] > 0 ? std::sqrt(std::max(0.0, amax - b.d1[i] * a) / b.d2[i]) : inf;
        lo = std::min(lo, cubic_speed(b.d3[i], 3.0 * b.d2[i] * a, jmax - b.d1[i] * j));
        if (!(lo < v)) continue;
        if (!(j > 0) || !std::isfinite(j)) {
            v = lo;
            continue;
        }
        // With no acceleration at the top speed: d2·v² <= amax, d3·v³ + d1·j <= jmax.
        double hi = b.d2[i] > 0 ? std::sqrt(amax / b.d2[i]) : inf;
        hi = std::min({hi, cubic_speed(b.d3[i], 0.0, jmax - b.d1[i] * j), v});
        for (int k = 0; k < 24 && hi > lo * (1.0 + 1e-6); ++k) {
            const double mid = 0.5 * (lo + hi);
            (knee_fits(b.d1[i], b.d2[i], b.d3[i], mid, a, j, amax, jmax) ? lo : hi) = mid;
        }
        v = std::min(v, lo);
    }
    return std::isfinite(v) ? v : 0.0;
}

//! Samples per piece for the signed ranges of its derivatives.
constexpr int sign_samples = 9;

//! The signed ranges of q', q'', q''' of axis i over `path`: the samples' extremes, widened by
//! the largest step between neighbouring samples (a value between two samples lies within half
//! a step of one of them while the derivative is monotone there, and a piece is short: 1.4° of
//! an arc, 1/32 of a transition), clamped into the bounds ±d1, ±d2, ±d3.
void set_signed_ranges(const std::array<PathPoint, sign_samples>& points, std::size_t i, CurvedAxis& c) {
    const auto range = [&](auto value, double bound) {
        double lo = value(points[0]);
        double hi = lo;
        double step = 0;
        for (int k = 1; k < sign_samples; ++k) {
            const double x = value(points[static_cast<std::size_t>(k)]);
            step = std::max(step, std::abs(x - value(points[static_cast<std::size_t>(k - 1)])));
            lo = std::min(lo, x);
            hi = std::max(hi, x);
        }
        return SignedRange{std::max(-bound, lo - step), std::min(bound, hi + step)};
    };
    c.q1 = range([i](const PathPoint& p) { return p.d1[i]; }, c.d1);
    c.q2 = range([i](const PathPoint& p) { return p.d2[i]; }, c.d2);
    c.q3 = range([i](const PathPoint& p) { return p.d3[i]; }, c.d3);
    c.signs_known = true;
}

//! A jerk-limited piece's curved axes, its speed limit (feed and axes' speeds) and its speed with
//! no path acceleration or jerk; no check (both speeds 0) when more than three axes curve.
PieceCheck piece_check(const PathSegment& path, const DerivativeBounds& b, const MachineConfig& machine,
                       double feed_mm_s) {
    std::array<PathPoint, sign_samples> points;
    for (int k = 0; k < sign_samples; ++k) {
        points[static_cast<std::size_t>(k)] = point_at(path, path.length * k / (sign_samples - 1));
    }
    PieceCheck check;
    double v = feed_and_axes_speed(b, machine, feed_mm_s);
    check.speed_limit = std::isfinite(v) ? v * (1.0 - 1e-9) : 0.0;
    for (const AxisConfig& axis : machine.axes) {
        const std::size_t i = index(axis.axis);
        if (!(b.d2[i] > 0 || b.d3[i] > 0)) {
            if (b.d1[i] > 0) {
                check.straight_acceleration = std::min(check.straight_acceleration, axis.max_acceleration / b.d1[i]);
                check.straight_jerk = std::min(check.straight_jerk, axis.max_jerk / b.d1[i]);
            }
            continue;
        }
        if (check.count == static_cast<int>(check.axes.size())) return PieceCheck{};
        CurvedAxis& curved = check.axes[static_cast<std::size_t>(check.count++)];
        curved = {b.d1[i], b.d2[i], b.d3[i], axis.max_acceleration, axis.max_jerk};
        set_signed_ranges(points, i, curved);
        if (b.d2[i] > 0) v = std::min(v, std::sqrt(axis.max_acceleration / b.d2[i]));
        if (b.d3[i] > 0) v = std::min(v, std::cbrt(axis.max_jerk / b.d3[i]));
    }
    check.cruise_velocity = std::isfinite(v) ? v * (1.0 - 1e-9) : 0.0;
    return check;
}

bool curvature_matters(const PathSegment& arc, const MachineConfig& machine, double feed_mm_s) {
    const DerivativeBounds b = derivative_bounds(arc);
    const double v = feed_and_axes_speed(b, machine, feed_mm_s);
    for (const AxisConfig& axis : machine.axes) {
        const std::size_t i = index(axis.axis);
        if (b.d2[i] * v * v > split_normal_share * axis.max_acceleration) return true;
    }
    return false;
}

}  // namespace

bool split_arc(const PathSegment& arc, const MachineConfig& machine, double feed_mm_s, bool starts_at_rest,
               bool ends_at_rest, std::vector<ArcPiece>& out) {
    if (arc.shape != SegmentShape::arc || !(arc.length > 0)) return false;
    const double turns = std::abs(arc.sweep_rad()) / (2.0 * M_PI);
    const int n = static_cast<int>(std::min<double>(max_arc_pieces, std::ceil(turns * arc_pieces_per_turn)));
    if (n < 2 || !curvature_matters(arc, machine, feed_mm_s)) return false;

    const double piece_length = arc.length / n;
    out.resize(static_cast<std::size_t>(n));
    std::vector<PieceBounds> pieces(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) {
        ArcPiece& piece = out[static_cast<std::size_t>(k)];
        const double start = k * piece_length;
        piece.path = trim_start(arc, start);
        piece.path.length = k + 1 == n ? arc.length - start : piece_length;
        piece.check = PieceCheck{};
        PieceBounds& p = pieces[static_cast<std::size_t>(k)];
        p.b = derivative_bounds(piece.path);
        p.length = piece.path.length;
        p.v = top_speed(p.b, machine, feed_mm_s);
    }
    // Forward: a piece entered below its limit must reach it with the acceleration that limit
    // leaves; where it cannot, its limit drops to the highest speed it reaches (which maximises
    // its exit speed: a lower limit leaves more acceleration). Backward likewise for braking.
    // Both passes only lower limits, so the forward pass's conditions still hold after the other.
    double entry = starts_at_rest ? 0.0 : inf;
    for (PieceBounds& p : pieces) {
        if (entry < p.v) p.v = std::min(p.v, std::sqrt(reachable_speed2(p, machine, entry * entry)));
        entry = p.v;
    }
    double exit = ends_at_rest ? 0.0 : inf;
    for (auto it = pieces.rbegin(); it != pieces.rend(); ++it) {
        if (exit < it->v) it->v = std::min(it->v, std::sqrt(reachable_speed2(*it, machine, exit * exit)));
        exit = it->v;
    }
    for (std::size_t k = 0; k < pieces.size(); ++k) {
        const PieceBounds& p = pieces[k];
        out[k].limits.max_velocity = p.v;
        out[k].limits.max_acceleration = acceleration_at(p, machine, p.v);
        out[k].limits.max_jerk = inf;
    }
    return true;
}

namespace {

//! Pieces of `segment` under a jerk limit, as split_arc_jerk_limited describes, n of them.
bool split_jerk_limited(const PathSegment& segment, int n, const MachineConfig& machine, double feed_mm_s,
                        double acceleration_share, double jerk_share, std::vector<ArcPiece>& out) {
    if (n < 2) return false;
    // Only where the curvature sets the speed: the whole segment's limits are below the feed and
    // the axes' speeds (else it runs at the feed whole, and keeps more acceleration).
    const DerivativeBounds whole = derivative_bounds(segment);
    const double cruise = feed_and_axes_speed(whole, machine, feed_mm_s);
    const ProfileLimits as_one = segment_limits(segment, machine, feed_mm_s, ProfileKind::scurve);
    if (!(as_one.max_velocity < cruise * (1.0 - 1e-9))) return false;
    // One path acceleration and jerk for the whole segment, so that its pieces share S-curve
    // runs: jerk_limited_jerk_share of each axis's jerk for j, and for a
    // jerk_limited_acceleration_share of its acceleration, at most what leaves
    // jerk_limited_coupling_share of its jerk to the coupling term 3·d2·v·a at the speed the
    // curvature alone allows (sqrt(amax/d2)).
    double a = inf;
    double j = inf;
    for (const AxisConfig& axis : machine.axes) {
        const std::size_t i = index(axis.axis);
        if (whole.d1[i] > 0) {
            a = std::min(a, acceleration_share * axis.max_acceleration / whole.d1[i]);
            j = std::min(j, jerk_share * axis.max_jerk / whole.d1[i]);
        }
        if (whole.d2[i] > 0) {
            const double turning_speed = std::min(cruise, std::sqrt(axis.max_acceleration / whole.d2[i]));
            a = std::min(a, jerk_limited_coupling_share * axis.max_jerk / (3.0 * whole.d2[i] * turning_speed));
        }
    }
    if (!std::isfinite(a) || !std::isfinite(j)) return false;
    const double piece_length = segment.length / n;
    out.resize(static_cast<std::size_t>(n));
    double fastest = 0;
    for (int k = 0; k < n; ++k) {
        ArcPiece& piece = out[static_cast<std::size_t>(k)];
        const double start = k * piece_length;
        piece.path = trim_start(segment, start);
        piece.path.length = k + 1 == n ? segment.length - start : piece_length;
        const DerivativeBounds b = derivative_bounds(piece.path);
        piece.limits.max_velocity = jerk_limited_speed(b, machine, feed_mm_s, a, j);
        piece.limits.max_acceleration = a;
        piece.limits.max_jerk = j;
        piece.check = piece_check(piece.path, b, machine, feed_mm_s);
        piece.check.limits_need_knee = true;  // jerk_limited_speed counts the knee
        fastest = std::max(fastest, piece.limits.max_velocity);
    }
    // Pieces slower than the whole segment everywhere (a short arc, a tight jerk budget): keep
    // it whole.
    return fastest > as_one.max_velocity;
}

}  // namespace

bool split_arc_jerk_limited(const PathSegment& arc, const MachineConfig& machine, double feed_mm_s,
                            std::vector<ArcPiece>& out) {
    if (arc.shape != SegmentShape::arc || !(arc.length > 0)) return false;
    const double turns = std::abs(arc.sweep_rad()) / (2.0 * M_PI);
    const int n = static_cast<int>(std::min<double>(max_arc_pieces, std::ceil(turns * arc_pieces_per_turn)));
    return split_jerk_limited(arc, n, machine, feed_mm_s, jerk_limited_acceleration_share, jerk_limited_jerk_share,
                              out);
}

bool split_transition_jerk_limited(const PathSegment& curve, const MachineConfig& machine, double feed_mm_s,
                                   std::vector<ArcPiece>& out, int pieces) {
    if (curve.shape != SegmentShape::quintic || !(curve.length > 0)) return false;
    return split_jerk_limited(curve, pieces, machine, feed_mm_s, transition_acceleration_share, transition_jerk_share,
                              out);
}

}  // namespace nckit::plan_detail
