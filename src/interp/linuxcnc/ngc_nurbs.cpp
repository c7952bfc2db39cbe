// LinuxCNC's spline approximation (ngc_nurbs.hpp): the curve's points from its B-spline basis,
// its tangents by a central difference, and the biarc between two points with their tangents.
#include "ngc_nurbs.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace nckit::interp::ngc {
namespace {

struct PlanePoint {
    double first = 0;
    double second = 0;
};

//! LinuxCNC's clamped uniform knots for n + 1 points of order k: k zeros, 1 .. n - k + 1, then
//! n - k + 2 repeated to the end (n + k + 1 knots).
std::vector<double> knots_for(unsigned n, unsigned k) {
    std::vector<double> knots;
    for (unsigned i = 0; i <= n + k; ++i) {
        if (i < k) {
            knots.push_back(0);
        } else if (i <= n) {
            knots.push_back(static_cast<double>(i - k + 1));
        } else {
            knots.push_back(static_cast<double>(n - k + 2));
        }
    }
    return knots;
}

//! The basis functions of order k at u that can be non-zero: values[m] belongs to control point
//! first + m; every other one is exactly zero.
struct BasisWindow {
    std::size_t first = 0;
    std::vector<double> values;
};

//! The order-k basis functions at u, level by level (the recursion's values, without its
//! repeated work). Level 1 counts u in every closed span [t_i, t_i+1], as LinuxCNC does, and a
//! span of no length drops its term. Only the spans around u are computed: level 1 is non-zero on
//! [lo, hi] alone and each level widens that by one to the left, so a point costs k^2 whatever
//! the number of control points (up to 20,000, each curve evaluated at 4 points per control point).
BasisWindow basis_at(double u, unsigned k, const std::vector<double>& t) {
    const std::size_t spans = t.size() - 1;
    // lo: the first span whose end reaches u; hi: the last span whose start is at or below u.
    const auto lo = static_cast<std::size_t>(std::lower_bound(t.begin() + 1, t.end(), u) - (t.begin() + 1));
    const auto past = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end() - 1, u) - t.begin());
    BasisWindow window;
    if (past == 0 || lo >= spans) return window;  // u outside the knots: every basis function is 0
    const std::size_t hi = past - 1;
    window.first = lo >= k - 1 ? lo - (k - 1) : 0;
    // level[m] is the value of index first + m; one zero past the end stands for hi + 1.
    std::vector<double> level(hi - window.first + 2, 0.0);
    for (std::size_t i = std::max(window.first, lo); i <= hi; ++i) {
        level[i - window.first] = (u >= t[i] && u <= t[i + 1]) ? 1.0 : 0.0;
    }
    for (unsigned j = 2; j <= k; ++j) {
        const std::size_t count = t.size() - j;  // basis functions of this level
        std::vector<double> next(level.size(), 0.0);
        for (std::size_t m = 0; m + 1 < level.size() && window.first + m < count; ++m) {
            const std::size_t i = window.first + m;
            const double left_span = t[i + j - 1] - t[i];
            const double right_span = t[i + j] - t[i + 1];
            double value = 0;
            if (left_span != 0) value += (u - t[i]) * level[m] / left_span;
            if (right_span != 0) value += (t[i + j] - u) * level[m + 1] / right_span;
            next[m] = value;
        }
        level = std::move(next);
    }
    const std::size_t count = t.size() - k;
    level.resize(std::min(level.size() - 1, count > window.first ? count - window.first : 0));
    window.values = std::move(level);
    return window;
}

PlanePoint point_at(double u, unsigned k, const std::vector<NurbsControlPoint>& points, const std::vector<double>& t) {
    const BasisWindow basis = basis_at(u, k, t);
    double weight = 0;
    for (std::size_t m = 0; m < basis.values.size(); ++m) weight += basis.values[m] * points[basis.first + m].weight;
    PlanePoint p;
    for (std::size_t m = 0; m < basis.values.size(); ++m) {
        const NurbsControlPoint& c = points[basis.first + m];
        p.first += c.first * basis.values[m] * c.weight / weight;
        p.second += c.second * basis.values[m] * c.weight / weight;
    }
    return p;
}

PlanePoint unit(PlanePoint v) {
    const double length = std::hypot(v.first, v.second);
    if (length != 0) {
        v.first /= length;
        v.second /= length;
    }
    return v;
}

