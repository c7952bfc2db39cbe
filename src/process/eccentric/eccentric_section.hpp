#pragma once
// Private to the eccentric process: the circle fit of a cut section.
#include <array>
#include <vector>

#include "nckit/process/eccentric/eccentric.hpp"

namespace nckit::eccentric_detail {

//! Fits a circle to the nose-centre points (mm, part frame) of one section and compares it
//! with the drawing: the circle of radius r + Rn about (e, 0).
[[nodiscard]] SectionFit fit_section(const std::vector<std::array<double, 2>>& points, const EccentricJob& job);

}  // namespace nckit::eccentric_detail
