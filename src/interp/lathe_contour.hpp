#pragma once
// The finishing shape of a lathe cycle (the moves of its P-Q blocks) as geometry: where it
// reaches a cutting level, whether it runs one way only, and the shape moved by an allowance.
#include <optional>
#include <vector>

#include "nckit/interp/move.hpp"

namespace nckit::interp {

//! G71 cuts in levels of X and runs along Z; G72 cuts in levels of Z and runs along X.
struct ContourAxes {
    Axis depth;
    Axis length;
};

//! The end points of a Line or Arc (nothing for other moves).
[[nodiscard]] std::optional<AxisVector> move_start(const Move& move);
[[nodiscard]] std::optional<AxisVector> move_end(const Move& move);

//! The element moved by `shift` (a Line or Arc; anything else unchanged).
[[nodiscard]] Move shifted(const Move& move, const AxisVector& shift);

//! Where along `axes.length` the element first reaches depth `level` (running from its start),
//! or nothing when it does not reach it.
[[nodiscard]] std::optional<double> level_crossing(const Move& element, ContourAxes axes, double level);

//! Lowest and highest value of `axis` along the element (arcs bulge past their ends).
struct Extent {
    double low = 0;
    double high = 0;
};
[[nodiscard]] Extent extent_along(const Move& element, Axis axis);

}  // namespace nckit::interp
