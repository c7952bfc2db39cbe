#include "nckit/plan/trajectory.hpp"

#include <algorithm>

namespace nckit {

TrajectorySample sample(const TrajectoryPiece& piece, double t) {
    TrajectorySample out;
    out.t = t;
    if (piece.kind != PieceKind::motion) {
        out.position = start_point(piece.segment);
        return out;
    }
    // At the piece's end time exactly the end state: (start + duration) − start can miss the
    // duration by a rounding, which would leave a trapezoid's last acceleration showing.
    const bool at_end = t >= piece.start_time_s + piece.duration_s;
    const double profile_t = at_end && piece.ends_profile ? piece.profile.duration_s()
                             : at_end                     ? piece.profile_offset_s + piece.duration_s
                                                          : piece.profile_offset_s + (t - piece.start_time_s);
    const ProfileState st = piece.profile.at(profile_t);
    const PathPoint p =
        point_at(piece.segment, std::clamp(st.position - piece.profile_offset_mm, 0.0, piece.segment.length));
    const double v = st.velocity;
    const double a = st.acceleration;
    const double j = st.jerk;
    const double v2 = v * v;
    for (std::size_t i = 0; i < axis_count; ++i) {
        out.position[i] = p.position[i];
        out.velocity[i] = p.d1[i] * v;
        out.acceleration[i] = p.d2[i] * v2 + p.d1[i] * a;
        out.jerk[i] = p.d3[i] * v2 * v + 3.0 * p.d2[i] * v * a + p.d1[i] * j;
    }
    out.path_velocity = v;
    out.path_acceleration = a;
    return out;
}

double Trajectory::duration_s() const {
    return pieces.empty() ? 0.0 : pieces.back().start_time_s + pieces.back().duration_s;
}

TrajectorySample Trajectory::sample(double t) const {
    if (pieces.empty()) return TrajectorySample{t, {}, {}, {}, {}, 0, 0};
    // The last piece starting at or before t.
    auto it = std::upper_bound(pieces.begin(), pieces.end(), t,
                               [](double time, const TrajectoryPiece& p) { return time < p.start_time_s; });
    if (it != pieces.begin()) --it;
    return nckit::sample(*it, t);
}

}  // namespace nckit
