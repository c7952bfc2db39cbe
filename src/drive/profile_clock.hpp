#pragma once
// Private to nckit_drive: the inverse of one piece's profile, the time at which it reaches a
// position. Step generation asks it once per step, so the common phases have closed forms.
#include <algorithm>
#include <cmath>

#include "nckit/plan/profile.hpp"

namespace nckit::drive_detail {

//! How the time inside a phase is found.
enum class PhaseSolver {
    closed_form,  //!< cruise linear, constant acceleration by the quadratic formula, jerk Newton
    newton        //!< bracketed Newton for every phase with acceleration (the reference)
};

//! Walks a profile forwards: queries come with non-decreasing positions, so phases are entered
//! in order and never revisited.
class ProfileClock {
public:
    explicit ProfileClock(const Profile& profile, PhaseSolver solver = PhaseSolver::closed_form);

    //! s of profile time at which the profile (relative to its start) reaches p.
    double time_at(double p) {
        if (p > end_p_ && phase_ + 1 < profile_.phase_count) advance(p);
        if (profile_.phase_count == 0) return 0;
        if (p <= p_) return start_s_;  // at (or, by rounding, before) the phase start
        if (p >= end_p_) return start_s_ + duration_;
        const double dp = p - p_;
        if (shape_ == Shape::cruise) return start_s_ + std::min(dp * inv_v_, duration_);
        if (shape_ == Shape::quadratic) {
            // v0 t + a t²/2 = dp, in the form without cancellation: t = 2 dp / (v0 + v(t)),
            // v(t) = sqrt(v0² + 2 a dp). A rounding below zero under the root only happens at
            // the very end of a stop, where p >= end_p_ has already answered.
            const double v_end = std::sqrt(std::max(v_ * v_ + 2.0 * a_ * dp, 0.0));
            return start_s_ + std::min(2.0 * dp / (v_ + v_end), duration_);
        }
        return start_s_ + newton(p);
    }

private:
    enum class Shape { cruise, quadratic, cubic };

    void advance(double p);
    void enter(int phase, double start_s, double p, double v);
    double newton(double p);

    const Profile& profile_;
    PhaseSolver solver_;
    Shape shape_ = Shape::cruise;
    int phase_ = 0;
    double start_s_ = 0;                    //!< s, profile time at the phase start
    double duration_ = 0;                   //!< s
    double p_ = 0, v_ = 0, a_ = 0, j_ = 0;  //!< state at the phase start (p relative to the profile)
    double end_p_ = 0;                      //!< mm at the phase end
    double inv_v_ = 0;                      //!< s/mm at the phase start (cruise phases)
    double half_a_ = 0, sixth_j_ = 0;       //!< the cubic's coefficients a/2, j/6
    double guess_ = 0;                      //!< s into the phase: the last root, a good start for the next
    double last_gap_ = 0;                   //!< s between the last two roots
    bool have_root_ = false;                //!< guess_ is a root in this phase, at position last_p_
    double last_p_ = 0;
};

}  // namespace nckit::drive_detail
