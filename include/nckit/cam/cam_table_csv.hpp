#pragma once
#include <ostream>
#include <span>

#include "nckit/cam/cam_table.hpp"

namespace nckit::cam {

//! Decimals of z_mm and radius_mm in the CSV: 6, i.e. 1 nm, below a 16-bit DAC step over 1 mm
//! (15 nm) and at the cam table's tolerance.
inline constexpr int cam_csv_decimals = 6;

//! Writes the header `z_mm,phi_deg,radius_mm`, then for each Z of `z_mm` in order the rows
//! φ = 0, 1, ..., 359 (whole degrees, written as integers) with `radius_mm(φ, z)`; z_mm and
//! radius_mm with cam_csv_decimals decimals. Lines end in '\n'.
void write_cam_table_csv(std::ostream& out, const CamFunction& radius_mm, std::span<const double> z_mm);

}  // namespace nckit::cam
