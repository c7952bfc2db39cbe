#pragma once
// The fastest bell (bell_profile.hpp) over a stretch of runs that holds curved pieces: a speed
// change out of a slow join and back into the next one, with the acceleration and the two
// jerks that the pieces' axes allow along it (docs/planner.md, "Bells: speed changes with two
// jerks").
#include <vector>

#include "cruise_raise.hpp"
#include "nckit/plan/profile.hpp"

namespace nckit::plan_detail {

//! Where the search starts: the rates of the runs (their widest and tightest acceleration and
//! jerk) and the highest speed any of them allows.
struct BellSeed {
    double acceleration = 0;        //!< mm/s², the widest of the runs'
    double jerk = 0;                //!< mm/s³, the widest of the runs'
    double tight_acceleration = 0;  //!< mm/s², the tightest of the runs'
    double tight_jerk = 0;          //!< mm/s³, the tightest of the runs'
    double max_velocity = 0;        //!< mm/s
};

//! The fastest bell over `distance` from v_start to v_end (both kept exactly) that
//! profile_keeps_pieces accepts on `spans`; false when there is none or no span is curved.
//! A pattern search over the acceleration and the two jerks of the rise and of the fall
//! (multiplying a rate by a factor, first on both sides together, then on one; the factor's
//! exponent halved when no step gains), each rate set with the highest top speed that fits
//! (bisection, started around the last set's top): at most max_bell_rates rate sets.
[[nodiscard]] bool fastest_bell(double distance, double v_start, double v_end, const BellSeed& seed,
                                const std::vector<CheckedSpan>& spans, Profile& out);

//! The most rate sets one search tries, and of them the most with both sides moved together.
//! Measured on the 100 semicircles at j 5,000 (cycle, planning time of the whole program):
//! 30/45 40.12 s in 0.68 s, 40/60 39.98 s in 0.74 s, 60/90 39.97 s in 1.05 s; the slot at F6000
//! 1.893, 1.888, 1.885 s.
inline constexpr int max_bell_rates = 60;
inline constexpr int max_bell_rates_together = 40;

}  // namespace nckit::plan_detail
