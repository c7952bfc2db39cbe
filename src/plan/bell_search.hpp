#pragma once
// The fastest bell (bell_profile.hpp) over a stretch of runs that holds curved pieces: a speed
// change out of a slow join and back into the next one, with the acceleration and the two
// jerks that the pieces' axes allow along it (docs/planner.md, "Bells: speed changes with two
// jerks").
#include <array>
#include <vector>

#include "bell_profile.hpp"
#include "cruise_raise.hpp"
#include "nckit/plan/profile.hpp"

namespace nckit::plan_detail {

//! The rates of the last bells a look-ahead took, newest first.
using RecentBellRates = std::array<BellRates, 4>;

//! Where the search starts: the rates of the runs (their widest and tightest acceleration and
//! jerk) and the highest speed any of them allows.
struct BellSeed {
    double acceleration = 0;        //!< mm/s², the widest of the runs'
    double jerk = 0;                //!< mm/s³, the widest of the runs'
    double tight_acceleration = 0;  //!< mm/s², the tightest of the runs'
    double tight_jerk = 0;          //!< mm/s³, the tightest of the runs'
    double max_velocity = 0;        //!< mm/s
    //! The rates of the last bells the look-ahead took (all 0: none). Neighbouring stretches of a
    //! program are often alike (the arcs of a chain): started there, the search needs fewer steps.
    RecentBellRates recent{};
};

//! The fastest bell over `distance` from v_start to v_end (both kept exactly) that
//! profile_keeps_pieces accepts on `spans`; false when there is none or no span is curved.
//! A pattern search over the acceleration and the two jerks of the rise and of the fall
//! (multiplying a rate by a factor, first on both sides together, then on one; the factor's
//! exponent halved when no step gains), each rate set with the highest top speed that fits
//! (bisection, started around the last set's top): at most max_bell_rates rate sets.
[[nodiscard]] bool fastest_bell(double distance, double v_start, double v_end, const BellSeed& seed,
                                const std::vector<CheckedSpan>& spans, Profile& out, BellRates& rates);

//! The most rate sets one search tries, and of them the most with both sides moved together.
//! Measured on the 100 semicircles at j 5,000 (cycle, planning time of the whole program):
//! 30/45 40.12 s in 0.68 s, 40/60 39.98 s in 0.74 s, 60/90 39.97 s in 1.05 s; the slot at F6000
//! 1.893, 1.888, 1.885 s. Since the check lets a speed change pass above the cruise speed, with
//! the recent bells as starts: 40/60 39.342 s in 0.56 s, 60/100 39.242 s in 0.77 s, 100/150
//! 39.243 s in 0.80 s; the slot 1.895, 1.892, 1.892 s.
inline constexpr int max_bell_rates = 100;
inline constexpr int max_bell_rates_together = 60;

}  // namespace nckit::plan_detail
