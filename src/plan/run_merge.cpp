#include "run_merge.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace nckit::plan_detail {

namespace {

//! Shares of the widest rates tried, fastest first (never below the tightest rates).
constexpr std::array<double, 6> rate_levels = {2.0, 1.5, 1.0, 0.7, 0.5, 0.35};
//! Top speeds tried per level: the highest, then a bisection.
constexpr int top_steps = 7;

}  // namespace

int end_direction(const Profile& profile) {
    if (profile.phase_count == 0) return 0;
    const double a = profile.phases[static_cast<std::size_t>(profile.phase_count - 1)].acceleration;
    return a > 0 ? 1 : (a < 0 ? -1 : 0);
}

int start_direction(const Profile& profile) {
    if (profile.phase_count == 0) return 0;
    const double j = profile.phases[0].jerk;
    return j > 0 ? 1 : (j < 0 ? -1 : 0);
}

bool merged_profile(double distance, double v_start, double v_end, const MergeRates& rates,
                    const std::vector<CheckedSpan>& spans, Profile& out) {
    bool found = false;
    const double floor_speed = std::max(v_start, v_end);
    double last_a = -1;
    for (const double level : rate_levels) {
        if (level > 1.0 && !rates.curved) continue;
        ProfileLimits limits;
        limits.max_acceleration = std::max(rates.tightest.max_acceleration, level * rates.widest.max_acceleration);
        limits.max_jerk = std::max(rates.tightest.max_jerk, level * rates.widest.max_jerk);
        if (limits.max_acceleration == last_a) break;  // already at the tightest rates
        last_a = limits.max_acceleration;
        double lo = floor_speed;
        double hi = std::max(floor_speed, rates.widest.max_velocity);
        for (int k = 0; k < top_steps; ++k) {
            // The highest top first, then (between two moving ends) no rise at all: where neither
            // fits, no top between does.
            const bool no_rise = k == 1 && lo > 0;
            const double top = k == 0 ? hi : (no_rise ? lo : 0.5 * (lo + hi));
            limits.max_velocity = top;
            const Profile candidate = plan_profile(distance, v_start, v_end, limits, ProfileKind::scurve);
            const bool same_ends = candidate.start_velocity == v_start && candidate.end_velocity == v_end;
            if (same_ends && profile_keeps_pieces(candidate, spans)) {
                if (!found || candidate.duration_s() < out.duration_s()) out = candidate;
                found = true;
                if (k == 0) break;
                lo = top;
            } else if (no_rise) {
                break;
            } else {
                hi = top;
            }
            if (!(hi > lo * (1.0 + 1e-4))) break;
        }
        // Lower rates with the same top speed are slower: the first level that fits is the one.
        if (found) break;
    }
    return found;
}

}  // namespace nckit::plan_detail
