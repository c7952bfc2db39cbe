#pragma once
// Invariants every planned trajectory must keep, checked by sampling each piece exactly at many
// times and at its ends.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

#include "nckit/core/machine.hpp"
#include "nckit/plan/trajectory.hpp"
#include "nckit/interp/move.hpp"
#include "nckit/plan/path_segment.hpp"

namespace nckit::plan_test {

inline MachineConfig test_machine(ProfileKind kind = ProfileKind::scurve) {
    MachineConfig m = default_mill();
    m.profile = kind;
    AxisConfig a;
    a.axis = Axis::A;
    a.kind = AxisKind::rotary;
    a.max_velocity = 360;
    a.max_acceleration = 3600;
    a.max_jerk = 360000;
    m.axes.push_back(a);
    m.exact_stop_mcodes = {7, 8};
    return m;
}

//! The programmed path of a line or arc move (a zero-length line for anything else).
inline PathSegment programmed_segment(const Move& move) {
    if (const auto* l = std::get_if<Line>(&move.what)) return make_line(l->from, l->to);
    if (const auto* a = std::get_if<Arc>(&move.what)) return make_arc(*a);
    return {};
}

//! mm: the distance from p to the XYZ chord a–b (its point a if it has no length), computed
//! here apart from the planner's own geometry.
inline double distance_to_chord(const AxisVector& p, const AxisVector& a, const AxisVector& b) {
    double dd = 0;
    double t = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        dd += (b[i] - a[i]) * (b[i] - a[i]);
        t += (p[i] - a[i]) * (b[i] - a[i]);
    }
    t = dd > 0 ? std::clamp(t / dd, 0.0, 1.0) : 0.0;
    double d2 = 0;
    for (std::size_t i = 0; i < 3; ++i) d2 += (p[i] - a[i] - t * (b[i] - a[i])) * (p[i] - a[i] - t * (b[i] - a[i]));
    return std::sqrt(d2);
}

//! mm: the largest distance, over 65 points of a blend or transition piece, from the programmed
//! path of `moves` (each taken as 4,096 chords; lines exactly).
inline double deviation_from(const TrajectoryPiece& piece, const std::vector<const Move*>& moves) {
    double worst = 0;
    std::vector<PathSegment> paths;
    for (const Move* m : moves) paths.push_back(programmed_segment(*m));
    for (int k = 0; k <= 64; ++k) {
        const AxisVector p = position_at(piece.segment, piece.segment.length * k / 64);
        double best = std::numeric_limits<double>::infinity();
        for (const PathSegment& g : paths) {
            const int chords = g.radius_mm > 0 ? 4096 : 1;
            AxisVector a = position_at(g, 0.0);
            for (int c = 1; c <= chords; ++c) {
                const AxisVector b = position_at(g, g.length * c / chords);
                best = std::min(best, distance_to_chord(p, a, b));
                a = b;
            }
        }
        worst = std::max(worst, best);
    }
    return worst;
}

//! The same from the programmed path of the two moves it joins.
inline double deviation_from(const TrajectoryPiece& piece, const Move& before, const Move& after) {
    return deviation_from(piece, std::vector<const Move*>{&before, &after});
}

struct CheckStats {
    double max_xyz_speed = 0;      //!< mm/s
    double worst_limit_ratio = 0;  //!< largest |v|/vmax, |a|/amax, |j|/jmax seen
    std::size_t samples = 0;
};

