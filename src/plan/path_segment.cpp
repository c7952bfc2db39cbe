#include "nckit/plan/path_segment.hpp"

#include "quintic_bounds.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace nckit {

namespace {

constexpr double two_pi = 2.0 * std::numbers::pi;
// Arc end points closer than this in the plane make a full circle (mm), as in the interpreter.
constexpr double same_point_mm = 1e-9;

double norm_of(const AxisVector& d, std::size_t first, std::size_t last) {
    double sum = 0;
    for (std::size_t i = first; i < last; ++i) sum += d[i] * d[i];
    return std::sqrt(sum);
}

struct PlaneIndex {
    std::size_t first, second, normal;
};

PlaneIndex plane_index(Plane plane) {
    switch (plane) {
        case Plane::xy:
            return {0, 1, 2};
        case Plane::zx:
            return {2, 0, 1};
        case Plane::yz:
            return {1, 2, 0};
    }
    return {0, 1, 2};
}

}  // namespace

double measured_length(const AxisVector& d) {
    const double xyz = norm_of(d, 0, 3);
    if (xyz > 0) return xyz;
    const double uvw = norm_of(d, 6, 9);
    if (uvw > 0) return uvw;
    return norm_of(d, 3, 6);
}

AxisVector position_at(const PathSegment& g, double s) {
    AxisVector p;
    for (std::size_t i = 0; i < axis_count; ++i) p[i] = g.origin[i] + g.rate[i] * s;
    if (g.shape == SegmentShape::quintic) {
        for (std::size_t i = 0; i < 3; ++i) {
            p[i] += s * s * (g.poly[0][i] + s * (g.poly[1][i] + s * (g.poly[2][i] + s * g.poly[3][i])));
        }
        return p;
    }
    if (g.radius_mm > 0) {
        const double theta = g.angle_rate * s;
        const double c = g.radius_mm * std::cos(theta);
        const double sn = g.radius_mm * std::sin(theta);
        for (std::size_t i = 0; i < 3; ++i) p[i] += c * g.u[i] + sn * g.v[i];
    }
    return p;
}

PathPoint point_at(const PathSegment& g, double s) {
    PathPoint out;
    for (std::size_t i = 0; i < axis_count; ++i) {
        out.position[i] = g.origin[i] + g.rate[i] * s;
        out.d1[i] = g.rate[i];
    }
    if (g.shape == SegmentShape::quintic) {
        for (std::size_t i = 0; i < 3; ++i) {
            const double c2 = g.poly[0][i];
            const double c3 = g.poly[1][i];
            const double c4 = g.poly[2][i];
            const double c5 = g.poly[3][i];
            out.position[i] += s * s * (c2 + s * (c3 + s * (c4 + s * c5)));
            out.d1[i] += s * (2 * c2 + s * (3 * c3 + s * (4 * c4 + s * 5 * c5)));
            out.d2[i] = 2 * c2 + s * (6 * c3 + s * (12 * c4 + s * 20 * c5));
            out.d3[i] = 6 * c3 + s * (24 * c4 + s * 60 * c5);
        }
        return out;
    }
    if (g.radius_mm > 0) {
        const double k = g.angle_rate;
        const double theta = k * s;
        const double c = std::cos(theta);
        const double sn = std::sin(theta);
        const double r1 = g.radius_mm * k;
        const double r2 = r1 * k;
        const double r3 = r2 * k;
        for (std::size_t i = 0; i < 3; ++i) {
            const double radial = c * g.u[i] + sn * g.v[i];       // (cos, sin)
            const double tangential = -sn * g.u[i] + c * g.v[i];  // its θ-derivative
            out.position[i] += g.radius_mm * radial;
            out.d1[i] += r1 * tangential;
            out.d2[i] = -r2 * radial;
            out.d3[i] = -r3 * tangential;
        }
    }
    return out;
}

