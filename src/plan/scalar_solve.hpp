#pragma once
// The two scalar root finders the profile maths needs.
#include <cmath>

#include "nckit/core/bracketed_newton.hpp"

namespace nckit::plan_detail {

using nckit::ValueSlope;

//! Root of f, increasing on [lo, hi] with f(lo) <= 0 <= f(hi), starting from x in [lo, hi]:
//! nckit's bracketed Newton, stopping when |f| <= tolerance or the bracket is down to adjacent
//! doubles. Newton steps converge quadratically on these smooth functions.
template <class F>
double solve_increasing(F&& f, double lo, double hi, double x, double tolerance) {
    return bracketed_newton(f, lo, hi, x, NewtonStop{.value_tolerance = tolerance, .max_iterations = 200}).x;
}

//! The real root of s^3 + p s - m = 0 for p >= 0 and m >= 0 (then it is the only one, and
//! >= 0). Cardano's A + B, with A B = -p/3, is rewritten as m / (A^2 - A B + B^2), a quotient
//! of positive terms, so it keeps full relative precision when p^3 dwarfs m^2.
inline double cubic_root(double p, double m) {
    const double half_m = 0.5 * m;
    const double a = std::cbrt(half_m + std::sqrt(half_m * half_m + p * p * p / 27.0));
    if (a == 0) return 0;
    const double b = p / (3.0 * a);
    return m / (a * a + p / 3.0 + b * b);
}

}  // namespace nckit::plan_detail
