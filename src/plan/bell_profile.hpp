#pragma once
// An S-curve whose jerk differs between the ends of its speed changes and their middle, and
// whose rise and fall have rates of their own. On a curved path the axes' jerk pays for the
// turning, q'''·ṡ³ and 3·q''·ṡ·s̈, besides the path's own q'·s⃛: on an arc between two slow
// joins the turning takes most of the jerk near the arc's top speed, little near the joins; a
// line braking into an arc has all of its axes' rates on the line and few left in the arc. One
// acceleration and jerk for a whole profile must be the ones its tightest place allows; a bell
// changes its speed with a high jerk where the path allows it and rounds the rest with a lower
// one (docs/planner.md, "Bells: speed changes with two jerks").
#include "nckit/plan/profile.hpp"

namespace nckit::plan_detail {

//! Rates of one speed change of a bell: its acceleration, the jerk at the bell's end speed (where
//! the change leaves the start speed or reaches the end speed) and the jerk at its top speed.
struct BellSide {
    double max_acceleration = 0;  //!< mm/s²
    double end_jerk = 0;          //!< mm/s³
    double top_jerk = 0;          //!< mm/s³
};

//! The rates of a bell's rise and fall.
struct BellRates {
    BellSide rise;
    BellSide fall;
};

//! The fastest bell over `distance` from v_start to v_end (both kept exactly, a = 0 at both
//! ends) with a top speed of at most v_top mm/s: rise with jerk +rise.end_jerk, constant
//! acceleration, -rise.top_jerk; cruise at v_top if there is room; fall with -fall.top_jerk,
//! constant deceleration, +fall.end_jerk. False when even the lowest top (the higher end speed)
//! needs more than `distance`.
[[nodiscard]] bool bell_profile(double distance, double v_start, double v_end, double v_top, const BellRates& rates,
                                Profile& out);

}  // namespace nckit::plan_detail
