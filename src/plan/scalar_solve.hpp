#pragma once
// The two scalar root finders the profile maths needs.
#include <cmath>

namespace nckit::plan_detail {

struct ValueSlope {
    double value = 0;
    double slope = 0;
};

//! Root of f, increasing on [lo, hi] with f(lo) <= 0 <= f(hi), starting from x in [lo, hi].
//! Newton steps converge quadratically on these smooth functions; a step that leaves the
//! bracket (near a square-root end, or a flat slope) is replaced by bisection, and every
//! evaluation narrows the bracket, so it cannot diverge or cycle. Stops when |f| <= tolerance
//! or the bracket is down to adjacent doubles.
template <class F>
double solve_increasing(F&& f, double lo, double hi, double x, double tolerance) {
    for (int iteration = 0; iteration < 200; ++iteration) {
        const ValueSlope fx = f(x);
        if (std::abs(fx.value) <= tolerance) return x;
        if (fx.value < 0) {
            lo = x;
        } else {
            hi = x;
        }
        double next = x - fx.value / fx.slope;
        if (!(next > lo && next < hi)) {
            next = lo + 0.5 * (hi - lo);
            if (!(next > lo && next < hi)) return x;  // bracket exhausted
        }
        x = next;
    }
    return x;
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
