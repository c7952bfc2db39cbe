#pragma once
// Splines through digitised points: the closed (periodic) cubic spline of a sole outline, with
// an optional smoothing tolerance, and the open (natural) cubic spline of a motif.
#include <cstddef>
#include <vector>

#include "nckit/process/pattern/plane_curve.hpp"

namespace nckit::pattern {

//! A closed curve as cubic pieces, piece i from point i to point i+1 (the last back to the first).
struct ClosedSpline {
    CubicPath path;
    //! Largest distance from a digitised point to the curve, mm (0 when it interpolates).
    double max_fit_error_mm = 0;
    //! How many control points the smoothing fit kept (the number of pieces).
    std::size_t control_points = 0;
};

//! Fits a closed C2 cubic spline. `smoothing_tolerance_mm` = 0: it passes through every point
//! (periodic interpolation, chord-length parameters). > 0: the periodic least-squares cubic
//! B-spline with the fewest control points whose curve lies within the tolerance of every point
//! (doubling from n/16 control points; at n it interpolates). Needs >= 4 distinct points.
[[nodiscard]] ClosedSpline fit_closed_spline(const std::vector<Vec2>& points, double smoothing_tolerance_mm);

//! The open natural cubic spline through `points` (chord-length parameters; >= 2 points).
[[nodiscard]] CubicPath fit_open_spline(const std::vector<Vec2>& points);

//! Distance from p to the closed path and the parameter of the nearest point (Newton polish of
//! the nearest of dense samples).
struct NearestPoint {
    double distance_mm = 0;
    double s = 0;
};
[[nodiscard]] NearestPoint nearest_on_path(const CubicPath& path, Vec2 p);

}  // namespace nckit::pattern
