#pragma once
// Where the planner's paths enter the look-ahead window: single segments, transitions and
// motions, the last two cut into pieces with limits of their own where their curvature sets the
// speed (arc_pieces.hpp, docs/planner.md "Speed along an arc").
#include <cstdint>
#include <optional>
#include <vector>

#include "arc_pieces.hpp"
#include "lookahead.hpp"
#include "transition.hpp"
#include "nckit/core/machine.hpp"

namespace nckit::plan_detail {

//! Where a segment comes from, for the trajectory pieces it becomes.
struct SegmentOrigin {
    SourceLocation where;
    std::int64_t sequence_number = -1;
    //! G32/G33: the speed is the spindle's, never part of a speed change planned across runs.
    bool spindle_locked = false;
};

//! Pieces of a whole ramp transition (shared among its quintics by length).
inline constexpr int ramp_transition_pieces = 48;

//! The check of a segment that has none (cruise_velocity 0): one constant, where a default
//! argument `{}` zeroed a new one at every call.
inline const PieceCheck no_piece_check{};

class WindowFeed {
public:
    //! machine and lookahead must outlive the feed.
    WindowFeed(const MachineConfig& machine, ProfileKind kind, Lookahead& lookahead)
        : machine_(machine), kind_(kind), lookahead_(lookahead) {}

    //! One segment as it is; junction_max 0 ends it at rest.
    void add_segment(const PathSegment& path, const ProfileLimits& limits, double junction_max,
                     const SegmentOrigin& origin, bool blend, std::vector<WindowEvent> after,
                     bool continues_move = false, const PieceCheck& check = no_piece_check);

    //! A transition between two motions (a blend, fed at feed_mm_s): under a jerk limit one that
    //! joins an arc goes in pieces whose speed follows its curvature; others whole.
    //! With `stop` it ends at rest (it took the rest of the motion before a stop: end_at_rest).
    void add_transition(Transition& transition, double feed_mm_s, const SegmentOrigin& origin, bool stop = false);

    //! A programmed motion, ending at rest when `stop`, else at most at its own speed limit (the
    //! next segment lowers it further); `after` follows its end. An arc whose curvature sets its
    //! speed goes in pieces; otherwise it goes whole with `limits` (computed here with
    //! normal_share when not known; the caller's copy is filled in).
    void add_motion(PathSegment path, double feed_mm_s, bool stop, const SegmentOrigin& origin,
                    std::vector<WindowEvent> after, std::optional<ProfileLimits>& limits, double normal_share);

    //! Where the path added so far ends; set by the caller while nothing is added.
    AxisVector position;
    //! The last segment added ends with a stop (or nothing was added yet).
    [[nodiscard]] bool at_rest() const { return at_rest_; }

private:
    //! One quintic of a transition in `pieces` pieces; false (nothing added) when it is better
    //! whole. Out of line: chains of lines never come here.
    [[gnu::noinline]] bool add_curve_pieces(PathSegment& curve, int pieces, double feed_mm_s,
                                            const SegmentOrigin& origin, bool continues_move);

    const MachineConfig& machine_;
    ProfileKind kind_;
    Lookahead& lookahead_;
    bool at_rest_ = true;
    std::vector<ArcPiece> pieces_;  //!< reused
};

}  // namespace nckit::plan_detail
