#include "bell_search.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "bell_profile.hpp"

namespace nckit::plan_detail {

namespace {

//! Top speeds tried per rate set, and the relative width at which their bisection stops.
constexpr int top_steps = 7;
constexpr double top_resolution = 1e-3;
//! How far from the last rate set's top the bracket of the next one starts (a pattern step
//! moves the top by a few per cent).
constexpr double hint_step = 0.04;
//! The first factor of the pattern search, and how often it is halved (in its exponent).
constexpr double first_factor = 1.6;
constexpr int factor_halvings = 3;

bool any_curved(const std::vector<CheckedSpan>& spans) {
    return std::any_of(spans.begin(), spans.end(),
                       [](const CheckedSpan& s) { return s.check != nullptr && s.check->count > 0; });
}

//! The fastest bell with these rates, the highest top that fits; +inf when none does.
//! `top_hint` (mm/s, 0 when none) is the top of the last rate set: the search brackets the
//! new top around it, and leaves the new top there.
double best_with(double distance, double v_start, double v_end, double v_max, const BellRates& rates,
                 const std::vector<CheckedSpan>& spans, double& top_hint, FailedSpan& failed, Profile& out) {
    const double floor_speed = std::max(v_start, v_end);
    const double ceiling = std::max(floor_speed, v_max);
    double best_s = std::numeric_limits<double>::infinity();
    int tried = 0;
    const auto fits = [&](double top) {
        ++tried;
        Profile candidate;
        if (!bell_profile(distance, v_start, v_end, top, rates, candidate) ||
            !profile_keeps_pieces(candidate, spans, &failed)) {
            return false;
        }
        if (candidate.duration_s() < best_s) {
            best_s = candidate.duration_s();
            out = candidate;
        }
        return true;
    };
    // A bracket [lo, hi] with lo fitting (or the floor, not tried yet) and hi not fitting.
    double lo = floor_speed;
    double hi = ceiling;
    bool lo_fits = false;
    if (top_hint > floor_speed && top_hint < ceiling) {
        if (fits(top_hint)) {
            lo = top_hint;
            lo_fits = true;
            const double up = std::min(ceiling, top_hint * (1.0 + hint_step));
            if (fits(up)) {
                lo = up;
                if (up == ceiling) hi = up;
            } else {
                hi = up;
            }
        } else {
            hi = top_hint;
            const double down = std::max(floor_speed, top_hint * (1.0 - hint_step));
            if (fits(down)) {
                lo = down;
                lo_fits = true;
            } else {
                hi = down;
            }
        }
    } else if (fits(ceiling)) {
        lo = hi = ceiling;
        lo_fits = true;
    }
    if (!lo_fits && lo < hi) {
        // Not even the lowest top (no rise at all) fits: none does.
        if (!fits(floor_speed)) return best_s;
        lo_fits = true;
    }
    while (lo_fits && hi > lo * (1.0 + top_resolution) && tried < top_steps) {
        const double mid = 0.5 * (lo + hi);
        (fits(mid) ? lo : hi) = mid;
    }
    if (std::isfinite(best_s)) top_hint = lo;
    return best_s;
}

}  // namespace

bool fastest_bell(double distance, double v_start, double v_end, const BellSeed& seed,
                  const std::vector<CheckedSpan>& spans, Profile& out, BellRates& rates) {
    if (!any_curved(spans) || !(seed.acceleration > 0) || !(seed.jerk > 0)) return false;
    // Coordinates: acceleration, end jerk, top jerk of the rise, then of the fall.
    using Rates = std::array<double, 6>;
    const auto rates_of = [](const Rates& p) { return BellRates{{p[0], p[1], p[2]}, {p[3], p[4], p[5]}}; };
    const auto coordinates_of = [](const BellRates& r) {
        return Rates{r.rise.max_acceleration, r.rise.end_jerk, r.rise.top_jerk,
                     r.fall.max_acceleration, r.fall.end_jerk, r.fall.top_jerk};
    };
    double top_hint = 0;
    FailedSpan failed;  // shared by all candidates: most fail where the one before did
    Rates x{};
    double best_s = std::numeric_limits<double>::infinity();
    int tried = 0;
    // Plans the bell of rate set y and takes it when it is faster than the best by `margin`.
    const auto take_if_faster = [&](const Rates& y, double margin) {
        ++tried;
        double hint = top_hint;
        Profile candidate;
        const double s =
            best_with(distance, v_start, v_end, seed.max_velocity, rates_of(y), spans, hint, failed, candidate);
        if (!(s < best_s * margin)) return false;
        best_s = s;
        top_hint = hint;
        x = y;
        out = candidate;
        return true;
    };
    // Three starts, the fastest taken: the runs' tightest rates (which every piece allows for
    // any profile), their widest (what a line allows), and twice their widest acceleration and
    // end jerk (the shares of curved pieces leave room for the turning everywhere; a bell needs
    // it only where the path turns fast).
    const double a = seed.acceleration;
    const double j = seed.jerk;
    const double ta = seed.tight_acceleration > 0 ? seed.tight_acceleration : a;
    const double tj = seed.tight_jerk > 0 ? seed.tight_jerk : j;
    const std::array<Rates, 3> starts = {Rates{ta, tj, tj, ta, tj, tj}, Rates{a, j, j, a, j, j},
                                         Rates{2 * a, 2 * j, j, 2 * a, 2 * j, j}};
    x = starts[0];  // searched from when no start fits
    // The rates of the last bells taken first: on a chain of like arcs one of them is near the
    // optimum, and the pattern search then mostly refines it.
    for (const BellRates& r : seed.recent) {
        if (!(r.rise.max_acceleration > 0 && r.fall.max_acceleration > 0)) continue;
        take_if_faster(coordinates_of(r), 1.0);
    }
    for (const Rates& start : starts) take_if_faster(start, 1.0);
    // First both sides together (directions 0-2), then each side on its own (3-8).
    for (int stage = 0; stage < 2; ++stage) {
        const std::size_t first_d = stage == 0 ? 0 : 3;
        const std::size_t end_d = stage == 0 ? 3 : 9;
        const int stage_budget = stage == 0 ? max_bell_rates_together : max_bell_rates;
        double factor = first_factor;
        for (int halving = 0; halving <= factor_halvings && tried < stage_budget; ++halving) {
            bool moved = true;
            while (moved && tried < stage_budget) {
                moved = false;
                for (std::size_t d = first_d; d < end_d && tried < stage_budget; ++d) {
                    for (const double f : {factor, 1.0 / factor}) {
                        Rates y = x;
                        if (d < 3) {
                            y[d] *= f;
                            y[d + 3] *= f;
                        } else {
                            y[d - 3] *= f;
                        }
                        if (take_if_faster(y, 1.0 - 1e-6)) {
                            moved = true;
                            break;
                        }
                    }
                }
            }
            factor = std::sqrt(factor);
        }
    }
    if (std::isfinite(best_s)) rates = rates_of(x);
    return std::isfinite(best_s);
}

}  // namespace nckit::plan_detail
