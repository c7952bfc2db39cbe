#include "nckit/cam/natural_spline.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace nckit::cam {

NaturalSpline::NaturalSpline(std::vector<double> x, std::vector<double> y)
    : x_(std::move(x)), y_(std::move(y)), m_(x_.size(), 0.0) {
    const std::size_t n = x_.size();
    if (n < 2 || y_.size() != n) {
        throw std::invalid_argument("NaturalSpline needs at least 2 points and as many y as x");
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (!std::isfinite(x_[i]) || !std::isfinite(y_[i])) {
            throw std::invalid_argument("NaturalSpline points must be finite");
        }
        if (i > 0 && !(x_[i] > x_[i - 1])) {
            throw std::invalid_argument("NaturalSpline x must increase strictly");
        }
    }
    if (n == 2) return;  // a straight line: y'' = 0 everywhere
    // Continuity of y' at the inner points gives a tridiagonal system for M_1..M_n-2:
    // h_{i-1} M_{i-1} + 2 (h_{i-1} + h_i) M_i + h_i M_{i+1} = 6 (d_i - d_{i-1}), M_0 = M_n-1 = 0.
    // It is strictly diagonally dominant, so elimination without pivoting is stable.
    const std::size_t inner = n - 2;
    std::vector<double> diag(inner), upper(inner), rhs(inner);
    for (std::size_t k = 0; k < inner; ++k) {
        const std::size_t i = k + 1;
        const double h0 = x_[i] - x_[i - 1];
        const double h1 = x_[i + 1] - x_[i];
        diag[k] = 2.0 * (h0 + h1);
        upper[k] = h1;
        rhs[k] = 6.0 * ((y_[i + 1] - y_[i]) / h1 - (y_[i] - y_[i - 1]) / h0);
    }
    for (std::size_t k = 1; k < inner; ++k) {
        const double lower = x_[k + 1] - x_[k];  // h_{i-1} for i = k + 1
        const double factor = lower / diag[k - 1];
        diag[k] -= factor * upper[k - 1];
        rhs[k] -= factor * rhs[k - 1];
    }
    for (std::size_t k = inner; k-- > 0;) {
        m_[k + 1] = (rhs[k] - upper[k] * m_[k + 2]) / diag[k];  // m_[n-1] stays 0
    }
}

std::size_t NaturalSpline::interval(double x) const {
    // upper_bound finds the first point right of x; the interval starts one before it.
    const auto hit = std::upper_bound(x_.begin() + 1, x_.end() - 1, x);
    return static_cast<std::size_t>(hit - x_.begin()) - 1;
}

double NaturalSpline::value(double x) const {
    const std::size_t last = x_.size() - 1;
    if (x < x_[0]) return y_[0] + slope(x_[0]) * (x - x_[0]);
    if (x > x_[last]) return y_[last] + slope(x_[last]) * (x - x_[last]);
    const std::size_t k = interval(x);
    const double h = x_[k + 1] - x_[k];
    const double a = (x_[k + 1] - x) / h;
    const double b = (x - x_[k]) / h;
    return a * y_[k] + b * y_[k + 1] + ((a * a * a - a) * m_[k] + (b * b * b - b) * m_[k + 1]) * (h * h) / 6.0;
}

double NaturalSpline::slope(double x) const {
    const std::size_t last = x_.size() - 1;
    const double inside = std::clamp(x, x_[0], x_[last]);  // straight beyond: the end slope
    const std::size_t k = interval(inside);
    const double h = x_[k + 1] - x_[k];
    const double a = (x_[k + 1] - inside) / h;
    const double b = (inside - x_[k]) / h;
    return (y_[k + 1] - y_[k]) / h + ((1.0 - 3.0 * a * a) * m_[k] + (3.0 * b * b - 1.0) * m_[k + 1]) * h / 6.0;
}

double NaturalSpline::curvature(double x) const {
    const std::size_t last = x_.size() - 1;
    if (x < x_[0] || x > x_[last]) return 0.0;
    const std::size_t k = interval(x);
    const double h = x_[k + 1] - x_[k];
    return ((x_[k + 1] - x) * m_[k] + (x - x_[k]) * m_[k + 1]) / h;
}

}  // namespace nckit::cam