//! The unit tangent at u: the chord from u - 1e-5 to u + 1e-5 (clipped to the curve's ends).
PlanePoint tangent_at(double u, double u_max, unsigned k, const std::vector<NurbsControlPoint>& points,
                      const std::vector<double>& t) {
    constexpr double du = 1e-5;
    const double lo = std::max(0.0, u - du);
    const double hi = std::min(u_max, u + du);
    const PlanePoint a = point_at(lo, k, points, t);
    const PlanePoint b = point_at(hi, k, points, t);
    return unit({(b.first - a.first) / (hi - lo), (b.second - a.second) / (hi - lo)});
}

//! The arc from p0 to p1 leaving p0 along the unit direction d; a straight feed when the
//! direction already points (nearly) at p1.
SplineElement arc_from(PlanePoint p0, PlanePoint p1, PlanePoint d) {
    const double x = p1.first - p0.first;
    const double y = p1.second - p0.second;
    const double den = 2 * (y * d.first - x * d.second);
    SplineElement e;
    e.end_first = p1.first;
    e.end_second = p1.second;
    if (std::abs(den) <= 1e-6) return e;
    const double r = -(x * x + y * y) / den;  // signed: below 0 turns counter-clockwise
    e.arc = true;
    e.center_first = p0.first + d.second * r;
    e.center_second = p0.second - d.first * r;
    e.counterclockwise = r < 0;
    return e;
}

//! The biarc from p0 (unit tangent ts) to p4 (unit tangent te) with equal tangent lengths: the
//! two arcs meet at p2 on the segment between the tangents' far points p1 and p3.
void biarc(PlanePoint p0, PlanePoint ts, PlanePoint p4, PlanePoint te, std::vector<SplineElement>& out) {
    ts = unit(ts);
    te = unit(te);
    const double vx = p0.first - p4.first;
    const double vy = p0.second - p4.second;
    const double c = vx * vx + vy * vy;
    const double b = 2 * (vx * (ts.first + te.first) + vy * (ts.second + te.second));
    const double a = 2 * (ts.first * te.first + ts.second * te.second - 1);
    const double discriminant = b * b - 4 * a * c;
    if (discriminant < 0) return;  // LinuxCNC leaves the step out (a <= 0 <= c: only by rounding)
    const double root = std::sqrt(discriminant);
    const double beta1 = (-b - root) / 2 / a;
    const double beta2 = (-b + root) / 2 / a;
    if (beta1 > 0 && beta2 > 0) return;
    const double beta = std::max(beta1, beta2);
    // Parallel tangents (a = 0) or a tangent length beyond 1e8: a straight feed to p4, as
    // LinuxCNC now does; nckit takes every other non-finite case that way too.
    if (!std::isfinite(beta) || beta > 1e8) {
        SplineElement line;
        line.end_first = p4.first;
        line.end_second = p4.second;
        out.push_back(line);
        return;
    }
    const PlanePoint p1{p0.first + beta * ts.first, p0.second + beta * ts.second};
    const PlanePoint p3{p4.first - beta * te.first, p4.second - beta * te.second};
    const PlanePoint p2{(p1.first + p3.first) / 2, (p1.second + p3.second) / 2};
    const PlanePoint middle = unit({p3.first - p2.first, p3.second - p2.second});
    out.push_back(arc_from(p0, p2, ts));
    out.push_back(arc_from(p2, p4, middle));
}

}  // namespace

std::vector<SplineElement> nurbs_biarcs(const std::vector<NurbsControlPoint>& points, unsigned order) {
    std::vector<SplineElement> out;
    if (points.size() < order || order < 2) return out;
    const auto n = static_cast<unsigned>(points.size() - 1);
    const double u_max = n - order + 2;
    const std::vector<double> t = knots_for(n, order);
    const auto steps = static_cast<unsigned>(points.size() * 4);
    PlanePoint p0 = point_at(0, order, points, t);
    PlanePoint t0 = tangent_at(0, u_max, order, points, t);
    for (unsigned i = 1; i <= steps; ++i) {
        const double u = u_max * i / steps;
        const PlanePoint p1 = point_at(u, order, points, t);
        const PlanePoint t1 = tangent_at(u, u_max, order, points, t);
        biarc(p0, t0, p1, t1, out);
        p0 = p1;
        t0 = t1;
    }
    return out;
}

}  // namespace nckit::interp::ngc