namespace {

//! The range [lo, hi] of cos ψ over ψ in [psi0, psi1] (psi0 <= psi1): ±1 where the interval
//! holds an extremum (a multiple of 2π, or π plus one), else the values at its ends.
struct CosRange {
    double lo = -1;
    double hi = 1;
};
CosRange cos_range(double psi0, double psi1) {
    if (!(psi1 - psi0 < two_pi)) return {};
    const double c0 = std::cos(psi0);
    const double c1 = std::cos(psi1);
    CosRange r{std::min(c0, c1), std::max(c0, c1)};
    if (std::floor(psi1 / two_pi) >= std::ceil(psi0 / two_pi)) r.hi = 1;
    if (std::floor((psi1 - std::numbers::pi) / two_pi) >= std::ceil((psi0 - std::numbers::pi) / two_pi)) r.lo = -1;
    return r;
}

// An arc's sweep is widened by this (rad) at both ends before its extrema are looked for, and
// the bounds raised by this relative amount: a deciding comparison or an end value that
// rounding gets wrong then still errs on the safe (larger) side.
constexpr double angle_pad_rad = 1e-9;
constexpr double bound_pad = 1e-12;

//! Over θ in [0, sweep] (or [sweep, 0]): the range of A cos θ + B sin θ = R cos(θ − α).
struct SinusoidRange {
    double lo = 0;
    double hi = 0;
};
//! The same for 0 < sweep < π, without trigonometry per sinusoid: given cos and sin of the
//! sweep, the ends are A and A·cos + B·sin, and the crest (the direction (A, B)) lies in the
//! swept angle when both cross products with its ends are >= 0 (trough: <= 0), tested with a
//! tolerance that counts near misses as inside (the safe side).
SinusoidRange sinusoid_range_short(double a, double b, double cos_sweep, double sin_sweep) {
    const double amplitude = std::sqrt(a * a + b * b);
    if (!(amplitude > 0)) return {};
    const double end = a * cos_sweep + b * sin_sweep;
    const double to_end = a * sin_sweep - b * cos_sweep;  // cross((A, B), (cos, sin))
    const double slack = angle_pad_rad * amplitude;
    const double pad = bound_pad * amplitude;
    const bool crest = b >= -slack && to_end >= -slack;
    const bool trough = b <= slack && to_end <= slack;
    return {(trough ? -amplitude : std::min(a, end)) - pad, (crest ? amplitude : std::max(a, end)) + pad};
}

//! max |c + A cos θ + B sin θ| over the sweep.
double max_abs_short(double c, double a, double b, double cos_sweep, double sin_sweep) {
    const SinusoidRange r = sinusoid_range_short(a, b, cos_sweep, sin_sweep);
    return std::max(std::abs(c + r.lo), std::abs(c + r.hi));
}

SinusoidRange sinusoid_range(double a, double b, double sweep) {
    const double amplitude = std::hypot(a, b);
    if (!(amplitude > 0)) return {};
    const double alpha = std::atan2(b, a);
    const double from = std::min(0.0, sweep) - alpha - angle_pad_rad;
    const double to = std::max(0.0, sweep) - alpha + angle_pad_rad;
    const CosRange c = cos_range(from, to);
    const double pad = bound_pad * amplitude;
    return {amplitude * c.lo - pad, amplitude * c.hi + pad};
}

//! max |c + A cos θ + B sin θ| over the sweep.
double max_abs(double c, double a, double b, double sweep) {
    const SinusoidRange r = sinusoid_range(a, b, sweep);
    return std::max(std::abs(c + r.lo), std::abs(c + r.hi));
}

}  // namespace

