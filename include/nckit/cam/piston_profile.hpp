#pragma once
#include "nckit/cam/drawing_function.hpp"
#include "nckit/cam/section_shape.hpp"

namespace nckit::cam {

//! The piston as drawn: r(θ, Z) = D(Z)/2 − drop(φ = θ, Z), with θ the spindle angle measured
//! from the major axis and Z from the crown. Exact (no tables): the reference a CamTable is
//! built from and checked against. Not safe to evaluate from two threads at once when any
//! part is a formula; copies are independent.
class PistonProfile {
public:
    PistonProfile(DrawingFunction major_diameter_mm, DrawingFunction ovality_mm, SectionShape shape);

    //! mm, the section's radius at `theta_deg` from the major axis, `z_mm` from the crown.
    [[nodiscard]] double radius_mm(double theta_deg, double z_mm) const;
    [[nodiscard]] double operator()(double theta_deg, double z_mm) const { return radius_mm(theta_deg, z_mm); }

    //! D(Z), mm
    [[nodiscard]] double major_diameter_mm(double z_mm) const { return major_diameter_(z_mm); }
    //! E(Z) = D − d, mm
    [[nodiscard]] double ovality_mm(double z_mm) const { return ovality_(z_mm); }
    [[nodiscard]] const SectionShape& shape() const { return shape_; }

private:
    DrawingFunction major_diameter_;
    DrawingFunction ovality_;
    SectionShape shape_;
};

}  // namespace nckit::cam
