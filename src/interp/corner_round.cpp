// Corner rounding (,R) and chamfering (,C) between a G1 line and the move after it, worked in
// the plane's two axes. Notation: the line runs from a to the corner p with unit direction u1 and
// length L1; the next move leaves p with unit direction u2 (an arc: its tangent at p). φ is the
// turning angle between u1 and u2, s = +1 for a left (counter-clockwise) turn, -1 for a right one.
#include "corner_round.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "nckit/interp/arc_geometry.hpp"

namespace nckit::interp {

namespace {

constexpr double pi = std::numbers::pi;
constexpr double length_eps_mm = 1e-6;   // a corner piece may use a move up to its whole length
constexpr double angle_eps_rad = 1e-6;   // straight on / straight back

struct P2 {
    double u = 0;
    double v = 0;
};
P2 operator+(P2 a, P2 b) { return {a.u + b.u, a.v + b.v}; }
P2 operator-(P2 a, P2 b) { return {a.u - b.u, a.v - b.v}; }
P2 operator*(P2 a, double k) { return {a.u * k, a.v * k}; }
double dot(P2 a, P2 b) { return a.u * b.u + a.v * b.v; }
double cross(P2 a, P2 b) { return a.u * b.v - a.v * b.u; }
double norm(P2 a) { return std::hypot(a.u, a.v); }
P2 left_of(P2 a) { return {-a.v, a.u}; }

P2 in_plane(const AxisVector& p, const PlaneAxes& axes) { return {p[axes.first], p[axes.second]}; }
AxisVector with_plane(AxisVector base, P2 q, const PlaneAxes& axes) {
    base[axes.first] = q.u;
    base[axes.second] = q.v;
    return base;
}

//! True when a and b differ only on the plane's two axes.
bool stays_in_plane(const AxisVector& a, const AxisVector& b, const PlaneAxes& axes) {
    for (std::size_t i = 0; i < axis_count; ++i) {
        if (i == index(axes.first) || i == index(axes.second)) continue;
        if (std::abs(a[i] - b[i]) > 1e-9) return false;
    }
    return true;
}

//! Angle from radial direction `from` to `to` about the centre, in the arc's direction, [0, 2π).
double sweep_between(P2 from, P2 to, ArcDirection direction) {
    double angle = std::atan2(cross(from, to), dot(from, to));
    if (direction == ArcDirection::clockwise) angle = -angle;
    return angle < 0 ? angle + 2 * pi : angle;
}

std::string does_not_fit(CornerKind kind, double size_mm, double needed_mm, double first_mm, double next_mm) {
    return fmt::format("{} {:.4g} mm does not fit: it needs {:.4f} mm of each move, the moves are {:.4f} and "
                       "{:.4f} mm long",
                       kind == CornerKind::round ? "corner radius ,R" : "chamfer ,C", size_mm, needed_mm, first_mm,
                       next_mm);
}

}  // namespace

std::variant<CornerResult, std::string> make_corner(const Line& first, const std::variant<Line, Arc>& next,
                                                    CornerKind kind, double size_mm, Plane plane) {
    const PlaneAxes axes = plane_axes(plane);
    if (!stays_in_plane(first.from, first.to, axes)) {
        return std::string("a move with a corner word must stay in the selected plane");
    }
    const P2 a = in_plane(first.from, axes);
    const P2 p = in_plane(first.to, axes);
    const double first_mm = norm(p - a);
    if (first_mm < length_eps_mm) return std::string("a corner word needs a move in the plane");
    const P2 u1 = (p - a) * (1.0 / first_mm);

    CornerResult result{first, next, Line{}};
    if (const Line* line = std::get_if<Line>(&next)) {
        if (line->rapid || !stays_in_plane(line->from, line->to, axes)) {
            return std::string("the block after a corner word must feed (G1, G2, G3) in the selected plane");
        }
        const P2 b = in_plane(line->to, axes);
        const double next_mm = norm(b - p);
        if (next_mm < length_eps_mm) return std::string("the block after a corner word must move in the plane");
        const P2 u2 = (b - p) * (1.0 / next_mm);
        const double phi = std::atan2(std::abs(cross(u1, u2)), dot(u1, u2));
        if (phi < angle_eps_rad) return std::string("the moves run straight on: there is no corner to round");
        if (pi - phi < angle_eps_rad) return std::string("the next move runs straight back: no corner can be made");
        // Rounding: the arc touches both lines r·tan(φ/2) from the corner; a chamfer starts c from it.
        const double trim_mm = kind == CornerKind::round ? size_mm * std::tan(phi / 2) : size_mm;
        if (trim_mm > first_mm + length_eps_mm || trim_mm > next_mm + length_eps_mm) {
            return does_not_fit(kind, size_mm, trim_mm, first_mm, next_mm);
        }
        const P2 start = p - u1 * trim_mm;
        const P2 end = p + u2 * trim_mm;
        result.first.to = with_plane(first.to, start, axes);
        Line shortened = *line;
        shortened.from = with_plane(line->from, end, axes);
        result.next = shortened;
        if (kind == CornerKind::chamfer) {
            result.corner = Line{result.first.to, shortened.from, first.feed, false, first.path};
            return result;
        }
        const double s = cross(u1, u2) > 0 ? 1.0 : -1.0;
        Arc fillet;
        fillet.from = result.first.to;
        fillet.to = shortened.from;
        fillet.center = with_plane(result.first.to, start + left_of(u1) * (s * size_mm), axes);
        fillet.plane = plane;
        fillet.direction = s > 0 ? ArcDirection::counterclockwise : ArcDirection::clockwise;
        fillet.feed = first.feed;
        fillet.path = first.path;
        result.corner = fillet;
        return result;
    }

    const Arc& arc = std::get<Arc>(next);
    if (kind == CornerKind::chamfer) return std::string("a chamfer ,C must be followed by a G1 line (an arc is not supported)");
    if (arc.plane != plane || !stays_in_plane(arc.from, arc.to, axes)) {
        return std::string("the arc after a corner word must lie in the selected plane (no helix)");
    }
    const P2 o = in_plane(arc.center, axes);
    const double arc_radius_mm = arc_start_radius(arc);
    const P2 radial = (p - o) * (1.0 / arc_radius_mm);
    const bool ccw = arc.direction == ArcDirection::counterclockwise;
    const P2 u2 = ccw ? left_of(radial) : left_of(radial) * -1.0;
    const double phi = std::atan2(std::abs(cross(u1, u2)), dot(u1, u2));
    if (phi < angle_eps_rad) return std::string("the arc leaves the line tangentially: there is no corner to round");
    if (pi - phi < angle_eps_rad) return std::string("the arc runs straight back along the line: no corner can be made");
    // The fillet's centre q lies r from the line on the turning side and |R ∓ r| from the arc's
    // centre: R - r when it sits inside the arc (the turn is toward the arc's centre), R + r
    // outside. q = p + n·r + u1·τ with τ < 0 (before the corner) solves |q - o| = R ∓ r.
    const double s = cross(u1, u2) > 0 ? 1.0 : -1.0;
    const P2 n1 = left_of(u1) * s;
    const bool inside = (s > 0) == ccw;
    const double rho = inside ? arc_radius_mm - size_mm : arc_radius_mm + size_mm;
    if (rho <= length_eps_mm) {
        return fmt::format("corner radius ,R {:.4g} mm is not smaller than the arc's radius {:.4f} mm", size_mm,
                           arc_radius_mm);
    }
    const P2 w = p + n1 * size_mm - o;
    const double half_b = dot(w, u1);
    const double disc = half_b * half_b - (dot(w, w) - rho * rho);
    if (disc < 0) return does_not_fit(kind, size_mm, size_mm, first_mm, arc_radius_mm);
    const double root = std::sqrt(disc);
    // Of the two centres on the offset line, the one nearer the corner.
    double tau = -half_b - root;
    if (std::abs(-half_b + root) < std::abs(tau)) tau = -half_b + root;
    const P2 start = p + u1 * tau;
    const P2 q = start + n1 * size_mm;
    const P2 toward = q - o;
    const P2 end = o + toward * (arc_radius_mm / norm(toward));
    const double arc_used = sweep_between(radial, (end - o) * (1.0 / arc_radius_mm), arc.direction);
    if (-tau > first_mm + length_eps_mm || tau > length_eps_mm || (arc.full_turns == 0 && arc_used >= arc_sweep_rad(arc))) {
        return does_not_fit(kind, size_mm, -tau, first_mm, arc_radius_mm * arc_sweep_rad(arc));
    }
    result.first.to = with_plane(first.to, start, axes);
    Arc shortened = arc;
    shortened.from = with_plane(arc.from, end, axes);
    result.next = shortened;
    Arc fillet;
    fillet.from = result.first.to;
    fillet.to = shortened.from;
    fillet.center = with_plane(result.first.to, q, axes);
    fillet.plane = plane;
    fillet.direction = s > 0 ? ArcDirection::counterclockwise : ArcDirection::clockwise;
    fillet.feed = first.feed;
    fillet.path = first.path;
    result.corner = fillet;
    return result;
}

}  // namespace nckit::interp
