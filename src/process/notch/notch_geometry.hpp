#pragma once
// Geometry the notch rewrite needs: move paths as polylines and the distance between two
// segments.
#include <optional>
#include <vector>

#include "nckit/core/machine.hpp"
#include "nckit/interp/move.hpp"
#include "nckit/plan/path_segment.hpp"
#include "nckit/plan/profile.hpp"

namespace nckit::notch_detail {

//! Path length of a straight move as the planner measures it: XYZ, else UVW, else ABC.
[[nodiscard]] inline double measured_length(const AxisVector& from, const AxisVector& to) {
    return nckit::measured_length(to - from);
}

//! The motion's path as points joined by straight chords, every chord within tolerance_mm of
//! an arc; empty for moves that are not motions.
[[nodiscard]] std::vector<AxisVector> path_polyline(const Move& move, double tolerance_mm);

//! Smallest distance between segments [p0, p1] and [q0, q1] over all nine axes.
[[nodiscard]] double segment_distance(const AxisVector& p0, const AxisVector& p1, const AxisVector& q0,
                                      const AxisVector& q1);

[[nodiscard]] double dot(const AxisVector& a, const AxisVector& b);
[[nodiscard]] AxisVector scaled(const AxisVector& a, double k);

//! The start and end of a motion (Line, Arc, SyncMove); nothing for other moves.
struct Ends {
    AxisVector from;
    AxisVector to;
};
[[nodiscard]] std::optional<Ends> motion_ends(const Move& move);

}  // namespace nckit::notch_detail
