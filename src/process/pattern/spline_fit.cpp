// Cubic spline fits of digitised points (closed outlines, open motif curves).
#include "nckit/process/pattern/spline_fit.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Sparse>

namespace nckit::pattern {

namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

// Chord lengths h_i between successive points (closed: the last back to the first).
std::vector<double> chords(const std::vector<Vec2>& p, bool closed) {
    const std::size_t n = p.size();
    const std::size_t count = closed ? n : n - 1;
    std::vector<double> h(count);
    for (std::size_t i = 0; i < count; ++i) h[i] = std::max(length(p[(i + 1) % n] - p[i]), 1e-9);
    return h;
}

// Second derivatives M (per coordinate) of the C2 cubic with knots at the cumulative chords:
// h_{i-1}·M_{i-1} + 2(h_{i-1} + h_i)·M_i + h_i·M_{i+1} = 6·(slope_i − slope_{i−1}); the
// closed spline wraps round, the open one is natural (M = 0 at both ends).
std::pair<Eigen::VectorXd, Eigen::VectorXd> second_derivatives(const std::vector<Vec2>& p, const std::vector<double>& h,
                                                               bool closed) {
    const auto n = static_cast<Eigen::Index>(p.size());
    Triplets t;
    Eigen::VectorXd rx = Eigen::VectorXd::Zero(n);
    Eigen::VectorXd ry = Eigen::VectorXd::Zero(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        const bool end = !closed && (i == 0 || i == n - 1);
        if (end) {
            t.emplace_back(i, i, 1.0);
            continue;
        }
        const auto prev = static_cast<std::size_t>((i + n - 1) % n);
        const auto here = static_cast<std::size_t>(i);
        const auto next = static_cast<std::size_t>((i + 1) % n);
        const double hp = h[prev];
        const double hi = h[here];
        t.emplace_back(i, static_cast<Eigen::Index>(prev), hp);
        t.emplace_back(i, i, 2.0 * (hp + hi));
        t.emplace_back(i, static_cast<Eigen::Index>(next), hi);
        rx[i] = 6.0 * ((p[next].x - p[here].x) / hi - (p[here].x - p[prev].x) / hp);
        ry[i] = 6.0 * ((p[next].y - p[here].y) / hi - (p[here].y - p[prev].y) / hp);
    }
    Eigen::SparseMatrix<double> a(n, n);
    a.setFromTriplets(t.begin(), t.end());
    Eigen::SparseLU<Eigen::SparseMatrix<double>> solver(a);
    return {solver.solve(rx), solver.solve(ry)};
}

CubicPath pieces_from(const std::vector<Vec2>& p, const std::vector<double>& h, const Eigen::VectorXd& mx,
                      const Eigen::VectorXd& my) {
    CubicPath path;
    const std::size_t n = p.size();
    for (std::size_t i = 0; i < h.size(); ++i) {
        const std::size_t j = (i + 1) % n;
        const auto ii = static_cast<Eigen::Index>(i);
        const auto jj = static_cast<Eigen::Index>(j);
        const double hh = h[i];
        auto coefficients = [&](double y0, double y1, double m0, double m1) {
            const double slope = (y1 - y0) / hh - hh * (2.0 * m0 + m1) / 6.0;
            return std::array<double, 4>{y0, slope * hh, 0.5 * m0 * hh * hh, (m1 - m0) * hh * hh / 6.0};
        };
        const auto cx = coefficients(p[i].x, p[j].x, mx[ii], mx[jj]);
        const auto cy = coefficients(p[i].y, p[j].y, my[ii], my[jj]);
        CubicPiece piece;
        for (std::size_t k = 0; k < 4; ++k) piece.c[k] = {cx[k], cy[k]};
        path.pieces.push_back(piece);
    }
    return path;
}

CubicPath interpolate_closed(const std::vector<Vec2>& p) {
    const std::vector<double> h = chords(p, true);
    auto [mx, my] = second_derivatives(p, h, true);
    return pieces_from(p, h, mx, my);
}

// Periodic uniform cubic B-spline with m control points fitted to p in the least-squares sense,
// point k at parameter m·(chord length to k)/(perimeter).
CubicPath least_squares_closed(const std::vector<Vec2>& p, std::size_t m) {
    const std::vector<double> h = chords(p, true);
    double perimeter = 0;
    for (double v : h) perimeter += v;
    const auto mm = static_cast<Eigen::Index>(m);
    Triplets t;
    Eigen::VectorXd bx = Eigen::VectorXd::Zero(mm);
    Eigen::VectorXd by = Eigen::VectorXd::Zero(mm);
    Eigen::SparseMatrix<double> normal(mm, mm);
    double along = 0;
    for (std::size_t k = 0; k < p.size(); ++k) {
        const double tau = static_cast<double>(m) * along / perimeter;
        along += h[k];
        const auto j = static_cast<Eigen::Index>(std::min(std::floor(tau), static_cast<double>(m - 1)));
        const double u = tau - static_cast<double>(j);
        const std::array<double, 4> b{(1 - u) * (1 - u) * (1 - u) / 6.0, (3 * u * u * u - 6 * u * u + 4) / 6.0,
                                      (-3 * u * u * u + 3 * u * u + 3 * u + 1) / 6.0, u * u * u / 6.0};
        for (Eigen::Index r = 0; r < 4; ++r) {
            const Eigen::Index row = (j - 1 + r + mm) % mm;
            bx[row] += b[static_cast<std::size_t>(r)] * p[k].x;
            by[row] += b[static_cast<std::size_t>(r)] * p[k].y;
            for (Eigen::Index c = 0; c < 4; ++c) {
                t.emplace_back(row, (j - 1 + c + mm) % mm,
                               b[static_cast<std::size_t>(r)] * b[static_cast<std::size_t>(c)]);
            }
        }
    }
    // A faint pull towards neighbours' mean keeps spans without points determined.
    for (Eigen::Index i = 0; i < mm; ++i) {
        t.emplace_back(i, i, 2e-9);
        t.emplace_back(i, (i + 1) % mm, -1e-9);
        t.emplace_back(i, (i + mm - 1) % mm, -1e-9);
    }
    normal.setFromTriplets(t.begin(), t.end());
    Eigen::SparseLU<Eigen::SparseMatrix<double>> solver(normal);
    const Eigen::VectorXd px = solver.solve(bx);
    const Eigen::VectorXd py = solver.solve(by);
    CubicPath path;
    for (Eigen::Index j = 0; j < mm; ++j) {
        auto c = [&](Eigen::Index r) { return Vec2{px[(j - 1 + r + mm) % mm], py[(j - 1 + r + mm) % mm]}; };
        const Vec2 p0 = c(0), p1 = c(1), p2 = c(2), p3 = c(3);
        CubicPiece piece{{(1.0 / 6.0) * (p0 + 4.0 * p1 + p2), 0.5 * (p2 - p0), 0.5 * (p0 - 2.0 * p1 + p2),
                          (1.0 / 6.0) * (3.0 * p1 - 3.0 * p2 + p3 - p0)}};
        path.pieces.push_back(piece);
    }
    return path;
}

double max_error(const CubicPath& path, const std::vector<Vec2>& p) {
    double worst = 0;
    for (const Vec2& q : p) worst = std::max(worst, nearest_on_path(path, q).distance_mm);
    return worst;
}

}  // namespace

