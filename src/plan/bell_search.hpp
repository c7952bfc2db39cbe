#pragma once
// The fastest bell (bell_profile.hpp) over a stretch of runs that holds curved pieces: a speed
// change out of a slow join and back into the next one, with the acceleration and the two
// jerks that the pieces' axes allow along it (docs/planner.md, "Bells: speed changes with two
// jerks").
#include <vector>

#include "cruise_raise.hpp"
#include "nckit/plan/profile.hpp"

namespace nckit::plan_detail {

//! Where the search starts: the rates of the runs (their widest acceleration and jerk) and the
//! highest speed any of them allows.
struct BellSeed {
    double acceleration = 0;  //!< mm/s²
    double jerk = 0;          //!< mm/s³
    double max_velocity = 0;  //!< mm/s
};

//! The fastest bell over `distance` from v_start to v_end (both kept exactly) that
//! profile_keeps_pieces accepts on `spans`; false when there is none or no span is curved.
//! A pattern search over the acceleration and the two jerks (multiplying each by a factor,
//! halving the factor's exponent when no step gains), each with the highest top speed that
//! fits (bisection): at most max_bell_rates rate sets are tried.
[[nodiscard]] bool fastest_bell(double distance, double v_start, double v_end, const BellSeed& seed,
                                const std::vector<CheckedSpan>& spans, Profile& out);

//! The most rate sets one search tries.
inline constexpr int max_bell_rates = 40;

}  // namespace nckit::plan_detail
