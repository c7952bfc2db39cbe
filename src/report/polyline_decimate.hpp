#pragma once
// Dropping the interior points of a move's polyline that the drawing does not need.
#include <vector>

#include "nckit/report/tool_path.hpp"

namespace nckit::report_detail {

//! Keeps points[0] and points.back(); drops an interior point when the chord between the kept
//! points around it passes within tolerance_mm of it and the speed interpolated along the chord
//! is within speed_tolerance_mm_s of its speed. Greedy from the start, at most `window` points
//! per chord (so the cost is linear in the number of points). Returns the kept points after
//! points[0].
[[nodiscard]] std::vector<ReportVertex> decimate(const std::vector<ReportVertex>& points, double tolerance_mm,
                                                 double speed_tolerance_mm_s, std::size_t window = 64);

}  // namespace nckit::report_detail
