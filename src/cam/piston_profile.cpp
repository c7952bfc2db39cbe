#include "nckit/cam/piston_profile.hpp"

namespace nckit::cam {

PistonProfile::PistonProfile(DrawingFunction major_diameter_mm, DrawingFunction ovality_mm, SectionShape shape)
    : major_diameter_(std::move(major_diameter_mm)), ovality_(std::move(ovality_mm)), shape_(std::move(shape)) {}

double PistonProfile::radius_mm(double theta_deg, double z_mm) const {
    const double d = major_diameter_(z_mm);
    const double e = ovality_(z_mm);
    return 0.5 * d - shape_.drop_mm(theta_deg, z_mm, d, e);
}

}  // namespace nckit::cam
