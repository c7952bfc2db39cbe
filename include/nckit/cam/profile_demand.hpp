#pragma once
#include <span>

#include "nckit/cam/cam_table.hpp"

namespace nckit::cam {

//! What a profile asks of the fast axis that cuts it: the radial range over a turn, and the
//! curvature d²r/dθ² that becomes acceleration ω² d²r/dθ² at a spindle speed.
struct ProfileDemand {
    double stroke_mm = 0;            //!< mm, largest max_θ r − min_θ r over the Z checked
    double stroke_z_mm = 0;          //!< mm, the Z where it is largest
    double min_radius_mm = 0;        //!< mm, smallest r seen (a shape must keep r > 0)
    double curvature_mm_rad2 = 0;    //!< mm/rad², largest |d²r/dθ²|
    double curvature_theta_deg = 0;  //!< deg, where it is largest
    double curvature_z_mm = 0;       //!< mm
    bool finite = true;              //!< every value seen was finite

    //! mm/s², the largest radial acceleration at `rpm`: ω² |d²r/dθ²|, ω = 2π rpm / 60.
    [[nodiscard]] double acceleration_mm_s2(double rpm) const;
    //! rpm at which that acceleration reaches `max_acceleration_mm_s2` (infinite for a round
    //! section).
    [[nodiscard]] double max_rpm(double max_acceleration_mm_s2) const;
};

//! Where the demand is measured: every `theta_step_deg` around the turn at each Z station and
//! `z_subdivisions` − 1 points between neighbouring stations (the splines can bulge there).
struct DemandGrid {
    double theta_step_deg = 0.25;  //!< deg; 360 / step is rounded to a whole number of points
    int z_subdivisions = 8;        //!< pieces each station interval is cut into, >= 1
};

//! The demand of `radius_mm(θ, z)` over the stations `z_mm` (increasing, at least one).
//! d²r/dθ² comes from second differences of the sampled turn, which at 0.25° are within a few
//! parts per million of the derivative for a drawing's low harmonics.
[[nodiscard]] ProfileDemand measure_demand(const CamFunction& radius_mm, std::span<const double> z_mm,
                                           DemandGrid grid = {});

//! The Z values the demand grid visits: the stations and the points between them.
[[nodiscard]] std::vector<double> demand_z_grid(std::span<const double> z_mm, int z_subdivisions);

}  // namespace nckit::cam
