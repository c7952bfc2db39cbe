#pragma once
// Inverses of change_distance: which speed change fits a given distance.
#include "rates.hpp"

namespace nckit::plan_detail {

//! mm/s, the speed gain dv >= 0 whose time-optimal speed-up from v covers exactly distance_mm
//! (no velocity limit). Closed form in both regimes.
[[nodiscard]] double speed_gain(double distance_mm, double v, const Rates& r);

//! Braking from v by dv covers change_distance(v - dv, dv) = mean speed x time. Unlike speeding
//! up, that is not monotone in dv for S-curves: braking further lowers the mean speed of the
//! whole braking, and near a stop that outweighs the time it adds (with the acceleration limit
//! reached, each mm/s less at the end saves a/(2j) mm). So stopping needs less distance than
//! nearly stopping: the braking distance rises from 0 to a maximum at dv = braking_peak_loss,
//! then falls to the stopping distance. (For trapezoids the maximum is the stop itself.)
[[nodiscard]] double braking_peak_loss(double v, const Rates& r);

//! mm/s, the speed loss dv in [0, braking_peak_loss] (rising side) or [braking_peak_loss, v]
//! (falling side) whose braking covers exactly distance_mm, which must lie within that side's
//! range of distances.
enum class BrakingSide { rising, falling };
[[nodiscard]] double speed_loss(double distance_mm, double v, BrakingSide side, const Rates& r);

}  // namespace nckit::plan_detail
