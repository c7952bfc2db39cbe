// The look-ahead's commit of several runs as one profile: merged S-curves (run_merge.hpp), runs
// of curved pieces raised (cruise_raise.hpp) and bells (bell_search.hpp); docs/planner.md,
// "Speed changes across runs" and "Bells: speed changes with two jerks".
#include <algorithm>

#include "bell_search.hpp"
#include "lookahead.hpp"

namespace nckit::plan_detail {

namespace {

//! S-curve runs committed as one profile at most (run_merge.hpp), and how many runs past the
//! last merge that paid off are still tried.
constexpr std::size_t max_merged_runs = 32;
constexpr std::size_t merge_patience = 2;
//! The most segments a bell is searched over: each rate set walks them all, so this bounds the
//! search's cost per commit (a semicircle and its transitions are about 200).
constexpr std::size_t max_bell_spans = 1024;

}  // namespace

Profile Lookahead::run_profile(const WindowRun& r, std::size_t first, double v_start, double v_end) {
    const Profile profile = plan_profile(r.length, v_start, v_end, r.limits, kind_);
    // A run of curved pieces may go faster where its profile keeps them (cruise_raise.hpp).
    if (kind_ != ProfileKind::scurve || !(r.cruise_velocity > r.limits.max_velocity * (1.0 + 1e-4))) return profile;
    spans_.clear();
    for (std::size_t i = first; i < first + r.count; ++i) {
        spans_.push_back({segments_[i].path.length, &segments_[i].check});
    }
    return raised_profile(profile, r.length, r.limits, r.cruise_velocity, spans_);
}

bool Lookahead::append_merge_spans(std::size_t first, std::size_t count) {
    for (std::size_t i = first; i < first + count; ++i) {
        const WindowSegment& s = segments_[i];
        // A thread runs at the spindle's speed: a speed change spread over it would cut the
        // pitch wrong, so thread runs keep their own profiles.
        if (!mergeable(s.check) || s.spindle_locked) return false;
        merge_spans_.push_back({s.path.length, &s.check, &s.limits});
    }
    return true;
}

std::size_t Lookahead::merge_following(Profile& profile) {
    const WindowRun& front = runs_.front();
    merge_spans_.clear();
    if (!append_merge_spans(0, front.count)) return 1;
    MergeRates rates{front.limits, front.limits};
    rates.widest.max_velocity = std::max(front.limits.max_velocity, front.cruise_velocity);
    MergeRates front_rates = rates;
    front_rates.curved = front.cruise_velocity > 0;
    double plan_s = profile.duration_s();  // the best plan of the runs taken so far and the ones after
    double v = profile.end_velocity;
    double length = front.length;
    std::size_t first = front.count;  // segment index of run m
    std::size_t taken = 1;
    BellExtent widest{1, front.length, v, merge_spans_.size(), plan_s};
    BellExtent taken_extent = widest;
    for (std::size_t m = 1; m < runs_.size() && m < max_merged_runs; ++m) {
        // Not across a stop or an event, and only up to an end speed the passes have fixed.
        if (!(runs_[m - 1].junction_max > 0) || !segments_[first - 1].after.empty()) break;
        const WindowRun& r = runs_[m];
        // Where run m starts by holding its speed, the boundary's a = 0 costs nothing. Checked
        // first without planning it (entered at its limit, and no raise can lift it), and for
        // runs without curved pieces after a block that ends holding its own limit (a corner's
        // transition between lines): most boundaries of a program of corners end here.
        const bool raisable = r.cruise_velocity > r.limits.max_velocity * (1.0 + 1e-4);
        if (m == taken && !raisable && v >= r.limits.max_velocity * (1.0 - 1e-9)) break;
        if (m == taken && !(r.cruise_velocity > 0) && end_direction(profile) == 0) break;
        double v_end = 0;
        if (!end_speed(r, v, v_end)) break;
        const Profile alone = run_profile(r, first, v, v_end);
        if (m == taken && start_direction(alone) == 0) break;
        plan_s += alone.duration_s();
        v = alone.end_velocity;
        if (!append_merge_spans(first, r.count)) break;
        first += r.count;
        length += r.length;
        ProfileLimits& w = rates.widest;
        w.max_velocity = std::max({w.max_velocity, r.limits.max_velocity, r.cruise_velocity});
        w.max_acceleration = std::max(w.max_acceleration, r.limits.max_acceleration);
        w.max_jerk = std::max(w.max_jerk, r.limits.max_jerk);
        ProfileLimits& t = rates.tightest;
        t.max_acceleration = std::min(t.max_acceleration, r.limits.max_acceleration);
        t.max_jerk = std::min(t.max_jerk, r.limits.max_jerk);
        Profile merged;
        if (merged_profile(length, start_speed_, v, rates, merge_spans_, merged) &&
            merged.duration_s() < plan_s * (1.0 - 1e-9)) {
            profile = merged;
            plan_s = merged.duration_s();
            taken = m + 1;
        }
        widest = {m + 1, length, v, merge_spans_.size(), plan_s};
        if (taken == m + 1) taken_extent = widest;
        if (m + 1 - taken >= merge_patience) break;
    }
    if (const std::size_t bell_runs = bell_curved_runs(profile, taken_extent, widest, rates)) return bell_runs;
    // A run of curved pieces alone: its own profile with higher rates, where its pieces allow.
    if (taken == 1 && front_rates.curved) {
        merge_spans_.resize(front.count);
        Profile faster;
        if (merged_profile(front.length, start_speed_, profile.end_velocity, front_rates, merge_spans_, faster) &&
            faster.duration_s() < profile.duration_s() * (1.0 - 1e-9)) {
            profile = faster;
        }
    }
    return taken;
}

std::size_t Lookahead::bell_curved_runs(Profile& profile, const BellExtent& taken, const BellExtent& widest,
                                        const MergeRates& rates) {
    const BellSeed seed{rates.widest.max_acceleration, rates.widest.max_jerk,     rates.tightest.max_acceleration,
                        rates.tightest.max_jerk,       rates.widest.max_velocity, recent_bell_rates_};
    // Against the plan of the widest extent: there the runs after the taken ones keep their own
    // profiles, which a bell over the taken runs leaves as they are.
    double best_gain_s = 0;
    std::size_t runs = 0;
    Profile best;
    Profile bell;
    BellRates best_rates;
    BellRates bell_rates;
    for (const BellExtent* extent : {&widest, &taken}) {
        if (extent == &taken && taken.runs == widest.runs) break;
        if (extent->span_count > max_bell_spans) continue;
        merge_spans_.resize(extent->span_count);
        if (!fastest_bell(extent->length, start_speed_, extent->v_end, seed, merge_spans_, bell, bell_rates)) continue;
        const double planned_s = extent == &taken ? profile.duration_s() : widest.plan_s;
        const double gain_s = planned_s - bell.duration_s();
        if (gain_s > best_gain_s + 1e-9 * planned_s) {
            best_gain_s = gain_s;
            best = bell;
            best_rates = bell_rates;
            runs = extent->runs;
        }
    }
    if (runs > 0) {
        profile = best;
        std::rotate(recent_bell_rates_.rbegin(), recent_bell_rates_.rbegin() + 1, recent_bell_rates_.rend());
        recent_bell_rates_[0] = best_rates;
    }
    return runs;
}

}  // namespace nckit::plan_detail
