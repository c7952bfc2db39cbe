#pragma once
// The one scalar root finder of nckit: Newton's method kept inside a bracket. Profiles (the time
// a profile reaches a position), step crossings on arcs and the spindle's angle under speed
// ripple all invert a smooth increasing function this way.
#include <cmath>

namespace nckit {

//! f(x) and f'(x) at one point.
struct ValueSlope {
    double value = 0;
    double slope = 0;
};

//! When the search stops; every test is optional (0 switches it off, except the iteration cap).
struct NewtonStop {
    double value_tolerance = 0;    //!< |f(x)| <= this: x is the root (0: only an exact zero)
    double step_tolerance = 0;     //!< a step no longer than this ends the search at its end
    double bracket_tolerance = 0;  //!< a bracket no wider than this ends the search
    int max_iterations = 100;      //!< evaluations of f at most
};

//! Where the search ended.
struct NewtonRoot {
    double x = 0;            //!< the root found (always within the initial bracket)
    double lo = 0, hi = 0;   //!< the final bracket: f(lo) <= 0 <= f(hi) when the input held it
    int evaluations = 0;     //!< calls of f
    bool converged = false;  //!< false: the iteration cap ended the search
};

//! Root of f on [lo, hi], f increasing there with f(lo) <= 0 <= f(hi), starting from x.
//! Each evaluation narrows the bracket to the side of the root; a Newton step that leaves the
//! bracket (a flat or wrong-signed slope, a square-root end) is replaced by bisection, so the
//! search cannot diverge or cycle, and it ends when the bracket is down to adjacent doubles at
//! the latest. A decreasing function is searched as -f.
template <class F>
NewtonRoot bracketed_newton(F&& f, double lo, double hi, double x, const NewtonStop& stop) {
    if (!(x >= lo)) x = lo;  // also a NaN start
    if (!(x <= hi)) x = hi;
    NewtonRoot root{x, lo, hi, 0, true};
    while (root.evaluations < stop.max_iterations) {
        if (root.hi - root.lo <= stop.bracket_tolerance) return root;
        const ValueSlope fx = f(root.x);
        ++root.evaluations;
        if (std::abs(fx.value) <= stop.value_tolerance) return root;
        if (fx.value < 0) {
            root.lo = root.x;
        } else {
            root.hi = root.x;
        }
        double next = root.lo;  // no Newton step without a positive slope: bisect
        if (fx.slope > 0) {
            next = root.x - fx.value / fx.slope;
            if (next == root.x) return root;  // the step is below x's last bit: a root to rounding
        }
        if (!(next > root.lo && next < root.hi)) {
            next = root.lo + 0.5 * (root.hi - root.lo);
            if (!(next > root.lo && next < root.hi)) return root;  // adjacent doubles
        }
        const double step = std::abs(next - root.x);
        root.x = next;
        if (step <= stop.step_tolerance || root.hi - root.lo <= stop.bracket_tolerance) return root;
    }
    root.converged = false;
    return root;
}

}  // namespace nckit
