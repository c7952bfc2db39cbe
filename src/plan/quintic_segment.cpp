// Quintic transitions: construction by Hermite interpolation, and bounds of their derivatives.
#include <algorithm>
#include <array>
#include <cmath>

#include "nckit/plan/path_segment.hpp"
#include "quintic_bounds.hpp"

namespace nckit {

void write_quintic(PathSegment& g, const PathPoint& start, const PathPoint& end, double length,
                   const AxisVector& other_rate) {
    g.shape = SegmentShape::quintic;
    g.length = length;
    g.origin = start.position;
    for (std::size_t i = 3; i < axis_count; ++i) g.rate[i] = other_rate[i];
    g.u = {};
    g.v = {};
    g.radius_mm = 0;
    g.angle_rate = 0;
    // In u = s / L: p(u) = Σ a_k u^k with p, p', p'' given at u = 0 and 1 (derivatives in u are
    // L and L² times those in s). The coefficients in s are a_k / L^k.
    const double l = length;
    for (std::size_t i = 0; i < 3; ++i) {
        const double delta = end.position[i] - start.position[i];
        const double v0 = start.d1[i] * l;
        const double v1 = end.d1[i] * l;
        const double k0 = start.d2[i] * l * l;
        const double k1 = end.d2[i] * l * l;
        const double a3 = 10 * delta - 6 * v0 - 4 * v1 - (3 * k0 - k1) / 2;
        const double a4 = -15 * delta + 8 * v0 + 7 * v1 + (3 * k0 - 2 * k1) / 2;
        const double a5 = 6 * delta - 3 * v0 - 3 * v1 - (k0 - k1) / 2;
        g.rate[i] = start.d1[i];
        g.poly[0][i] = start.d2[i] / 2;
        g.poly[1][i] = a3 / (l * l * l);
        g.poly[2][i] = a4 / (l * l * l * l);
        g.poly[3][i] = a5 / (l * l * l * l * l);
    }
}

PathSegment make_quintic(const PathPoint& start, const PathPoint& end, double length, const AxisVector& other_rate) {
    PathSegment g;
    write_quintic(g, start, end, length, other_rate);
    return g;
}

namespace {

//! max |c0 + c1 s + c2 s²| over [0, l].
double max_abs_quadratic(double c0, double c1, double c2, double l) {
    auto f = [&](double s) { return std::abs(c0 + s * (c1 + s * c2)); };
    double m = std::max(f(0), f(l));
    if (c2 != 0) {
        const double vertex = -c1 / (2 * c2);
        if (vertex > 0 && vertex < l) m = std::max(m, f(vertex));
    }
    return m;
}

//! The real roots of qa s² + qb s + qc = 0 (up to two; none when there are none or infinitely
//! many). Each root comes from the formula that does not subtract nearly equal numbers: with
//! qa tiny (a quintic whose s⁵ term is rounding noise) the textbook (−qb + √disc) / (2 qa)
//! cancels to noise divided by noise and loses the root near −qc / qb, where q'' peaks.
struct QuadraticRoots {
    std::array<double, 2> at{};
    int count = 0;
};
QuadraticRoots quadratic_roots(double qa, double qb, double qc) {
    QuadraticRoots r;
    if (qa == 0) {
        if (qb != 0) r.at[r.count++] = -qc / qb;
        return r;
    }
    const double disc = qb * qb - 4 * qa * qc;
    if (disc < 0) return r;
    const double q = -0.5 * (qb + std::copysign(std::sqrt(disc), qb));
    if (q == 0) {  // qb = 0 and qc = 0: a double root at 0
        r.at[r.count++] = 0;
        return r;
    }
    r.at[r.count++] = q / qa;
    r.at[r.count++] = qc / q;
    return r;
}

//! max |c0 + c1 s + c2 s² + c3 s³| over [0, l]: ends and the roots of the derivative.
double max_abs_cubic(double c0, double c1, double c2, double c3, double l) {
    auto f = [&](double s) { return std::abs(c0 + s * (c1 + s * (c2 + s * c3))); };
    double m = std::max(f(0), f(l));
    // 3 c3 s² + 2 c2 s + c1 = 0
    const QuadraticRoots roots = quadratic_roots(3 * c3, 2 * c2, c1);
    for (int k = 0; k < roots.count; ++k) {
        const double s = roots.at[static_cast<std::size_t>(k)];
        if (s > 0 && s < l) m = std::max(m, f(s));
    }
    return m;
}

constexpr std::size_t bound_samples = 24;

//! The largest of the samples (destroys them): the halves compared element by element.
double largest(std::array<double, bound_samples>& x) {
    static_assert(bound_samples == 24);
    for (std::size_t k = 0; k < 12; ++k) x[k] = std::max(x[k], x[k + 12]);
    for (std::size_t k = 0; k < 6; ++k) x[k] = std::max(x[k], x[k + 6]);
    // In pairs from here (not halves of 6): reading back across two of the paired stores
    // stalls the load.
    for (std::size_t k = 0; k < 2; ++k) x[k] = std::max(std::max(x[k], x[k + 2]), x[k + 4]);
    return std::max(x[0], x[1]);
}
constexpr double bound_pad = 1e-12;
//! k + 1 at k, as doubles: a table, since converting an unsigned index to double takes several
//! instructions per sample.
constexpr std::array<double, bound_samples> sample_index = {1,  2,  3,  4,  5,  6,  7,  8,  9,  10, 11, 12,
                                                            13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24};

//! The control points (Bernstein coefficients on u = s/L in [0, 1]) of q' = c1 + 2c2 s + 3c3 s²
//! + 4c4 s³ + 5c5 s⁴ on one axis: q' lies between the smallest and the largest of them.
std::array<double, 5> slope_control_points(double c1, double c2, double c3, double c4, double c5, double l) {
    // Power coefficients in u, then b_i = sum_k C(i,k)/C(4,k) e_k.
    const double e0 = c1;
    const double e1 = 2 * c2 * l;
    const double e2 = 3 * c3 * l * l;
    const double e3 = 4 * c4 * l * l * l;
    const double e4 = 5 * c5 * l * l * l * l;
    return {e0, e0 + e1 / 4, e0 + e1 / 2 + e2 / 6, e0 + 3 * e1 / 4 + e2 / 2 + e3 / 4, e0 + e1 + e2 + e3 + e4};
}

//! A control-point bound is used as it is when it exceeds the larger end value by less than
//! this, relative to that value or to 1 (|q'| is about 1, so an axis's slope is at most about 1):
//! on a gentle transition it is then practically exact, and sampling is saved. An axis with a
//! small slope never limits the speed or the acceleration much, so 1e-3 absolute is enough there.
constexpr double tight_hull = 1e-3;
bool tight(double hull, double ends) {
    return hull <= ends + tight_hull * std::max(ends, 1.0);
}

}  // namespace

DerivativeBounds quintic_bounds(const PathSegment& g) {
    DerivativeBounds b;
    const double l = g.length;
    for (std::size_t i = 3; i < axis_count; ++i) b.d1[i] = std::abs(g.rate[i]);
    double d2_norm2 = 0;
    std::array<std::array<double, 5>, 3> control;  // every element set below
    std::array<double, 3> hull{};
    std::array<bool, 3> sample_axis{};
    std::array<bool, 3> moves{};
    for (std::size_t i = 0; i < 3; ++i) {
        const double c1 = g.rate[i];
        const double c2 = g.poly[0][i];
        const double c3 = g.poly[1][i];
        const double c4 = g.poly[2][i];
        const double c5 = g.poly[3][i];
        if (c1 == 0 && c2 == 0 && c3 == 0 && c4 == 0 && c5 == 0) {
            control[i] = {};  // an axis that stands: every bound 0, as computed they come out 0
            continue;
        }
        moves[i] = true;
        b.d3[i] = max_abs_quadratic(6 * c3, 24 * c4, 60 * c5, l) * (1 + bound_pad);
        b.d2[i] = max_abs_cubic(2 * c2, 6 * c3, 12 * c4, 20 * c5, l) * (1 + bound_pad);
        d2_norm2 += b.d2[i] * b.d2[i];
        control[i] = slope_control_points(c1, c2, c3, c4, c5, l);
        for (double c : control[i]) hull[i] = std::max(hull[i], std::abs(c));
        const double ends = std::max(std::abs(control[i][0]), std::abs(control[i][4]));
        sample_axis[i] = !tight(hull[i], ends);
        if (!sample_axis[i]) b.d1[i] = hull[i] * (1 + bound_pad);
    }
    // |p'| is convex in p', so it is at most the largest norm of the control points. Squares are
    // compared and one root taken: the root is monotonic, so the maximum is the same number.
    auto norm2_at = [&](std::size_t k) {
        return control[0][k] * control[0][k] + control[1][k] * control[1][k] + control[2][k] * control[2][k];
    };
    double speed_hull2 = 0;
    for (std::size_t k = 0; k < 5; ++k) speed_hull2 = std::max(speed_hull2, norm2_at(k));
    const double speed_hull = std::sqrt(speed_hull2);
    const bool sample_speed = !tight(speed_hull, std::sqrt(std::max(norm2_at(0), norm2_at(4))));
    if (!sample_speed) b.speed_factor = speed_hull * (1 + bound_pad);
    if (!(sample_speed || sample_axis[0] || sample_axis[1] || sample_axis[2])) return b;
    // q' sampled on all three axes at once (independent sums, one root at the end); between
    // samples q' moves by at most d2 · h/2 from the nearer one, |p'| by at most |d2| · h/2.
    const double h = l / static_cast<double>(bound_samples);
    // The samples after the start (s = h·k, k = 1..24) in flat arrays the compiler vectorises; at
    // s = 0, q' is c1. An axis that does not move adds nothing. The largest of a set does not
    // depend on the order it is searched in: by halving.
    std::array<double, bound_samples> at;  // every element set below
    for (std::size_t k = 0; k < bound_samples; ++k) at[k] = h * sample_index[k];
    // |p'|² at the samples: the first axis that moves sets them (0 + x is x, and a memset of
    // them cost as much as the sums), the others add to them.
    std::array<double, bound_samples> speed2;  // every element set below
    bool speed2_set = false;
    double speed2_start = 0;
    std::array<double, 3> most{};
    for (std::size_t i = 0; i < 3; ++i) {
        const double c1 = g.rate[i];
        if (!moves[i]) continue;
        const double c2 = 2 * g.poly[0][i];
        const double c3 = 3 * g.poly[1][i];
        const double c4 = 4 * g.poly[2][i];
        const double c5 = g.poly[3][i];
        std::array<double, bound_samples> slope;  // every element set below
        for (std::size_t k = 0; k < bound_samples; ++k) {
            const double s = at[k];
            slope[k] = c1 + s * (c2 + s * (c3 + s * (c4 + s * 5 * c5)));
        }
        if (speed2_set) {
            for (std::size_t k = 0; k < bound_samples; ++k) speed2[k] += slope[k] * slope[k];
        } else {
            for (std::size_t k = 0; k < bound_samples; ++k) speed2[k] = slope[k] * slope[k];
            speed2_set = true;
        }
        speed2_start += c1 * c1;
        for (double& d : slope) d = std::abs(d);
        most[i] = std::max(std::abs(c1), largest(slope));
    }
    if (!speed2_set) speed2.fill(0);  // no axis moves (then nothing is sampled: not reached)
    const double speed2_most = std::max(speed2_start, largest(speed2));
    for (std::size_t i = 0; i < 3; ++i) {
        if (sample_axis[i]) b.d1[i] = std::min(hull[i], most[i] + b.d2[i] * h / 2) * (1 + bound_pad);
    }
    if (sample_speed) {
        b.speed_factor = std::min(speed_hull, std::sqrt(speed2_most) + std::sqrt(d2_norm2) * h / 2) * (1 + bound_pad);
    }
    return b;
}

}  // namespace nckit
