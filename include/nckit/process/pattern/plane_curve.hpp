#pragma once
// Plane curves of the pattern process: straight segments, circular arcs and piecewise cubic
// paths (the splines of outlines, borders and motifs), all on one parameter interface so the
// clipper and the program writer need not know which kind they hold. Units: mm, deg.
#include <algorithm>
#include <array>
#include <cmath>
#include <variant>
#include <vector>

#include "nckit/core/vec2.hpp"

namespace nckit::pattern {

//! p(u) = c[0] + c[1]·u + c[2]·u² + c[3]·u³ for u in [0, 1].
struct CubicPiece {
    std::array<Vec2, 4> c{};
    [[nodiscard]] Vec2 point(double u) const { return c[0] + u * (c[1] + u * (c[2] + u * c[3])); }
    [[nodiscard]] Vec2 tangent(double u) const { return c[1] + u * (2.0 * c[2] + 3.0 * u * c[3]); }
    [[nodiscard]] Vec2 second(double u) const { return 2.0 * c[2] + 6.0 * u * c[3]; }
};

struct Segment {
    Vec2 from;
    Vec2 to;
};

//! Counter-clockwise for sweep > 0. Points are centre + radius·(cos a, sin a).
struct ArcCurve {
    Vec2 center;
    double radius_mm = 0;
    double start_deg = 0;
    double sweep_deg = 0;
};

//! Pieces joined end to start; the parameter s runs 0..pieces.size() (piece i on [i, i+1]).
struct CubicPath {
    std::vector<CubicPiece> pieces;
};

using PlaneCurve = std::variant<Segment, ArcCurve, CubicPath>;

//! Parameter range of a curve: [0, 1] for a segment, [0, sweep] (deg) for an arc, [0, pieces].
[[nodiscard]] double parameter_end(const PlaneCurve& curve);
[[nodiscard]] Vec2 point_at(const PlaneCurve& curve, double s);
//! dP/ds.
[[nodiscard]] Vec2 tangent_at(const PlaneCurve& curve, double s);
//! The part of `curve` between parameters s0 < s1, of the same kind.
[[nodiscard]] PlaneCurve sub_curve(const PlaneCurve& curve, double s0, double s1);
//! The same points traversed the other way.
[[nodiscard]] PlaneCurve reversed(const PlaneCurve& curve);
//! Arc length (cubic paths by Gauss–Legendre quadrature per piece, 1e-9 relative on smooth pieces).
[[nodiscard]] double curve_length(const PlaneCurve& curve);
//! Points along the curve no further than `chord_mm` apart and off the curve by at most
//! `deviation_mm` between them (both ends exact).
[[nodiscard]] std::vector<Vec2> polyline(const PlaneCurve& curve, double deviation_mm, std::size_t max_points = 100000);

struct Box {
    Vec2 low{1e300, 1e300};
    Vec2 high{-1e300, -1e300};
    void add(Vec2 p) {
        low = {std::min(low.x, p.x), std::min(low.y, p.y)};
        high = {std::max(high.x, p.x), std::max(high.y, p.y)};
    }
    [[nodiscard]] bool overlaps(const Box& o, double margin) const {
        return low.x <= o.high.x + margin && o.low.x <= high.x + margin && low.y <= o.high.y + margin &&
               o.low.y <= high.y + margin;
    }
    [[nodiscard]] Vec2 size() const { return high - low; }
    [[nodiscard]] Vec2 centre() const { return 0.5 * (low + high); }
};
//! A box that holds the whole curve (cubic pieces: the hull of their Bézier control points).
[[nodiscard]] Box bounding_box(const PlaneCurve& curve);
[[nodiscard]] Box bounding_box(const CubicPiece& piece);

//! An affine map x' = m·x + t (m row-major 2×2): grading, mirroring, placing motifs.
struct Affine {
    std::array<double, 4> m{1, 0, 0, 1};
    Vec2 t;
    [[nodiscard]] Vec2 apply(Vec2 p) const { return {m[0] * p.x + m[1] * p.y + t.x, m[2] * p.x + m[3] * p.y + t.y}; }
    [[nodiscard]] Vec2 linear(Vec2 v) const { return {m[0] * v.x + m[1] * v.y, m[2] * v.x + m[3] * v.y}; }
    [[nodiscard]] double determinant() const { return m[0] * m[3] - m[1] * m[2]; }
};
//! The image of `curve` under `map`. Arcs need a similarity (equal scale, any rotation or
//! reflection); a reflection turns their sweep round.
[[nodiscard]] PlaneCurve transformed(const PlaneCurve& curve, const Affine& map);
[[nodiscard]] CubicPiece transformed(const CubicPiece& piece, const Affine& map);

}  // namespace nckit::pattern
