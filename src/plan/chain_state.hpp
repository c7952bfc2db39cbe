#pragma once
// The state at the middle of a line of a CAM chain where two chained transitions meet
// (transition.hpp, ChainStart): the point, direction and curvature of the smooth curve the chain
// samples, estimated from the directions of the line and its two neighbours.
//
// Why not the line's own middle and direction: the middle of a chord of length h of a curve g
// lies h²·g''/8 inside the curve, and the chord's direction is g' + h²·g'''/24. With the middles
// as the meeting points, a quintic given the chords' directions at both of its ends is off by
// h²·g'''/12 at each, on the same side, and bends to make up for it: its third derivative gained
// 60·(h²·g'''/12)/h² = 5·g'''. On the 0.5 mm rows of the 3D raster (g''' = 0.0039 /mm²) that was
// 0.020 /mm², and the jerk term q'''·v³ held the rows to 43.5 mm/s at j 5,000. Where chords of
// different lengths meet (a merged chord of 0.565 mm after a written one of 0.0628 mm on the
// circle r 20) their middles lie 2 µm and 0.025 µm inside the circle: a step sideways that the
// quintic between them pays in its third derivative. So the meeting point is moved onto the
// curve and given the curve's direction there (docs/planner.md, "CAM polylines").
#include <array>
#include <cmath>
#include <cstddef>

namespace nckit::plan_detail {

struct ChainMidState {
    std::array<double, 3> offset{};  //!< mm, from the line's middle to the curve
    std::array<double, 3> d1{};      //!< unit direction dq/ds there
    std::array<double, 3> d2{};      //!< curvature vector d²q/ds², normal to d1 (1/mm)
};

//! At the middle of a line of length `line_mm` in direction `line_d1`, between the chord
//! directions `before_d1` (the line before, whose middle lies `before_mm` back along the chain)
//! and `after_d1` (the line after, `after_mm` on): the curvature g'' = (after − before) /
//! (before_mm + after_mm) without its part along the direction (|q'| stays 1 to first order, so
//! the quintics meeting there keep their parameter speed), the point of the curve at −h²·g''/8
//! from the middle, and the direction there, chord − h²·g'''/24, with g''' from the second
//! difference of the three directions. A straight chain keeps its line's middle and direction;
//! a circle of equal chords its chords' directions (a circle's g''' lies along its tangent).
//! The chords turn by more than chain_state_max_turn (the length of the difference of their unit
//! directions, about the angle; chain_smoother.hpp's corner), or the direction would turn by more
//! than chain_state_max_correction: a corner or a zig-zag, which samples no smooth curve. There
//! the line's middle and direction stay, with the curvature of the turn between the neighbours:
//! moving the meeting point would only make the transitions' tolerance checks fail (each failure
//! another build). On a smooth curve the correction is h²·g'''/24 (4e-5 rad on the raster's
//! rows); on the zig-zag of `BM_PlannerZigZagSCurve` (0.3 rad at every vertex) about 0.025 rad.
inline constexpr double chain_state_max_turn = 0.25;
inline constexpr double chain_state_max_correction = 1e-3;

[[nodiscard]] inline ChainMidState chain_mid_state(const std::array<double, 3>& before_d1, double before_mm,
                                                   const std::array<double, 3>& line_d1, double line_mm,
                                                   const std::array<double, 3>& after_d1, double after_mm) {
    ChainMidState s;
    const double spacing = 0.5 * (before_mm + after_mm);
    const double correction = -line_mm * line_mm / 24.0;
    double turn_before2 = 0;
    double turn_after2 = 0;
    double moved2 = 0;
    double norm2 = 0;
    double same_way = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        same_way += (line_d1[i] - before_d1[i]) * (after_d1[i] - line_d1[i]);
        turn_before2 += (line_d1[i] - before_d1[i]) * (line_d1[i] - before_d1[i]);
        turn_after2 += (after_d1[i] - line_d1[i]) * (after_d1[i] - line_d1[i]);
        const double third =
            ((after_d1[i] - line_d1[i]) / after_mm - (line_d1[i] - before_d1[i]) / before_mm) / spacing;
        s.d1[i] = line_d1[i] + correction * third;
        moved2 += correction * third * correction * third;
        norm2 += s.d1[i] * s.d1[i];
    }
    constexpr double most2 = chain_state_max_turn * chain_state_max_turn;
    constexpr double moved_most2 = chain_state_max_correction * chain_state_max_correction;
    if (turn_before2 > most2 || turn_after2 > most2 || (!(same_way > 0) && moved2 > moved_most2)) {
        for (std::size_t i = 0; i < 3; ++i) {
            s.d1[i] = line_d1[i];
            s.d2[i] = (after_d1[i] - before_d1[i]) / (before_mm + after_mm);
        }
        return s;
    }
    const double inv = 1.0 / std::sqrt(norm2);
    double along = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        s.d1[i] *= inv;
        s.d2[i] = (after_d1[i] - before_d1[i]) / (before_mm + after_mm);
        along += s.d2[i] * s.d1[i];
    }
    for (std::size_t i = 0; i < 3; ++i) {
        s.d2[i] -= along * s.d1[i];
        s.offset[i] = -line_mm * line_mm / 8.0 * s.d2[i];
    }
    return s;
}

//! A unit direction and the curvature vector normal to it.
struct DirectionState {
    std::array<double, 3> d1{};
    std::array<double, 3> d2{};
};

//! The state ds along from direction `d1` on a curve of curvature vector `curvature`: the
//! direction turned on by ds·curvature (made unit), and the curvature without its part along
//! it. A chain's first and last lines end at rest in this state (pending_motion.cpp).
[[nodiscard]] inline DirectionState turned_state(const std::array<double, 3>& d1,
                                                 const std::array<double, 3>& curvature, double ds) {
    DirectionState s;
    double norm2 = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        s.d1[i] = d1[i] + ds * curvature[i];
        norm2 += s.d1[i] * s.d1[i];
    }
    double along = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        s.d1[i] /= std::sqrt(norm2);
        along += curvature[i] * s.d1[i];
    }
    for (std::size_t i = 0; i < 3; ++i) s.d2[i] = curvature[i] - along * s.d1[i];
    return s;
}

}  // namespace nckit::plan_detail
