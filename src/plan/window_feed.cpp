#include "window_feed.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "nckit/plan/segment_limits.hpp"

namespace nckit::plan_detail {

void WindowFeed::add_segment(const PathSegment& path, const ProfileLimits& limits, double junction_max,
                             const SegmentOrigin& origin, bool blend, std::vector<WindowEvent> after,
                             bool continues_move, const PieceCheck& check) {
    position = end_point(path);
    at_rest_ = !(junction_max > 0);
    // Every field named: the path is copied once, into the segment, not zeroed first.
    lookahead_.add(WindowSegment{.path = path,
                                 .limits = limits,
                                 .junction_max = junction_max,
                                 .where = origin.where,
                                 .sequence_number = origin.sequence_number,
                                 .blend = blend,
                                 .continues_move = continues_move,
                                 .spindle_locked = origin.spindle_locked,
                                 .after = std::move(after),
                                 .check = check});
}

bool WindowFeed::add_curve_pieces(PathSegment& curve, int pieces, double feed_mm_s, const SegmentOrigin& origin,
                                  bool continues_move) {
    if (!split_transition_jerk_limited(curve, machine_, feed_mm_s, pieces_, pieces)) return false;
    for (std::size_t k = 0; k < pieces_.size(); ++k) {
        ArcPiece& piece = pieces_[k];
        // The pieces after the first continue one corner (the tool-path report counts it once).
        add_segment(std::move(piece.path), piece.limits, piece.limits.max_velocity, origin, true, {},
                    continues_move || k > 0, piece.check);
    }
    return true;
}

void WindowFeed::add_transition(Transition& transition, double feed_mm_s, const SegmentOrigin& origin, bool stop) {
    // Under a jerk limit a transition that joins an arc is cut into pieces whose speed follows
    // its curvature; transitions between lines stay whole (a CAM chain would pay the pieces at
    // every vertex). A ramp transition's quintics share the pieces by their lengths.
    const bool next_to_arc =
        transition.replaced_before.shape == SegmentShape::arc || transition.replaced_after.shape == SegmentShape::arc;
    const bool in_pieces = kind_ == ProfileKind::scurve && next_to_arc;
    double total = transition.curve.length;
    for (const PathSegment& g : transition.more) total += g.length;
    auto add_one = [&](PathSegment& curve, bool continues_move) {
        const int pieces =
            transition.more.empty()
                ? transition_pieces
                : std::clamp(static_cast<int>(std::lround(ramp_transition_pieces * curve.length / total)), 4,
                             transition_pieces);
        if (in_pieces && add_curve_pieces(curve, pieces, feed_mm_s, origin, continues_move)) return;
        const ProfileLimits limits = segment_limits(
            curve, machine_, feed_mm_s, kind_, kind_ == ProfileKind::trapezoid ? trapezoid_blend_normal_share : 0.5);
        const bool last = &curve == (transition.more.empty() ? &transition.curve : &transition.more.back());
        add_segment(std::move(curve), limits, stop && last ? 0.0 : limits.max_velocity, origin, true, {},
                    continues_move);
    };
    add_one(transition.curve, false);
    for (PathSegment& g : transition.more) add_one(g, true);
}

void WindowFeed::add_motion(PathSegment path, double feed_mm_s, bool stop, const SegmentOrigin& origin,
                            std::vector<WindowEvent> after, std::optional<ProfileLimits>& limits, double normal_share) {
    const bool in_pieces = kind_ == ProfileKind::trapezoid
                               ? split_arc(path, machine_, feed_mm_s, at_rest_, stop, pieces_)
                               : split_arc_jerk_limited(path, machine_, feed_mm_s, pieces_);
    if (in_pieces) {
        for (std::size_t k = 0; k < pieces_.size(); ++k) {
            const bool last = k + 1 == pieces_.size();
            const ProfileLimits& piece_limits = pieces_[k].limits;
            add_segment(std::move(pieces_[k].path), piece_limits, last && stop ? 0.0 : piece_limits.max_velocity,
                        origin, false, last ? std::move(after) : std::vector<WindowEvent>{}, k > 0, pieces_[k].check);
        }
        return;
    }
    if (!limits) limits = segment_limits(path, machine_, feed_mm_s, kind_, normal_share);
    const ProfileLimits whole = *limits;
    add_segment(std::move(path), whole, stop ? 0.0 : whole.max_velocity, origin, false, std::move(after));
}

}  // namespace nckit::plan_detail
