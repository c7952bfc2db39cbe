#include "bell_search.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "bell_profile.hpp"

namespace nckit::plan_detail {

namespace {

//! Top speeds tried per rate set: the highest, the lowest (no rise), then a bisection.
constexpr int top_steps = 8;
//! The first factor of the pattern search, and how often it is halved (in its exponent).
constexpr double first_factor = 1.6;
constexpr int factor_halvings = 3;

bool any_curved(const std::vector<CheckedSpan>& spans) {
    return std::any_of(spans.begin(), spans.end(),
                       [](const CheckedSpan& s) { return s.check != nullptr && s.check->count > 0; });
}

//! The fastest bell with these rates, the highest top that fits; +inf when none does.
double best_with(double distance, double v_start, double v_end, double v_max, const BellRates& rates,
                 const std::vector<CheckedSpan>& spans, Profile& out) {
    double best_s = std::numeric_limits<double>::infinity();
    double lo = std::max(v_start, v_end);
    double hi = std::max(lo, v_max);
    for (int k = 0; k < top_steps; ++k) {
        const double top = k == 0 ? hi : (k == 1 ? lo : 0.5 * (lo + hi));
        Profile candidate;
        if (bell_profile(distance, v_start, v_end, top, rates, candidate) && profile_keeps_pieces(candidate, spans)) {
            if (candidate.duration_s() < best_s) {
                best_s = candidate.duration_s();
                out = candidate;
            }
            if (k == 0) break;  // the highest top fits: nothing between is faster
            lo = top;
        } else if (k == 1) {
            break;  // not even the lowest top fits: none does
        } else if (k > 1) {
            hi = top;
        }
        if (k >= 1 && !(hi > lo * (1.0 + 1e-4))) break;
    }
    return best_s;
}

}  // namespace

bool fastest_bell(double distance, double v_start, double v_end, const BellSeed& seed,
                  const std::vector<CheckedSpan>& spans, Profile& out) {
    if (!any_curved(spans) || !(seed.acceleration > 0) || !(seed.jerk > 0)) return false;
    // Start where the measurements found most bells: twice the runs' acceleration and outer jerk
    // (their shares left room for the turning everywhere; a bell only needs it where it turns
    // fast), the inner jerk at the runs' own.
    std::array<double, 3> x = {2.0 * seed.acceleration, 2.0 * seed.jerk, seed.jerk};
    const auto rates_of = [](const std::array<double, 3>& p) { return BellRates{p[0], p[1], p[2]}; };
    int tried = 1;
    double best_s = best_with(distance, v_start, v_end, seed.max_velocity, rates_of(x), spans, out);
    double factor = first_factor;
    for (int halving = 0; halving <= factor_halvings && tried < max_bell_rates; ++halving) {
        bool moved = true;
        while (moved && tried < max_bell_rates) {
            moved = false;
            for (std::size_t i = 0; i < x.size() && tried < max_bell_rates; ++i) {
                for (const double f : {factor, 1.0 / factor}) {
                    std::array<double, 3> y = x;
                    y[i] *= f;
                    Profile candidate;
                    ++tried;
                    const double s =
                        best_with(distance, v_start, v_end, seed.max_velocity, rates_of(y), spans, candidate);
                    if (s < best_s * (1.0 - 1e-6)) {
                        best_s = s;
                        out = candidate;
                        x = y;
                        moved = true;
                        break;
                    }
                }
            }
        }
        factor = std::sqrt(factor);
    }
    return std::isfinite(best_s);
}

}  // namespace nckit::plan_detail
