#pragma once
// The model a ramp transition is designed on (ramp_transition.hpp, docs/planner.md "Ramp
// transitions"): the curve's offset y from the programmed path along its normal in the plane, as
// a function of the programmed arc length x from the join (x < 0 on the move before). y'' is
// the difference Δκ between the curve's curvature and the path's (to first order in y),
// piecewise linear in x between knots; the path's curvature steps from ka to kb at 0 and its
// direction by `kink`, the curve's do not, so Δκ steps by ka − kb and y' by −kink there.
#include <array>

namespace nckit::plan_detail {

struct RampModel {
    double ka = 0, kb = 0, kink = 0;   //!< 1/mm, 1/mm, rad
    double ta = 0, tb = 0;             //!< mm, the trims
    double ease_a = 0, ease_b = 0;     //!< mm over which Δκ rises from 0 to its plateau
    double w = 0;                      //!< mm, half of the ramp across the join
    int plateau_a = 1, plateau_b = 1;  //!< pieces of each plateau
    //! Knots (part boundaries) and Δκ there as c + a·da + b·db (da, db: the plateaus' Δκ).
    std::array<double, 16> x{};
    std::array<std::array<double, 3>, 16> f{};
    int knots = 0;
    int ramp = 0;  //!< the ramp runs from knot `ramp` to `ramp + 1`
};

//! Sets the knots from the lengths and piece counts.
void set_knots(RampModel& m);

//! y, y' and Δκ at one x.
struct Offset {
    double y = 0, slope = 0, dk = 0;
};

//! The model solved: the offset at every knot, the largest |y| (sampled), the largest |κ| and
//! the largest |dκ/dx| of the curve.
struct RampSolution {
    std::array<Offset, 16> at{};
    double max_y = 0;
    double peak_curvature = 0;
    double peak_rate = 0;
};

//! One stretch of linear Δκ from fa to fb over h: y and y' advance in closed form.
void advance(Offset& o, double h, double fa, double fb);

//! The plateaus da, db that bring the curve back onto the path at tb with its direction (y and
//! y' at the end are affine in them: a 2×2 system), and the model integrated with them. False
//! when the system is singular.
[[nodiscard]] bool solve(const RampModel& m, RampSolution& out, double& da, double& db);

//! Arc length (mm) of the offset curve over a stretch of h from `start` with Δκ from fa to fb
//! on a path of curvature k: sqrt((1 − k·y)² + y'²) by Simpson's rule.
[[nodiscard]] double offset_length(const Offset& start, double h, double fa, double fb, double k);

}  // namespace nckit::plan_detail
