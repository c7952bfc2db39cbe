#pragma once
// An S-curve whose jerk differs between the ends of its speed changes and their middle. On a
// curved path the axes' jerk pays for the turning, v³·q''' and 3·q''·v·s̈, besides the path's
// own q'·s⃛: on an arc between two slow joins the turning takes most of the jerk near the
// arc's top speed, little near the joins. One jerk for the whole profile must be the one the
// top allows; a bell that starts and ends its speed changes with a high jerk ("outer") and
// rounds its top with a lower one ("inner") follows the speed the arc allows more closely
// (docs/planner.md, "Bells: speed changes with two jerks").
#include "nckit/plan/profile.hpp"

namespace nckit::plan_detail {

//! Rates of a bell: the acceleration, the jerk where a speed change leaves or reaches the end
//! speeds, the jerk where it reaches or leaves its top speed.
struct BellRates {
    double max_acceleration = 0;  //!< mm/s²
    double outer_jerk = 0;        //!< mm/s³
    double inner_jerk = 0;        //!< mm/s³
};

//! The fastest bell over `distance` from v_start to v_end (both kept exactly, a = 0 at both
//! ends) with a top speed of at most v_top mm/s: rise with jerk +outer, constant
//! acceleration, -inner; cruise at v_top if there is room; fall with -inner, constant
//! deceleration, +outer. False when even the lowest top (the higher end speed) needs more than
//! `distance`.
[[nodiscard]] bool bell_profile(double distance, double v_start, double v_end, double v_top, const BellRates& rates,
                                Profile& out);

}  // namespace nckit::plan_detail
