#pragma once
// Fanuc's corner words: `G1 X.. Y.. ,R r` (or a G2/G3 block with ,R) rounds the corner between
// this move and the next with an arc of radius r tangent to both; `,C c` cuts it with a chamfer
// from c before the corner to c after it (straight-line distances from the corner, so on an arc
// c is a chord). Geometry only: the executor decides when.
#include <optional>
#include <string>
#include <variant>

#include "nckit/interp/move.hpp"

namespace nckit::interp {

enum class CornerKind { round, chamfer };

using CornerMove = std::variant<Line, Arc>;

//! The corner between `first` (a G1 line or G2/G3 arc ending at the corner) and `next` (the line
//! or arc that leaves it), in `plane`: both are shortened to the tangent (or chamfer) points and
//! `corner` is the piece between them, with the first move's feed.
struct CornerResult {
    CornerMove first;
    CornerMove next;
    CornerMove corner;
};

//! The rounded or chamfered corner, or why it cannot be made (the moves are not in the plane,
//! they run straight on or back, the radius or chamfer does not fit on them).
[[nodiscard]] std::variant<CornerResult, std::string> make_corner(const CornerMove& first, const CornerMove& next,
                                                                  CornerKind kind, double size_mm, Plane plane);

}  // namespace nckit::interp
