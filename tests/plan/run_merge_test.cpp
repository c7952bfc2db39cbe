// S-curve runs committed as one profile (src/plan/run_merge.hpp): a speed change that crosses
// several runs carries its acceleration across their boundaries, and every segment keeps its
// own limits along the merged profile, by finite differences of the sampled positions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "../../src/plan/lookahead.hpp"
#include "../../src/plan/run_merge.hpp"
#include "nckit/plan/path_segment.hpp"

namespace nckit {
namespace {

using plan_detail::CheckedSpan;
using plan_detail::Lookahead;
using plan_detail::MergeRates;
using plan_detail::PieceCheck;
using plan_detail::WindowSegment;

struct Staircase {
    std::vector<TrajectoryPiece> pieces;
    std::vector<ProfileLimits> limits;  //!< of each motion piece's segment
};

// A 40 mm line at 100 mm/s, 500 mm/s², 5,000 mm/s³, then ten 1 mm segments whose speed limits
// fall from 90 to 45 mm/s with lower rates (200 mm/s², 2,000 mm/s³: a transition's share), then
// a 20 mm line at the lowest speed and a stop. Every step of the speed limits is more than
// run_spread, so each segment is a run of its own that starts and ends at a = 0.
Staircase staircase(bool merge_runs) {
    Lookahead lookahead(ProfileKind::scurve, 10000);
    lookahead.set_merge_runs(merge_runs);
    Staircase out;
    AxisVector at;
    auto add = [&](double length, ProfileLimits limits, bool stop) {
        AxisVector to = at;
        to[Axis::X] += length;
        WindowSegment s;
        s.path = make_line(at, to);
        s.limits = limits;
        s.junction_max = stop ? 0.0 : limits.max_velocity;
        lookahead.add(std::move(s));
        out.limits.push_back(limits);
        at = to;
    };
    add(40.0, {100, 500, 5000}, false);
    for (int k = 0; k < 10; ++k) add(2.0, {95.0 - 5.0 * k, 400, 4000}, false);
    add(20.0, {45, 400, 4000}, true);
    lookahead.finish();
    auto& queue = lookahead.output();
    while (!queue.empty()) {
        out.pieces.push_back(queue.front());
        queue.pop_front();
    }
    return out;
}

double end_of(const std::vector<TrajectoryPiece>& pieces) {
    return pieces.back().start_time_s + pieces.back().duration_s;
}

long profiles(const std::vector<TrajectoryPiece>& pieces) {
    return std::count_if(pieces.begin(), pieces.end(), [](const TrajectoryPiece& p) { return p.ends_profile; });
}

TEST(RunMerge, StaircaseOfRunsBecomesOneSpeedChange) {
    const Staircase alone = staircase(false);
    const Staircase merged = staircase(true);
    ASSERT_EQ(alone.pieces.size(), merged.pieces.size());
    EXPECT_EQ(profiles(alone.pieces), 12);
    EXPECT_LT(profiles(merged.pieces), 6);
    // Every boundary of the staircase brought the braking back to a = 0 (9.6 ms in all).
    EXPECT_LT(end_of(merged.pieces), end_of(alone.pieces) - 0.005);
}

// Positions sampled every 0.1 ms, differenced: speed, acceleration and jerk of the path (the X
// axis) within the limits of the segment each sample lies on, and at some boundary between two
// segments of different limits the acceleration is well away from 0.
TEST(RunMerge, MergedProfileKeepsEverySegmentsLimitsByFiniteDifferences) {
    const Staircase merged = staircase(true);
    const double h = 1e-4;
    const double end_s = end_of(merged.pieces);
    std::vector<double> x;
    std::vector<std::size_t> on;  // index of the piece each sample lies on
    std::size_t piece = 0;
    for (double t = 0; t <= end_s; t += h) {
        while (piece + 1 < merged.pieces.size() &&
               t > merged.pieces[piece].start_time_s + merged.pieces[piece].duration_s) {
            ++piece;
        }
        x.push_back(sample(merged.pieces[piece], t).position[Axis::X]);
        on.push_back(piece);
    }
    ASSERT_GT(x.size(), 100U);
    double carried = 0;  // the largest |a| seen where a segment of other limits begins
    for (std::size_t i = 3; i < x.size(); ++i) {
        // A difference is a weighted mean of the derivative over its samples: each part keeps
        // its own segment's limit, so the mean keeps the loosest of them (inside a segment, its
        // own limits).
        ProfileLimits l = merged.limits[on[i - 3]];
        for (std::size_t k = i - 2; k <= i; ++k) {
            const ProfileLimits& o = merged.limits[on[k]];
            l = {std::max(l.max_velocity, o.max_velocity), std::max(l.max_acceleration, o.max_acceleration),
                 std::max(l.max_jerk, o.max_jerk)};
        }
        const double v = (x[i] - x[i - 1]) / h;
        const double a = (x[i] - 2 * x[i - 1] + x[i - 2]) / (h * h);
        const double j = (x[i] - 3 * x[i - 1] + 3 * x[i - 2] - x[i - 3]) / (h * h * h);
        ASSERT_LE(v, l.max_velocity * 1.001) << "sample " << i;
        ASSERT_LE(std::abs(a), l.max_acceleration * 1.005) << "sample " << i;
        ASSERT_LE(std::abs(j), l.max_jerk * 1.01) << "sample " << i;
        const bool boundary =
            on[i] != on[i - 1] && merged.limits[on[i]].max_velocity != merged.limits[on[i - 1]].max_velocity;
        if (boundary && !merged.pieces[on[i - 1]].ends_profile) carried = std::max(carried, std::abs(a));
    }
    EXPECT_GT(carried, 50.0);
}

// Random chains of lines with limits that change by more than run_spread, stops and a small
// window: every motion piece keeps its own segment's speed, acceleration and jerk at every
// sampled instant (the profile's exact state), and merging never makes the plan slower.
TEST(RunMerge, RandomChainsKeepEachSegmentsLimitsAndNeverSlowDown) {
    const ProfileLimits sets[] = {{100, 500, 5000}, {60, 300, 2500}, {80, 150, 1200}, {30, 400, 4000}};
    for (unsigned seed = 1; seed <= 6; ++seed) {
        double durations[2] = {0, 0};
        long profile_count[2] = {0, 0};
        for (const bool merge : {false, true}) {
            Lookahead lookahead(ProfileKind::scurve, seed % 2 == 0 ? 40 : 10000);
            lookahead.set_merge_runs(merge);
            std::mt19937 random(seed);
            std::uniform_real_distribution<double> unit(0.0, 1.0);
            std::vector<ProfileLimits> limits;
            std::vector<TrajectoryPiece> pieces;
            AxisVector at;
            for (int i = 0; i < 400; ++i) {
                AxisVector to = at;
                to[Axis::X] += 0.05 + 3.0 * unit(random) * unit(random);
                WindowSegment s;
                s.path = make_line(at, to);
                const ProfileLimits& l = sets[static_cast<std::size_t>(unit(random) * 3.999)];
                const double scale = 0.8 + 0.4 * unit(random);
                s.limits = {l.max_velocity * scale, l.max_acceleration * scale, l.max_jerk * scale};
                s.junction_max = unit(random) < 0.02 ? 0.0 : s.limits.max_velocity;
                s.sequence_number = i;
                limits.push_back(s.limits);
                lookahead.add(std::move(s));
                at = to;
                for (auto& q = lookahead.output(); !q.empty(); q.pop_front()) pieces.push_back(q.front());
            }
            lookahead.finish();
            for (auto& q = lookahead.output(); !q.empty(); q.pop_front()) pieces.push_back(q.front());
            for (const TrajectoryPiece& p : pieces) {
                const ProfileLimits& l = limits[static_cast<std::size_t>(p.sequence_number)];
                for (int k = 0; k <= 16; ++k) {
                    const TrajectorySample q = sample(p, p.start_time_s + p.duration_s * k / 16.0);
                    ASSERT_LE(q.velocity[Axis::X], l.max_velocity * (1 + 1e-9)) << seed << " " << p.sequence_number;
                    ASSERT_LE(std::abs(q.acceleration[Axis::X]), l.max_acceleration * (1 + 1e-6))
                        << seed << " " << p.sequence_number;
                    ASSERT_LE(std::abs(q.jerk[Axis::X]), l.max_jerk * (1 + 1e-6)) << seed << " " << p.sequence_number;
                }
            }
            durations[merge ? 1 : 0] = end_of(pieces);
            profile_count[merge ? 1 : 0] = profiles(pieces);
        }
        EXPECT_LE(durations[1], durations[0] * (1 + 1e-9)) << seed;
        EXPECT_LT(profile_count[1], profile_count[0]) << seed;  // some runs were merged
    }
}

// A curved piece in the middle of a merged span whose axes cannot take the speed change: the
// check refuses every profile that carries the braking onto it at speed.
TEST(RunMerge, MergedProfileRefusedWhereACurvedPieceCannotTakeIt) {
    const ProfileLimits line{100, 500, 5000};
    PieceCheck tight;  // one axis turning hard: d2·v² <= 500 allows 31.6 mm/s with no acceleration
    tight.axes[0] = {1.0, 0.5, 0.0, 500.0, 5000.0};
    tight.count = 1;
    tight.cruise_velocity = 31.6;
    tight.speed_limit = 100.0;
    const PieceCheck none;
    std::vector<CheckedSpan> spans{{20.0, &none, &line}, {2.0, &tight, nullptr}, {20.0, &none, &line}};
    MergeRates rates{line, line};
    Profile out;
    // 60 mm/s in and out: the profile would have to cross the tight piece above 31.6 mm/s.
    EXPECT_FALSE(plan_detail::merged_profile(42.0, 60.0, 60.0, rates, spans, out));
    // From rest to rest it may brake to pass it, which one S-curve (rise, cruise, fall) over the
    // whole span cannot do either unless it stays below 31.6 mm/s: then it fits.
    ASSERT_TRUE(plan_detail::merged_profile(42.0, 0.0, 0.0, rates, spans, out));
    EXPECT_LE(out.end_velocity, 0.0);
    EXPECT_TRUE(plan_detail::profile_keeps_pieces(out, spans));
    // Pieces whose limits count the knee but whose axes are unknown are never merged.
    PieceCheck knee;
    knee.limits_need_knee = true;
    EXPECT_FALSE(plan_detail::mergeable(knee));
    EXPECT_TRUE(plan_detail::mergeable(none));
    EXPECT_TRUE(plan_detail::mergeable(tight));
}

}  // namespace
}  // namespace nckit
