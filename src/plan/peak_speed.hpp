#pragma once
// The peak speed of a profile: rise from one boundary speed, fall to the other.
#include "rates.hpp"

namespace nckit::plan_detail {

struct Peak {
    double rise_mm_s = 0;  //!< mm/s, peak speed minus the higher boundary speed (>= 0)
    double cruise_s = 0;   //!< s at the peak; > 0 only when the peak is v_max
};

//! The peak speed (as a rise above v_high) of the fastest profile from v_low to v_high or back
//! over distance_mm, v_low <= v_high <= v_max. The rise is 0 when the distance is at most
//! change_distance(v_low, v_high - v_low), that is, for an infeasible request too.
//!
//! Why a peak: in a given time, the farthest a profile can go between the two speeds is to
//! speed up as hard as the limits allow, then brake as late as possible (cruising at v_max if
//! it gets there). That distance grows with the time, so the fastest profile over d is the one
//! of that shape that covers d exactly; its distance grows strictly with the peak speed, so the
//! peak is unique.
[[nodiscard]] Peak solve_peak(double distance_mm, double v_low, double v_high, const Rates& r);

}  // namespace nckit::plan_detail