DerivativeBounds derivative_bounds(const PathSegment& g) {
    if (g.shape == SegmentShape::quintic) return quintic_bounds(g);  // before b: it is zeroed
    DerivativeBounds b;
    for (std::size_t i = 0; i < axis_count; ++i) b.d1[i] = std::abs(g.rate[i]);
    if (!(g.radius_mm > 0)) return b;  // a line: |p'| = 1 on the measured axes by construction
    // Over the arc's own sweep, not the whole circle: with θ = k·s in [0, k·length],
    //   q'_i   = rate_i + r k (v_i cos θ − u_i sin θ),
    //   q''_i  = −r k² (u_i cos θ + v_i sin θ),
    //   q'''_i = −r k³ (v_i cos θ − u_i sin θ),
    // each a sinusoid in θ whose extremes over an interval lie at its ends or at a crest inside
    // (sinusoid_range). A blend of a few degrees thus bounds an axis by its real slope along the
    // arc, not by the circle's full radius (which would cost up to half its acceleration).
    const double k = g.angle_rate;
    const double sweep = k * g.length;
    const double r1 = g.radius_mm * k;
    const double r2 = r1 * k;
    const double r3 = r2 * k;
    // Arcs under half a turn (every blend) take the fast path.
    const bool short_arc = sweep > 0 && sweep < 3.0;
    const double cos_sweep = short_arc ? std::cos(sweep) : 0.0;
    const double sin_sweep = short_arc ? std::sin(sweep) : 0.0;
    for (std::size_t i = 0; i < 3 && short_arc; ++i) {
        b.d1[i] = max_abs_short(g.rate[i], r1 * g.v[i], -r1 * g.u[i], cos_sweep, sin_sweep);
        b.d2[i] = max_abs_short(0.0, r2 * g.u[i], r2 * g.v[i], cos_sweep, sin_sweep);
        b.d3[i] = max_abs_short(0.0, r3 * g.v[i], -r3 * g.u[i], cos_sweep, sin_sweep);
    }
    for (std::size_t i = 0; i < 3 && !short_arc; ++i) {
        b.d1[i] = max_abs(g.rate[i], r1 * g.v[i], -r1 * g.u[i], sweep);
        b.d2[i] = max_abs(0.0, r2 * g.u[i], r2 * g.v[i], sweep);
        b.d3[i] = max_abs(0.0, r3 * g.v[i], -r3 * g.u[i], sweep);
    }
    // |p'_xyz|² = |rate|² + r1² + 2 r1 (rate·v cos θ − rate·u sin θ) (u ⟂ v, both unit).
    double rate2 = 0;
    double ru = 0;
    double rv = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        rate2 += g.rate[i] * g.rate[i];
        ru += g.rate[i] * g.u[i];
        rv += g.rate[i] * g.v[i];
    }
    const SinusoidRange cross = short_arc ? sinusoid_range_short(2.0 * r1 * rv, -2.0 * r1 * ru, cos_sweep, sin_sweep)
                                          : sinusoid_range(2.0 * r1 * rv, -2.0 * r1 * ru, sweep);
    b.speed_factor = std::sqrt(std::max(0.0, rate2 + r1 * r1 + cross.hi));
    return b;
}

PathSegment trim_start(const PathSegment& g, double trim) {
    PathSegment out = g;
    out.length = g.length - trim;
    if (g.shape == SegmentShape::quintic) {
        // The same polynomial expanded about s = trim (Taylor shift): the coefficient of s^k is
        // the k-th derivative there over k!.
        out.origin = position_at(g, trim);
        const double t = trim;
        for (std::size_t i = 0; i < 3; ++i) {
            const double c2 = g.poly[0][i];
            const double c3 = g.poly[1][i];
            const double c4 = g.poly[2][i];
            const double c5 = g.poly[3][i];
            out.rate[i] = g.rate[i] + t * (2 * c2 + t * (3 * c3 + t * (4 * c4 + t * 5 * c5)));
            out.poly[0][i] = c2 + t * (3 * c3 + t * (6 * c4 + t * 10 * c5));
            out.poly[1][i] = c3 + t * (4 * c4 + t * 10 * c5);
            out.poly[2][i] = c4 + t * 5 * c5;
        }
    } else if (g.radius_mm > 0) {
        // The centre's linear part moves on; the start direction turns by the angle swept.
        const double theta = g.angle_rate * trim;
        const double c = std::cos(theta);
        const double sn = std::sin(theta);
        for (std::size_t i = 0; i < axis_count; ++i) out.origin[i] = g.origin[i] + g.rate[i] * trim;
        for (std::size_t i = 0; i < 3; ++i) {
            out.u[i] = c * g.u[i] + sn * g.v[i];
            out.v[i] = -sn * g.u[i] + c * g.v[i];
        }
    } else {
        out.origin = position_at(g, trim);
    }
    return out;
}