//! feed_of(piece) gives the XYZ speed limit of a motion piece (mm/s, +inf for none).
inline CheckStats check_trajectory(const std::vector<TrajectoryPiece>& pieces, const MachineConfig& m, ProfileKind kind,
                                   const AxisVector& end, const std::function<double(const TrajectoryPiece&)>& feed_of,
                                   int samples_per_piece = 24) {
    CheckStats stats;
    constexpr double rel = 1e-6;
    const bool jerk = kind == ProfileKind::scurve;
    auto check = [&](const TrajectorySample& s, const TrajectoryPiece& p, double feed) {
        ++stats.samples;
        for (const AxisConfig& axis : m.axes) {
            const std::size_t i = index(axis.axis);
            const double rv = std::abs(s.velocity[i]) / axis.max_velocity;
            const double ra = std::abs(s.acceleration[i]) / axis.max_acceleration;
            const double rj = jerk ? std::abs(s.jerk[i]) / axis.max_jerk : 0.0;
            stats.worst_limit_ratio = std::max({stats.worst_limit_ratio, rv, ra, rj});
            ASSERT_LE(rv, 1 + rel) << "velocity axis " << i << " t=" << s.t << " line " << p.where.line;
            ASSERT_LE(ra, 1 + rel) << "acceleration axis " << i << " t=" << s.t << " line " << p.where.line;
            ASSERT_LE(rj, 1 + rel) << "jerk axis " << i << " t=" << s.t << " line " << p.where.line;
        }
        const double xyz = std::hypot(s.velocity[0], s.velocity[1], s.velocity[2]);
        stats.max_xyz_speed = std::max(stats.max_xyz_speed, xyz);
        ASSERT_LE(xyz, feed * (1 + rel) + 1e-12) << "feed t=" << s.t << " line " << p.where.line;
    };
    double time = 0;
    const TrajectoryPiece* previous = nullptr;
    TrajectorySample previous_end;
    for (const TrajectoryPiece& p : pieces) {
        EXPECT_NEAR(p.start_time_s, time, 1e-9 * std::max(1.0, time));
        time = p.start_time_s + p.duration_s;
        const double feed = p.kind == PieceKind::motion ? feed_of(p) : std::numeric_limits<double>::infinity();
        const TrajectorySample first = sample(p, p.start_time_s);
        if (previous != nullptr && p.kind == PieceKind::io) {
            for (std::size_t i = 0; i < axis_count; ++i) EXPECT_NEAR(first.position[i], previous_end.position[i], 1e-9);
        } else if (previous != nullptr) {
            for (std::size_t i = 0; i < axis_count; ++i) {
                EXPECT_NEAR(first.position[i], previous_end.position[i], 1e-9) << "position jump at t=" << first.t;
                // Junctions count as tangent up to 1e-6 in dq/ds (junction.hpp): a jump of 1e-6·ṡ.
                const double scale = 1.01e-6 * std::max(1.0, first.path_velocity);
                EXPECT_NEAR(first.velocity[i], previous_end.velocity[i], scale)
                    << "velocity jump at t=" << first.t << " ṡ " << previous_end.path_velocity << " -> "
                    << first.path_velocity << " kinds " << int(previous->kind) << int(p.kind) << " offsets "
                    << p.profile_offset_s << " " << p.profile_offset_mm << " prev ends " << previous->ends_profile
                    << " blend " << previous->blend << p.blend << " len " << p.segment.length << " r "
                    << p.segment.radius_mm << " prev r " << previous->segment.radius_mm << " prev len "
                    << previous->segment.length;
            }
            if (kind == ProfileKind::scurve && p.kind == PieceKind::motion && previous->kind == PieceKind::motion) {
                EXPECT_NEAR(first.path_acceleration, previous_end.path_acceleration, 1e-6)
                    << "tangential acceleration jump at t=" << first.t;
            }
        }
        if (p.kind == PieceKind::dwell || (p.kind == PieceKind::io && p.io.waits)) {
            for (std::size_t i = 0; i < axis_count; ++i) EXPECT_EQ(previous_end.velocity[i], 0.0) << "not at rest";
        }
        if (p.kind == PieceKind::io) continue;  // no motion of its own: continuity runs through it
        check(first, p, feed);
        for (int k = 1; k < samples_per_piece; ++k) {
            check(sample(p, p.start_time_s + p.duration_s * k / samples_per_piece), p, feed);
        }
        previous_end = sample(p, p.start_time_s + p.duration_s);
        check(previous_end, p, feed);
        if (::testing::Test::HasFatalFailure()) return stats;
        previous = &p;
    }
    for (std::size_t i = 0; i < axis_count; ++i) {
        EXPECT_NEAR(previous_end.position[i], end[i], 1e-9) << "end position axis " << i;
        EXPECT_EQ(previous_end.velocity[i], 0.0) << "not at rest at the end";
        EXPECT_EQ(previous_end.acceleration[i], 0.0);
    }
    return stats;
}

}  // namespace nckit::plan_test
