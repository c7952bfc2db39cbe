#pragma once
// Private to nckit_drive: where one XYZ axis of an arc, q(s) = o + r s + R (u cos ks + v sin ks),
// crosses a step boundary. Written as q(s) = o + r s + A cos(k s - psi) with A = R |(u, v)|.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "nckit/plan/path_segment.hpp"

namespace nckit::drive_detail {

//! Where dq/ds of one XYZ axis of an arc is zero, in (0, length), sorted: the ends of the
//! intervals on which the axis moves one way.
[[nodiscard]] std::vector<double> arc_turning_points(const PathSegment& g, std::size_t i);

//! s in [lo, hi] where x(s) = spu * q_i(s) crosses `target`; x is monotone on the interval,
//! rising when direction > 0. Newton on the exact derivative from `guess` (sine and cosine from
//! the library at every iterate), safeguarded by bisection: the reference the closed form below
//! is tested against, and its fallback.
[[nodiscard]] double arc_crossing_newton(const PathSegment& g, std::size_t i, double spu, double target, double lo,
                                         double hi, int direction, double guess);

//! The crossings of one axis in closed form: on an interval where the axis moves one way,
//! k s - psi stays on one branch of the cosine, so s = (branch(acos(c)) + psi) / k with
//! c = (q - o - r s) / A. A radius-mismatch rate r (rounding-sized in practice) is taken in by
//! a fixed-point iteration on r s, which contracts by |r / q'(s)| per round.
class ArcAxisCrossings {
public:
    //! Whether the closed form serves axis i of g: it moves on the circle (A > 0, k > 0) and its
    //! linear part is a small perturbation (|r| <= 1e-6 A k) that cannot add turning points.
    [[nodiscard]] static bool applies(const PathSegment& g, std::size_t i);

    ArcAxisCrossings() = default;
    ArcAxisCrossings(const PathSegment& g, std::size_t i);

    //! Chooses the branch for the monotone interval [s_a, s_b] (between turning points).
    void set_interval(double s_a, double s_b);

    //! s in [lo, hi] where q(s) = target_mm on the current interval, or -1 when the closed
    //! form cannot vouch for its answer (the caller then solves with arc_crossing_newton).
    //! The fixed point starts from the interval's middle, not from the last crossing: no
    //! crossing waits for the one before it.
    [[nodiscard]] double crossing(double target_mm, double lo, double hi) const {
        double s_ref = s_middle_;
        for (int round = 0; round < 4; ++round) {
            const double c = (target_mm - origin_ - rate_ * s_ref) * inv_amplitude_;
            // Beyond ±1 by more than a rounding: the target is not on this branch as the
            // closed form sees it (a rate large enough to move the extremum): Newton decides.
            if (!(std::abs(c) <= 1.0 + 1e-12)) return -1;
            const double phi = branch_base_ + branch_sign_ * std::acos(std::clamp(c, -1.0, 1.0));
            const double s = (phi + psi_) * inv_k_;
            if (!(s >= lo - slack_ && s <= hi + slack_)) return -1;
            // The linear part was taken at s_ref; at s it differs by r (s − s_ref).
            if (std::abs(rate_ * (s - s_ref)) <= q_ulp_) return std::clamp(s, lo, hi);
            s_ref = s;
        }
        return -1;
    }

private:
    double origin_ = 0;         //!< mm, o
    double rate_ = 0;           //!< mm per unit s, r
    double inv_amplitude_ = 0;  //!< 1 / A, 1/mm
    double psi_ = 0;            //!< rad
    double k_ = 0;              //!< rad per unit s
    double inv_k_ = 0;          //!< unit s per rad
    double q_ulp_ = 0;          //!< mm, a rounding of q: where the fixed point has converged
    double slack_ = 0;          //!< unit s, how far outside [lo, hi] a rounding may put the answer
    double branch_base_ = 0;    //!< rad, n pi (even n) or (n + 1) pi (odd n)
    double branch_sign_ = 1;    //!< +1 on a falling branch of the cosine, -1 on a rising one
    double s_middle_ = 0;       //!< unit s, the middle of the interval: the fixed point's start
};

}  // namespace nckit::drive_detail