PathSegment make_line(const AxisVector& from, const AxisVector& to) {
    PathSegment g;
    g.shape = SegmentShape::line;
    g.origin = from;
    const AxisVector d = to - from;
    g.length = measured_length(d);
    if (g.length > 0) {
        // An axis that does not move keeps its (signed) zero: the same number as 0 / length,
        // without a division for each of the standing axes of every line.
        for (std::size_t i = 0; i < axis_count; ++i) g.rate[i] = d[i] == 0 ? d[i] : d[i] / g.length;
    }
    return g;
}

PathSegment make_arc(const Arc& arc) {
    const PlaneIndex p = plane_index(arc.plane);
    const double c1 = arc.center[p.first];
    const double c2 = arc.center[p.second];
    const double f1 = arc.from[p.first] - c1;
    const double f2 = arc.from[p.second] - c2;
    const double r = std::hypot(f1, f2);
    if (!(r > 0)) return make_line(arc.from, arc.to);

    double sweep = two_pi * arc.full_turns;
    const double t1 = arc.to[p.first] - c1;
    const double t2 = arc.to[p.second] - c2;
    const bool ccw = arc.direction == ArcDirection::counterclockwise;
    if (std::hypot(arc.to[p.first] - arc.from[p.first], arc.to[p.second] - arc.from[p.second]) < same_point_mm) {
        sweep += two_pi;
    } else {
        double a = ccw ? std::atan2(t2, t1) - std::atan2(f2, f1) : std::atan2(f2, f1) - std::atan2(t2, t1);
        while (a <= 0) a += two_pi;
        while (a > two_pi) a -= two_pi;
        sweep += a;
    }

    PathSegment g;
    g.shape = SegmentShape::arc;
    g.radius_mm = r;
    g.origin = arc.from;
    g.origin[p.first] = c1;
    g.origin[p.second] = c2;
    g.u[p.first] = f1 / r;
    g.u[p.second] = f2 / r;
    // v is u turned a quarter in the direction of travel.
    g.v[p.first] = ccw ? -g.u[p.second] : g.u[p.second];
    g.v[p.second] = ccw ? g.u[p.first] : -g.u[p.first];
    // Everything the circle does not cover moves linearly: the helix axis, the other axes, and
    // the (small) radius mismatch of the end point.
    const double ce = std::cos(sweep);
    const double se = std::sin(sweep);
    AxisVector rest = arc.to - arc.from;
    for (std::size_t i = 0; i < 3; ++i) rest[i] = arc.to[i] - g.origin[i] - r * (ce * g.u[i] + se * g.v[i]);
    const double circle = r * sweep;
    g.length = std::hypot(circle, norm_of(rest, 0, 3));
    for (std::size_t i = 0; i < axis_count; ++i) g.rate[i] = rest[i] / g.length;
    g.angle_rate = sweep / g.length;
    return g;
}

PathSegment make_circular(const AxisVector& start, const std::array<double, 3>& centre,
                          const std::array<double, 3>& tangent, double sweep_rad, const AxisVector& other_rate) {
    PathSegment g;
    g.shape = SegmentShape::arc;
    g.origin = start;
    double r2 = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        g.origin[i] = centre[i];
        g.u[i] = start[i] - centre[i];
        r2 += g.u[i] * g.u[i];
    }
    g.radius_mm = std::sqrt(r2);
    double along = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        g.u[i] /= g.radius_mm;
        along += tangent[i] * g.u[i];
    }
    // Remove the rounding-level radial part of the tangent so u, v are orthonormal.
    double v2 = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        g.v[i] = tangent[i] - along * g.u[i];
        v2 += g.v[i] * g.v[i];
    }
    const double vn = std::sqrt(v2);
    for (std::size_t i = 0; i < 3; ++i) g.v[i] /= vn;
    g.length = g.radius_mm * sweep_rad;
    g.angle_rate = 1.0 / g.radius_mm;
    for (std::size_t i = 3; i < axis_count; ++i) g.rate[i] = other_rate[i];
    return g;
}

}  // namespace nckit
