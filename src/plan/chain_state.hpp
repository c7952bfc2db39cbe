#pragma once
// The state at the middle of a line of a CAM chain where two chained transitions meet
// (transition.hpp, ChainStart): the direction and curvature of the smooth curve the chain
// samples, estimated from the directions of the line and its two neighbours.
//
// Why not the line's own direction: the middles of the chords of a curve g lie on the curve
// G = g + h²·g''/8 (h the chord length), whose direction there is g' + h²·g'''/8, while the
// chord's direction is g' + h²·g'''/24. A quintic given the chord's direction at both of its
// ends is off by h²·g'''/12 at each, on the same side, and bends to make up for it: its third
// derivative gains 60·(h²·g'''/12)/h² = 5·g'''. On the 0.5 mm rows of the 3D raster
// (g''' = 0.0039 /mm²) that was 0.020 /mm² where the surface has 0.0039, and the jerk term
// q'''·v³ held the rows to 43.5 mm/s at j 5,000 (docs/planner.md, "CAM polylines").
#include <array>
#include <cmath>

namespace nckit::plan_detail {

struct ChainMidState {
    std::array<double, 3> d1{};  //!< unit direction dq/ds
    std::array<double, 3> d2{};  //!< curvature vector d²q/ds², normal to d1 (1/mm)
};

//! At the middle of a line of length `line_mm` in direction `line_d1`, between the chord
//! directions `before_d1` (the line before, whose middle lies `before_mm` back along the
//! chain) and `after_d1` (the line after, `after_mm` on): direction g' + h²·g'''/12 with g'''
//! from the second difference of the three directions, and the curvature (after − before) /
//! (before_mm + after_mm) with its part along that direction removed (|q'| stays 1 to first
//! order, so the quintics meeting there keep their parameter speed). A straight or circular
//! chain of equal lines keeps the line's direction (a circle's g''' lies along the tangent).
[[nodiscard]] inline ChainMidState chain_mid_state(const std::array<double, 3>& before_d1, double before_mm,
                                                   const std::array<double, 3>& line_d1, double line_mm,
                                                   const std::array<double, 3>& after_d1, double after_mm) {
    ChainMidState s;
    const double spacing = 0.5 * (before_mm + after_mm);
    const double correction = line_mm * line_mm / 12.0;
    double norm2 = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        const double third =
            ((after_d1[i] - line_d1[i]) / after_mm - (line_d1[i] - before_d1[i]) / before_mm) / spacing;
        s.d1[i] = line_d1[i] + correction * third;
        norm2 += s.d1[i] * s.d1[i];
    }
    const double inv = 1.0 / std::sqrt(norm2);
    double along = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        s.d1[i] *= inv;
        s.d2[i] = (after_d1[i] - before_d1[i]) / (before_mm + after_mm);
        along += s.d2[i] * s.d1[i];
    }
    for (std::size_t i = 0; i < 3; ++i) s.d2[i] -= along * s.d1[i];
    return s;
}

}  // namespace nckit::plan_detail
