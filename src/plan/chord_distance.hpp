#pragma once
// The distance from a point to a straight chord in XYZ, which the chain smoother (how far a
// smoothed vertex lies from a merged chord) and the transitions (how far a curve strays from its
// polygon) both measure.
#include <algorithm>
#include <cstddef>

namespace nckit::plan_detail {

//! mm²: the squared distance from p to the chord a–b, over the first three coordinates of any
//! indexable vector (AxisVector, std::array<double, 3>); a chord of zero length is its point a.
template <class Point>
double distance2_to_chord(const Point& p, const Point& a, const Point& b) {
    double dd = 0;
    double t = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        dd += (b[i] - a[i]) * (b[i] - a[i]);
        t += (p[i] - a[i]) * (b[i] - a[i]);
    }
    t = dd > 0 ? std::clamp(t / dd, 0.0, 1.0) : 0.0;
    double d2 = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        const double e = p[i] - a[i] - t * (b[i] - a[i]);
        d2 += e * e;
    }
    return d2;
}

}  // namespace nckit::plan_detail