NearestPoint nearest_on_path(const CubicPath& path, Vec2 p) {
    constexpr int samples = 8;
    NearestPoint best{1e300, 0};
    for (std::size_t i = 0; i < path.pieces.size(); ++i) {
        for (int k = 0; k < samples; ++k) {
            const double u = (k + 0.5) / samples;
            const double d = length(path.pieces[i].point(u) - p);
            if (d < best.distance_mm) best = {d, static_cast<double>(i) + u};
        }
    }
    // Newton on f(s) = (P(s) − p)·P'(s), kept inside the sample's neighbourhood.
    const auto n = static_cast<double>(path.pieces.size());
    double s = best.s;
    const double low = s - 1.0 / samples, high = s + 1.0 / samples;
    for (int it = 0; it < 30; ++it) {
        const double wrapped = std::fmod(std::fmod(s, n) + n, n);
        const auto i = static_cast<std::size_t>(std::min(std::floor(wrapped), n - 1));
        const double u = wrapped - static_cast<double>(i);
        const CubicPiece& piece = path.pieces[i];
        const Vec2 d = piece.point(u) - p;
        const Vec2 t = piece.tangent(u);
        const double f = dot(d, t);
        const double df = dot(t, t) + dot(d, piece.second(u));
        if (df <= 0) break;
        const double next = std::clamp(s - f / df, low, high);
        if (std::abs(next - s) < 1e-15) break;
        s = next;
    }
    const double wrapped = std::fmod(std::fmod(s, n) + n, n);
    const auto i = static_cast<std::size_t>(std::min(std::floor(wrapped), n - 1));
    const double d = length(path.pieces[i].point(wrapped - static_cast<double>(i)) - p);
    if (d < best.distance_mm) best = {d, wrapped};
    return best;
}

ClosedSpline fit_closed_spline(const std::vector<Vec2>& points, double smoothing_tolerance_mm) {
    ClosedSpline out;
    if (smoothing_tolerance_mm > 0) {
        for (std::size_t m = std::max<std::size_t>(8, points.size() / 16); m < points.size(); m *= 2) {
            CubicPath path = least_squares_closed(points, m);
            const double error = max_error(path, points);
            if (error <= smoothing_tolerance_mm) {
                out.path = std::move(path);
                out.max_fit_error_mm = error;
                out.control_points = m;
                return out;
            }
        }
    }
    out.path = interpolate_closed(points);
    out.max_fit_error_mm = 0;
    out.control_points = points.size();
    return out;
}

CubicPath fit_open_spline(const std::vector<Vec2>& points) {
    if (points.size() == 2) {
        return CubicPath{{CubicPiece{{points[0], points[1] - points[0], Vec2{}, Vec2{}}}}};
    }
    const std::vector<double> h = chords(points, false);
    auto [mx, my] = second_derivatives(points, h, false);
    return pieces_from(points, h, mx, my);
}

}  // namespace nckit::pattern
