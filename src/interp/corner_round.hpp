#pragma once
// Fanuc's corner words: `G1 X.. Y.. ,R r` rounds the corner between this line and the next
// move with an arc of radius r tangent to both; `,C c` cuts it with a chamfer from c before the
// corner on the line to c after it on the next line. Geometry only: the executor decides when.
#include <optional>
#include <string>
#include <variant>

#include "nckit/interp/move.hpp"

namespace nckit::interp {

enum class CornerKind { round, chamfer };

//! The corner between `first` (a G1 line ending at the corner) and `next` (the move that leaves
//! it: a line, or for rounding an arc), in `plane`: both are shortened to the tangent (or
//! chamfer) points and `corner` is the piece between them, with the first line's feed.
struct CornerResult {
    Line first;
    std::variant<Line, Arc> next;
    std::variant<Line, Arc> corner;
};

//! The rounded or chamfered corner, or why it cannot be made (the moves are not in the plane,
//! they run straight on or back, the radius or chamfer does not fit on them).
[[nodiscard]] std::variant<CornerResult, std::string> make_corner(const Line& first,
                                                                  const std::variant<Line, Arc>& next,
                                                                  CornerKind kind, double size_mm, Plane plane);

}  // namespace nckit::interp
