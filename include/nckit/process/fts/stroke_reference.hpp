#pragma once
// The middle of a cam table's radial range along Z: the fast tool servo cuts about it, so its
// stroke is used symmetrically. The simulation (piston.hpp) and the HAL component (hal/) share it.
#include <cstddef>
#include <vector>

#include "nckit/cam/cam_table.hpp"
#include "nckit/cam/natural_spline.hpp"

namespace nckit {

//! The fast axis's zero along Z: (max_θ r + min_θ r) / 2 of the cam table at evenly spaced Z,
//! each extreme refined by a parabola through the best sample of the turn and its neighbours,
//! and a natural cubic spline between, so the slide's path is smooth (its curvature continuous)
//! even where the drawing changes formula.
class StrokeReference {
public:
    //! Over the table's Z range at `points` (>= 2) values of Z, the turn sampled every
    //! `theta_step_deg`.
    StrokeReference(const cam::CamTable& table, std::size_t points, double theta_step_deg = 0.25);

    //! mm, the radius the fast axis's mid-stroke cuts at `z_mm`.
    [[nodiscard]] double radius_mm(double z_mm) const { return spline_.value(z_mm); }
    [[nodiscard]] const cam::NaturalSpline& spline() const { return spline_; }

private:
    cam::NaturalSpline spline_;
};

//! Radii of one turn of `table` at `z_mm`: `count` samples from θ = 0 in equal steps.
void sample_turn(const cam::CamTable& table, double z_mm, std::size_t count, std::vector<double>& out);

//! Points a StrokeReference over `table` takes: one every half millimetre of Z, 17 .. 4097.
[[nodiscard]] std::size_t stroke_reference_points(const cam::CamTable& table);

}  // namespace nckit
