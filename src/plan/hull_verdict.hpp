#pragma once
// A cheap, rigorous deviation bound for a quintic transition between two lines, from the convex
// hull of its Bézier control points (transition.cpp decides with it before sampling).
#include "transition.hpp"

namespace nckit::plan_detail {

//! A rigorous, cheap verdict for a transition between two lines (the corner C between the cut
//! points A and B), used before sampling: a polynomial curve lies in the convex hull of its
//! Bézier control points, and the distance to the chord A–B is convex, so no point of the curve
//! is farther from that chord than the farthest control point. Every point of the chord is
//! within dist(C, line AB) of the two lines when the triangle's angles at A and B are acute.
//! A chained meeting point may lie off its line (chain_state.hpp): then the height is taken over
//! the feet A', B' of A and B on the lines, plus the larger of their offsets and a nanometre of
//! rounding.
//! Likewise the curve's velocity dq/ds lies in the hull of the derivative's control points: when
//! all of them have a component of at least `min_speed` along one direction, so has
//! the curve everywhere. Returns the deviation bound, or a negative value when it cannot decide
//! (then the samples do).
[[nodiscard]] double hull_verdict(const PathSegment& curve, const Transition& t, const AxisVector& a,
                                  const AxisVector& b, double min_speed);

}  // namespace nckit::plan_detail
