#pragma once
// The planner's output: time-parameterised pieces of path, dwells and I/O events, in order.
#include <cstdint>
#include <vector>

#include "nckit/core/axes.hpp"
#include "nckit/core/source_location.hpp"
#include "nckit/interp/move.hpp"
#include "nckit/plan/path_segment.hpp"
#include "nckit/plan/profile.hpp"

namespace nckit {

enum class PieceKind {
    motion,  //!< the profile moves along the segment
    dwell,   //!< at rest at the segment's start for duration_s
    io       //!< zero duration: `io` happens here, at speed unless it waits
};

struct TrajectoryPiece {
    PieceKind kind = PieceKind::motion;
    PathSegment segment;  //!< the path; a zero-length line at the place for dwell and io
    //! s(t) of the run of tangent segments this one belongs to (one profile over several
    //! segments keeps the acceleration going through their junctions); empty for dwell and io.
    Profile profile;
    double profile_offset_s = 0;        //!< s, the profile's time at this piece's start
    double profile_offset_mm = 0;       //!< mm, the profile's position at the segment's start (s = 0)
    bool ends_profile = true;           //!< the last piece of its run: ends exactly at the profile's end
    double start_time_s = 0;            //!< s from the trajectory start
    double duration_s = 0;              //!< s: the profile's duration, the dwell time, or 0
    SourceLocation where;               //!< the block that made it (for blends: the block of the corner)
    std::int64_t sequence_number = -1;  //!< the block's N number, -1 when none
    Io io;                              //!< io pieces only
    bool blend = false;                 //!< motion inserted by the planner to round a corner
    //! The path of the same move as the motion piece before it goes on here (an arc, or under a
    //! jerk limit a transition next to an arc, is planned in pieces, docs/planner.md "Speed along
    //! an arc"): not a new move, no junction.
    bool continues_move = false;
    bool waits_for_index = false;  //!< a dwell until the spindle's index pulse (before G32/G33)
    double index_angle_deg = 0;    //!< waits_for_index: the angle past the pulse it waits for (Q)
};

//! The axes' state at one time, exact (from the piecewise-cubic profile and the segment's
//! analytic derivatives).
struct TrajectorySample {
    double t = 0;                  //!< s
    AxisVector position;           //!< mm, deg
    AxisVector velocity;           //!< mm/s, deg/s
    AxisVector acceleration;       //!< mm/s²
    AxisVector jerk;               //!< mm/s³
    double path_velocity = 0;      //!< ṡ, units of s per second
    double path_acceleration = 0;  //!< s̈
};

//! The state at time t (s, trajectory time), clamped into the piece:
//! v = p'ṡ, a = p''ṡ² + p's̈, j = p'''ṡ³ + 3p''ṡs̈ + p's⃛.
[[nodiscard]] TrajectorySample sample(const TrajectoryPiece& piece, double t);

//! A whole planned program (plan_program's result).
struct Trajectory {
    std::vector<TrajectoryPiece> pieces;

    //! s, the cycle time.
    [[nodiscard]] double duration_s() const;
    //! The state at t; at a piece boundary the later piece's.
    [[nodiscard]] TrajectorySample sample(double t) const;
};

}  // namespace nckit
