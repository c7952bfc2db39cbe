#pragma once
#include <cstddef>
#include <span>

#include "nckit/cam/cam_table.hpp"
#include "nckit/cam/piston_profile.hpp"

namespace nckit::cam {

//! The fewest equal Z cells (up to `max_cells`) over [breaks.front(), breaks.back()] whose
//! nodes fall on every break (stations, ends of formula intervals), so that each cell lies in
//! one spline piece or formula; 0 when none up to `max_cells` does. `breaks` is increasing.
[[nodiscard]] std::size_t aligned_z_cells(std::span<const double> breaks_mm, std::size_t max_cells = 4096);

//! Table options for a profile drawn between the first and last of `breaks_mm` (the stations
//! and any other Z where the drawing changes formula): that Z range, cells aligned with the
//! breaks where possible, else one cell per shortest interval.
[[nodiscard]] CamTableOptions piston_cam_options(std::span<const double> breaks_mm, double tolerance_mm = 1e-6);

//! The cam engine for `profile`: r(θ, z) tabulated to `options.tolerance_mm`.
[[nodiscard]] CamTable build_piston_cam_table(const PistonProfile& profile, const CamTableOptions& options);

}  // namespace nckit::cam
