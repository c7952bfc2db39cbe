// Corner rounding (,R) and chamfering (,C) between two moves, each a G1 line or a G2/G3 arc,
// worked in the plane's two axes. Notation: the first move arrives at the corner p with unit
// tangent u1, the next leaves it with unit tangent u2; φ is the turning angle between them and
// s = +1 for a left (counter-clockwise) turn, -1 for a right one.
//
// Rounding: the fillet's centre q lies r from both moves on the turning side, so it is where the
// two moves' offset curves cross: a line offset by r is a parallel line, an arc of radius R a
// concentric circle of radius R - r (the turning side is toward its centre) or R + r. Of the
// crossings (line-line: one; line-circle and circle-circle: up to two) the one whose tangent
// points lie on both moves and cut least of them is taken. Chamfer: the points at straight
// distance c from p on each move (on an arc: the chord c, an angle 2·asin(c / 2R) from p).
#include "corner_round.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include <fmt/format.h>

#include "nckit/interp/arc_geometry.hpp"

namespace nckit::interp {

namespace {

constexpr double pi = std::numbers::pi;
constexpr double length_eps_mm = 1e-6;  // a corner piece may use a move up to its whole length
constexpr double angle_eps_rad = 1e-6;  // straight on / straight back

struct P2 {
    double u = 0;
    double v = 0;
};
P2 operator+(P2 a, P2 b) {
    return {a.u + b.u, a.v + b.v};
}
P2 operator-(P2 a, P2 b) {
    return {a.u - b.u, a.v - b.v};
}
P2 operator*(P2 a, double k) {
    return {a.u * k, a.v * k};
}
double dot(P2 a, P2 b) {
    return a.u * b.u + a.v * b.v;
}
double cross(P2 a, P2 b) {
    return a.u * b.v - a.v * b.u;
}
double norm(P2 a) {
    return std::hypot(a.u, a.v);
}
P2 left_of(P2 a) {
    return {-a.v, a.u};
}
P2 rotated(P2 a, double angle_rad) {
    const double c = std::cos(angle_rad);
    const double s = std::sin(angle_rad);
    return {a.u * c - a.v * s, a.u * s + a.v * c};
}

P2 in_plane(const AxisVector& p, const PlaneAxes& axes) {
    return {p[axes.first], p[axes.second]};
}
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
double sweep_between(P2 from, P2 to, bool ccw) {
    double angle = std::atan2(cross(from, to), dot(from, to));
    if (!ccw) angle = -angle;
    return angle < 0 ? angle + 2 * pi : angle;
}

//! One of the two moves in plane coordinates: a segment from a to b, or an arc about o.
struct Piece {
    bool is_arc = false;
    P2 a, b;
    P2 o;
    double radius_mm = 0;  //!< at the corner
    bool ccw = false;
    double length_mm = 0;  //!< segment length, or arc sweep in rad
    P2 u;                  //!< a segment's unit direction
};

P2 tangent_at(const Piece& piece, P2 x) {
    if (!piece.is_arc) return piece.u;
    const P2 radial = (x - piece.o) * (1.0 / norm(x - piece.o));
    return piece.ccw ? left_of(radial) : left_of(radial) * -1.0;
}

//! The move in plane coordinates, or why it cannot take part in a corner.
std::variant<Piece, std::string> to_piece(const CornerMove& move, const PlaneAxes& axes, Plane plane, bool first) {
    Piece piece;
    if (const Line* line = std::get_if<Line>(&move)) {
        if (line->rapid || !stays_in_plane(line->from, line->to, axes)) {
            return std::string("the moves at a corner word must feed (G1, G2, G3) in the selected plane");
        }
        piece.a = in_plane(line->from, axes);
        piece.b = in_plane(line->to, axes);
        piece.length_mm = norm(piece.b - piece.a);
        if (piece.length_mm < length_eps_mm) return std::string("the moves at a corner word must move in the plane");
        piece.u = (piece.b - piece.a) * (1.0 / piece.length_mm);
        return piece;
    }
    const Arc& arc = std::get<Arc>(move);
    if (arc.plane != plane || !stays_in_plane(arc.from, arc.to, axes) || arc.full_turns != 0) {
        return std::string("an arc at a corner word must lie in the selected plane (no helix, no full turns)");
    }
    piece.is_arc = true;
    piece.a = in_plane(arc.from, axes);
    piece.b = in_plane(arc.to, axes);
    piece.o = in_plane(arc.center, axes);
    piece.ccw = arc.direction == ArcDirection::counterclockwise;
    piece.radius_mm = first ? arc_end_radius(arc) : arc_start_radius(arc);
    piece.length_mm = arc_sweep_rad(arc);
    return piece;
}

//! How much of the piece lies between the corner p and x: mm along a segment, rad along an arc;
//! negative when x is not on the piece's corner side. `first`: the piece ends at p.
double cut_from_corner(const Piece& piece, P2 p, P2 x, bool first) {
    if (!piece.is_arc) return first ? dot(p - x, piece.u) : dot(x - p, piece.u);
    const P2 rp = p - piece.o;
    const P2 rx = x - piece.o;
    double angle = first ? sweep_between(rx, rp, piece.ccw) : sweep_between(rp, rx, piece.ccw);
    if (angle > 2 * pi - angle_eps_rad) angle -= 2 * pi;  // a hair on the other side of p
    return angle;
}

bool fits(const Piece& piece, double cut) {
    const double eps = piece.is_arc ? angle_eps_rad : length_eps_mm;
    return cut > -eps && cut <= piece.length_mm + eps;
}

//! Foot of q on the piece's line or circle.
P2 foot_on(const Piece& piece, P2 q) {
    if (!piece.is_arc) return piece.a + piece.u * dot(q - piece.a, piece.u);
    const P2 toward = q - piece.o;
    return piece.o + toward * (piece.radius_mm / norm(toward));
}

//! The fillet from t1 to t2 about q, turning s, with the first move's feed.
Arc fillet_arc(const CornerMove& first, P2 t1, P2 t2, P2 q, double s, Plane plane, const PlaneAxes& axes) {
    Arc fillet;
    std::visit(
        [&](const auto& move) {
            fillet.from = with_plane(move.to, t1, axes);
            fillet.feed = move.feed;
            fillet.path = move.path;
        },
        first);
    fillet.to = with_plane(fillet.from, t2, axes);
    fillet.center = with_plane(fillet.from, q, axes);
    fillet.plane = plane;
    fillet.direction = s > 0 ? ArcDirection::counterclockwise : ArcDirection::clockwise;
    return fillet;
}

//! Points where the piece's offset curve (r to side s) meets the other's: fillet centres.
std::vector<P2> offset_crossings(const Piece& one, const Piece& two, P2 p, double s, double r) {
    std::vector<P2> out;
    struct Curve {
        bool circle;
        P2 point;  // a point of the line, or the circle's centre
        P2 dir;    // the line's direction
        double rho;
    };
    const auto offset = [&](const Piece& piece) {
        if (!piece.is_arc) return Curve{false, p + left_of(piece.u) * (s * r), piece.u, 0};
        return Curve{true, piece.o, {}, piece.ccw ? piece.radius_mm - s * r : piece.radius_mm + s * r};
    };
    const Curve c1 = offset(one);
    const Curve c2 = offset(two);
    if ((c1.circle && c1.rho <= length_eps_mm) || (c2.circle && c2.rho <= length_eps_mm)) return out;
    if (!c1.circle && !c2.circle) {
        const double det = cross(c1.dir, c2.dir);
        if (std::abs(det) < 1e-12) return out;
        out.push_back(c1.point + c1.dir * (cross(c2.point - c1.point, c2.dir) / det));
        return out;
    }
    if (c1.circle != c2.circle) {
        const Curve& line = c1.circle ? c2 : c1;
        const Curve& circle = c1.circle ? c1 : c2;
        const P2 w = line.point - circle.point;
        const double half_b = dot(w, line.dir);
        const double disc = half_b * half_b - (dot(w, w) - circle.rho * circle.rho);
        if (disc < 0) return out;
        for (double sign : {-1.0, 1.0}) out.push_back(line.point + line.dir * (-half_b + sign * std::sqrt(disc)));
        return out;
    }
    const P2 d = c2.point - c1.point;
    const double dist = norm(d);
    if (dist < 1e-12) return out;
    const double along = (dist * dist + c1.rho * c1.rho - c2.rho * c2.rho) / (2 * dist);
    const double h2 = c1.rho * c1.rho - along * along;
    if (h2 < 0) return out;
    const P2 e = d * (1.0 / dist);
    const P2 mid = c1.point + e * along;
    for (double sign : {-1.0, 1.0}) out.push_back(mid + left_of(e) * (sign * std::sqrt(h2)));
    return out;
}

//! The point at straight distance c from p on the piece (before p on the first, after it on
//! the next), or nothing when the piece is too short.
std::optional<P2> chamfer_point(const Piece& piece, P2 p, double c, bool first) {
    if (!piece.is_arc) {
        if (c > piece.length_mm + length_eps_mm) return std::nullopt;
        return first ? p - piece.u * c : p + piece.u * c;
    }
    if (c > 2 * piece.radius_mm) return std::nullopt;
    const double angle = 2 * std::asin(c / (2 * piece.radius_mm));
    if (angle > piece.length_mm + angle_eps_rad) return std::nullopt;
    const double forward = piece.ccw ? angle : -angle;
    return piece.o + rotated(p - piece.o, first ? -forward : forward);
}

//! Why the corner piece does not fit; between two lines, how much of each it would need
//! (r·tan(φ/2) for rounding, c for a chamfer).
std::string does_not_fit(CornerKind kind, double size_mm, const Piece& one, const Piece& two, double phi) {
    const char* what = kind == CornerKind::round ? "corner radius ,R" : "chamfer ,C";
    if (one.is_arc || two.is_arc) {
        return fmt::format("{} {:.4g} mm does not fit on the moves before and after the corner", what, size_mm);
    }
    const double needed_mm = kind == CornerKind::round ? size_mm * std::tan(phi / 2) : size_mm;
    return fmt::format(
        "{} {:.4g} mm does not fit: it needs {:.4f} mm of each move, the moves are {:.4f} and "
        "{:.4f} mm long",
        what, size_mm, needed_mm, one.length_mm, two.length_mm);
}

CornerMove shortened(CornerMove move, P2 x, const PlaneAxes& axes, bool first) {
    std::visit(
        [&](auto& m) {
            if (first) {
                m.to = with_plane(m.to, x, axes);
            } else {
                m.from = with_plane(m.from, x, axes);
            }
        },
        move);
    return move;
}

}  // namespace

std::variant<CornerResult, std::string> make_corner(const CornerMove& first, const CornerMove& next, CornerKind kind,
                                                    double size_mm, Plane plane) {
    const PlaneAxes axes = plane_axes(plane);
    auto first_piece = to_piece(first, axes, plane, true);
    if (const std::string* why = std::get_if<std::string>(&first_piece)) return *why;
    auto next_piece = to_piece(next, axes, plane, false);
    if (const std::string* why = std::get_if<std::string>(&next_piece)) return *why;
    const Piece& one = std::get<Piece>(first_piece);
    const Piece& two = std::get<Piece>(next_piece);
    const P2 p = one.b;
    const P2 u1 = tangent_at(one, p);
    const P2 u2 = tangent_at(two, p);
    const double phi = std::atan2(std::abs(cross(u1, u2)), dot(u1, u2));
    if (phi < angle_eps_rad) return std::string("the moves run straight on: there is no corner to round");
    if (pi - phi < angle_eps_rad) return std::string("the next move runs straight back: no corner can be made");

    const auto result = [&](P2 t1, P2 t2, CornerMove piece) {
        return CornerResult{shortened(first, t1, axes, true), shortened(next, t2, axes, false), std::move(piece)};
    };
    if (kind == CornerKind::chamfer) {
        const auto t1 = chamfer_point(one, p, size_mm, true);
        const auto t2 = chamfer_point(two, p, size_mm, false);
        if (!t1 || !t2) return does_not_fit(kind, size_mm, one, two, phi);
        Line cut;
        std::visit(
            [&](const auto& move) {
                cut.feed = move.feed;
                cut.path = move.path;
                cut.from = with_plane(move.to, *t1, axes);
            },
            first);
        cut.to = with_plane(cut.from, *t2, axes);
        return result(*t1, *t2, cut);
    }
    const double s = cross(u1, u2) > 0 ? 1.0 : -1.0;
    for (const Piece* piece : {&one, &two}) {
        if (piece->is_arc && (piece->ccw == (s > 0)) && piece->radius_mm - size_mm <= length_eps_mm) {
            return fmt::format("corner radius ,R {:.4g} mm is not smaller than the arc's radius {:.4f} mm", size_mm,
                               piece->radius_mm);
        }
    }
    bool found = false;
    double best_cut = 0;
    P2 best_q, best_t1, best_t2;
    for (const P2 q : offset_crossings(one, two, p, s, size_mm)) {
        const P2 t1 = foot_on(one, q);
        const P2 t2 = foot_on(two, q);
        const double cut1 = cut_from_corner(one, p, t1, true);
        const double cut2 = cut_from_corner(two, p, t2, false);
        if (!fits(one, cut1) || !fits(two, cut2)) continue;
        const double cut = norm(t1 - p) + norm(t2 - p);
        if (found && cut >= best_cut) continue;
        found = true;
        best_cut = cut;
        best_q = q;
        best_t1 = t1;
        best_t2 = t2;
    }
    if (!found) return does_not_fit(kind, size_mm, one, two, phi);
    return result(best_t1, best_t2, fillet_arc(first, best_t1, best_t2, best_q, s, plane, axes));
}

}  // namespace nckit::interp
