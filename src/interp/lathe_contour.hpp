#pragma once
// The finishing shape of a lathe cycle (the moves of its P-Q blocks) as geometry: where it
// reaches a cutting level, whether it runs one way only, and the shape moved by an allowance.
#include <optional>
#include <string>
#include <vector>

#include "nckit/interp/move.hpp"

namespace nckit::interp {

//! G71 cuts in levels of X and runs along Z; G72 cuts in levels of Z and runs along X.
struct ContourAxes {
    Axis depth;
    Axis length;
};

//! The moves of a cycle's blocks N p .. N q, run from the cycle's start point.
struct PqShape {
    std::vector<Move> moves;
    std::size_t approach_moves = 0;  //!< how many of `moves` the P block made
    std::string p_letters;           //!< the letters of the P block's words, as written
};

//! What the roughing levels of G71/G72 need: A (the start point), the direction from the shape
//! towards A (`up`, +1 or -1 along `axes.depth`), the cutting direction (`along`), the levels.
struct RoughLevels {
    ContourAxes axes;
    double up = 1;
    double along = 1;
    double start_depth_mm = 0;
    double start_length_mm = 0;
    double depth_of_cut_mm = 0;
    double escape_mm = 0;
    int levels = 0;
    bool rapid_infeed = true;  //!< the P block is a G0 (a G1 feeds in)
};

//! The end points of a Line or Arc (nothing for other moves).
[[nodiscard]] std::optional<AxisVector> move_start(const Move& move);
[[nodiscard]] std::optional<AxisVector> move_end(const Move& move);

//! The element moved by `shift` (a Line or Arc; anything else unchanged).
[[nodiscard]] Move shifted(const Move& move, const AxisVector& shift);

//! Where along `axes.length` the element first reaches depth `level` (running from its start),
//! or nothing when it does not reach it.
[[nodiscard]] std::optional<double> level_crossing(const Move& element, ContourAxes axes, double level);

//! Every place along `axes.length` where the element crosses or touches depth `level` (a line
//! along the level: its two ends), in the element's running order.
[[nodiscard]] std::vector<double> level_crossings(const Move& element, ContourAxes axes, double level);

//! The depth of a shape that runs one way along `axes.length` at `length` (the first element
//! that reaches it), or nothing when the shape does not reach it.
[[nodiscard]] std::optional<double> depth_at(const std::vector<Move>& shape, ContourAxes axes, double length);

//! Lowest and highest value of `axis` along the element (arcs bulge past their ends).
struct Extent {
    double low = 0;
    double high = 0;
};
[[nodiscard]] Extent extent_along(const Move& element, Axis axis);

}  // namespace nckit::interp
