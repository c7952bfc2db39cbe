// The look-ahead window's incremental backward pass (which stops at the first bound that comes
// out unchanged, before the runs changed since the last pass) and its cached stop speeds give
// exactly the pieces of full passes that recompute everything.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "../../src/plan/lookahead.hpp"
#include "nckit/plan/path_segment.hpp"

namespace nckit {
namespace {

using plan_detail::Lookahead;
using plan_detail::WindowEvent;
using plan_detail::WindowSegment;

std::vector<TrajectoryPiece> run_window(ProfileKind kind, std::size_t window, unsigned seed, bool full,
                                        bool final_bound_commits = true, std::size_t* most_in_window = nullptr,
                                        bool merge_runs = true) {
    Lookahead lookahead(kind, window);
    lookahead.set_full_passes(full);
    lookahead.set_final_bound_commits(final_bound_commits);
    lookahead.set_merge_runs(merge_runs);
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    // A few limit sets, each also slightly perturbed, so runs join, lower and break.
    const ProfileLimits sets[] = {{50, 1000, 50000}, {20, 400, 20000}, {80, 2000, 1e5}, {5, 300, 8000}};
    std::vector<TrajectoryPiece> out;
    AxisVector at;
    for (int i = 0; i < 6000; ++i) {
        AxisVector to = at;
        const double length = unit(random) < 0.02 ? 5.0 * unit(random) + 0.5 : 0.001 + 0.1 * unit(random);
        to[Axis::X] += length;
        WindowSegment s;
        s.path = make_line(at, to);
        ProfileLimits l = sets[(i / 40 + (unit(random) < 0.1 ? 1 : 0)) % 4];
        const double wiggle = 1.0 + 0.06 * (unit(random) - 0.3);
        l = {l.max_velocity * wiggle, l.max_acceleration * wiggle, l.max_jerk * wiggle};
        s.limits = l;
        const double u = unit(random);
        s.junction_max = u < 0.01 ? 0.0 : u < 0.2 ? l.max_velocity * unit(random) : l.max_velocity;
        s.sequence_number = i;
        lookahead.add(std::move(s));
        if (unit(random) < 0.003) {
            WindowEvent e;
            e.kind = PieceKind::dwell;
            e.dwell_s = 0.01;
            lookahead.add_event(e, to);
        }
        at = to;
        if (most_in_window != nullptr) *most_in_window = std::max(*most_in_window, lookahead.window_segments());
        auto& queue = lookahead.output();
        while (!queue.empty()) {
            out.push_back(queue.front());
            queue.pop_front();
        }
    }
    lookahead.finish();
    auto& queue = lookahead.output();
    while (!queue.empty()) {
        out.push_back(queue.front());
        queue.pop_front();
    }
    return out;
}

TEST(Lookahead, IncrementalPassesMatchFullPasses) {
    for (ProfileKind kind : {ProfileKind::scurve, ProfileKind::trapezoid}) {
        for (std::size_t window : {std::size_t{2}, std::size_t{7}, std::size_t{100}, std::size_t{10000}}) {
            for (unsigned seed : {1U, 2U}) {
                const auto fast = run_window(kind, window, seed, false);
                const auto reference = run_window(kind, window, seed, true);
                ASSERT_EQ(fast.size(), reference.size());
                for (std::size_t i = 0; i < fast.size(); ++i) {
                    const TrajectoryPiece& a = fast[i];
                    const TrajectoryPiece& b = reference[i];
                    ASSERT_EQ(a.kind, b.kind) << i;
                    ASSERT_EQ(a.start_time_s, b.start_time_s) << i;
                    ASSERT_EQ(a.duration_s, b.duration_s) << i;
                    ASSERT_EQ(a.profile_offset_s, b.profile_offset_s) << i;
                    ASSERT_EQ(a.profile_offset_mm, b.profile_offset_mm) << i;
                    ASSERT_EQ(a.profile.start_velocity, b.profile.start_velocity) << i;
                    ASSERT_EQ(a.profile.end_velocity, b.profile.end_velocity) << i;
                    ASSERT_EQ(a.profile.distance, b.profile.distance) << i;
                    ASSERT_EQ(a.profile.phase_count, b.profile.phase_count) << i;
                    ASSERT_EQ(a.sequence_number, b.sequence_number) << i;
                }
            }
        }
    }
}

// A run whose end speed is held by a junction limit further on (not by the window's provisional
// stop) is committed at once: the pieces are those of a window that waits until the run's own
// junction limit holds it or the window overflows, while far fewer segments wait in the window.
TEST(Lookahead, RunsHeldByALaterJunctionLimitLeaveTheWindowEarly) {
    for (ProfileKind kind : {ProfileKind::scurve, ProfileKind::trapezoid}) {
        for (unsigned seed : {1U, 2U, 3U}) {
            std::size_t early_most = 0;
            std::size_t late_most = 0;
            // Runs merged into one profile (run_merge.hpp) depend on which later runs are in the
            // window when a run leaves it, so the end speeds are compared without merging.
            const auto early = run_window(kind, 10000, seed, false, true, &early_most, false);
            const auto late = run_window(kind, 10000, seed, false, false, &late_most, false);
            ASSERT_EQ(early.size(), late.size());
            for (std::size_t i = 0; i < early.size(); ++i) {
                ASSERT_EQ(early[i].start_time_s, late[i].start_time_s) << i;
                ASSERT_EQ(early[i].duration_s, late[i].duration_s) << i;
                ASSERT_EQ(early[i].profile.end_velocity, late[i].profile.end_velocity) << i;
            }
            // The late window holds nearly the whole input (its junction limits are mostly at
            // the segments' speed limits, which hold the bounds from further on).
            EXPECT_LE(early_most, late_most);
            EXPECT_LT(early_most, 1000U);
        }
    }
}

// A chain of lines and transitions between them, speeding up from rest: under a jerk limit their
// acceleration and jerk limits differ by more than run_spread from one to the next (a line takes
// the axis's acceleration, a transition keeps a share for its turning). They share one run, so
// the path acceleration is not brought back to 0 at every vertex; arcs' pieces keep run_spread
// (and, with the runs merged at commit, still get one profile where that is faster).
TEST(Lookahead, StraightChainsShareARunAcrossDifferentRateLimits) {
    auto pieces_of = [](SegmentShape odd_shape, bool merge_runs = false) {
        Lookahead lookahead(ProfileKind::scurve, 10000);
        lookahead.set_merge_runs(merge_runs);
        AxisVector at;
        for (int i = 0; i < 40; ++i) {
            AxisVector to = at;
            to[Axis::X] += 0.25;
            WindowSegment s;
            s.path = make_line(at, to);
            if (i % 2 == 1) s.path.shape = odd_shape;  // the limits are what matters here
            s.limits = i % 2 == 0 ? ProfileLimits{50, 500, 5000} : ProfileLimits{50, 360, 3600};
            s.junction_max = s.limits.max_velocity;
            lookahead.add(std::move(s));
            at = to;
        }
        lookahead.finish();
        std::vector<TrajectoryPiece> out;
        auto& queue = lookahead.output();
        while (!queue.empty()) {
            out.push_back(queue.front());
            queue.pop_front();
        }
        return out;
    };
    auto profiles = [](const std::vector<TrajectoryPiece>& pieces) {
        return std::count_if(pieces.begin(), pieces.end(), [](const TrajectoryPiece& p) { return p.ends_profile; });
    };
    auto duration = [](const std::vector<TrajectoryPiece>& pieces) {
        return pieces.back().start_time_s + pieces.back().duration_s;
    };
    const auto straight = pieces_of(SegmentShape::line);
    const auto curved = pieces_of(SegmentShape::arc);
    EXPECT_EQ(profiles(straight), 1);
    EXPECT_EQ(profiles(curved), 40);
    // One run at the lower limits is faster than 40 runs that each start and end at a = 0.
    EXPECT_LT(duration(straight), 0.8 * duration(curved));
    // Merged at commit, the 40 runs of the curved variant become a few profiles that carry the
    // acceleration across the runs' boundaries.
    const auto merged = pieces_of(SegmentShape::arc, true);
    EXPECT_LT(profiles(merged), 5);
    EXPECT_LT(duration(merged), 0.8 * duration(curved));
    EXPECT_EQ(pieces_of(SegmentShape::line, true).size(), straight.size());
}

}  // namespace
}  // namespace nckit
