#pragma once
// Totals over a move stream: how many of each kind, how far, where. Used by `nckit moves
// --summary` and the demo; computed as the moves stream past, so it costs no memory.
#include <cstdint>

#include "nckit/core/axes.hpp"
#include "nckit/interp/move.hpp"

namespace nckit {

struct MoveSummary {
    std::int64_t rapids = 0;
    std::int64_t lines = 0;
    std::int64_t arcs = 0;
    std::int64_t syncs = 0;
    std::int64_t dwells = 0;
    std::int64_t ios = 0;
    double cutting_length_mm = 0;  //!< path length of G1, G2/G3 and G33 moves (X Y Z), mm
    double rapid_length_mm = 0;    //!< path length of G0 moves (X Y Z), mm
    double dwell_s = 0;            //!< total programmed dwell, s
    double feed_time_s = 0;        //!< cutting length / programmed feed: a lower bound of cycle time, s
    AxisVector low;                //!< smallest coordinate reached per axis (whole arcs included)
    AxisVector high;               //!< largest coordinate reached per axis
    bool any_motion = false;

    void add(const Move& move);
};

//! Length of an arc or helix in X Y Z, mm.
[[nodiscard]] double arc_length_mm(const Arc& arc);

}  // namespace nckit
