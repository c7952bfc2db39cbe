#pragma once
// The sole outline: digitised points (CSV `x_mm,y_mm`, or a closed polyline or spline of a DXF
// drawing) fitted by a closed cubic spline, checked to be a simple closed curve, turned
// counter-clockwise, and the border a given width inside it, which the pattern is clipped to.
#include <filesystem>
#include <vector>

#include "nckit/core/result.hpp"
#include "nckit/core/source_location.hpp"
#include "nckit/process/pattern/plane_curve.hpp"

namespace nckit::pattern {

//! Digitised points in order round the sole and where each came from (CSV line, or the file).
struct OutlinePoints {
    std::vector<Vec2> points;
    std::vector<SourceLocation> where;
};

//! Reads a CSV with the header `x_mm,y_mm`, one point a row (blank lines and `#` comments
//! skipped); a bad row is an error at its line and column. At most 100000 points.
[[nodiscard]] Result<OutlinePoints> load_outline_csv(const std::filesystem::path& path);
//! The first closed polyline or spline of a DXF drawing (its vertices or fit points).
[[nodiscard]] Result<OutlinePoints> load_outline_dxf(const std::filesystem::path& path);
//! By extension: `.dxf` (any case) through dxflib, anything else as CSV.
[[nodiscard]] Result<OutlinePoints> load_outline_points(const std::filesystem::path& path);

struct SoleOutline {
    CubicPath curve;          //!< closed, counter-clockwise
    double fit_error_mm = 0;  //!< largest distance of a digitised point from the curve
    std::size_t control_points = 0;
    Box box;
};

//! Fits the closed spline (see fit_closed_spline) and checks it: fewer than 4 distinct points,
//! or a curve that crosses itself, is an error at the digitised point nearest the trouble.
[[nodiscard]] Result<SoleOutline> fit_sole_outline(const OutlinePoints& points, double smoothing_tolerance_mm);

//! The border `width_mm` inside the outline: points offset along the inward normal, 16 per
//! outline piece, fitted by a closed interpolating spline; its largest deviation from the exact
//! offset is measured halfway between samples. A width the outline's curvature does not allow
//! (the offset curve folds over) is an error at `where`.
struct Border {
    CubicPath curve;
    double offset_error_mm = 0;
};
[[nodiscard]] Result<Border> inner_border(const SoleOutline& outline, double width_mm, const SourceLocation& where);

//! True when the closed polygon crosses itself; `at` gets a point near the first crossing.
[[nodiscard]] bool polygon_crosses_itself(const std::vector<Vec2>& polygon, Vec2& at);

}  // namespace nckit::pattern
