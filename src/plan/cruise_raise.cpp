#include "cruise_raise.hpp"

#include <algorithm>
#include <cmath>

#include "profile_inverse.hpp"

namespace nckit::plan_detail {

namespace {

//! Bisection steps between the pieces' limit and their cruise speed.
constexpr int raise_steps = 6;

//! The state of constant-jerk motion after x seconds from (v, a) with jerk j.
struct Motion {
    double v;
    double a;
};
Motion advance(double v, double a, double j, double x) {
    return {v + x * (a + 0.5 * x * j), a + x * j};
}

SignedRange product(SignedRange x, SignedRange y) {
    const double p[4] = {x.lo * y.lo, x.lo * y.hi, x.hi * y.lo, x.hi * y.hi};
    return {std::min({p[0], p[1], p[2], p[3]}), std::max({p[0], p[1], p[2], p[3]})};
}
SignedRange sum(SignedRange x, SignedRange y) {
    return {x.lo + y.lo, x.hi + y.hi};
}
double magnitude(SignedRange x) {
    return std::max(std::abs(x.lo), std::abs(x.hi));
}

//! Whether an axis keeps its limits for every speed in `v`, path acceleration in `a` and the
//! path jerk j: q''·ṡ² + q'·s̈ and q'''·ṡ³ + 3·q''·ṡ·s̈ + q'·s⃛ over their ranges.
bool axis_fits(const CurvedAxis& c, SignedRange v, SignedRange a, double j) {
    const SignedRange q1 = c.signs_known ? c.q1 : SignedRange{-c.d1, c.d1};
    const SignedRange q2 = c.signs_known ? c.q2 : SignedRange{-c.d2, c.d2};
    const SignedRange q3 = c.signs_known ? c.q3 : SignedRange{-c.d3, c.d3};
    const SignedRange v2{v.lo * v.lo, v.hi * v.hi};
    const SignedRange v3{v2.lo * v.lo, v2.hi * v.hi};
    if (magnitude(sum(product(q2, v2), product(q1, a))) > c.max_acceleration) return false;
    const SignedRange turning = product(q3, v3);
    const SignedRange coupling = product({3.0 * q2.lo, 3.0 * q2.hi}, product(v, a));
    const SignedRange path = product(q1, {j, j});
    return magnitude(sum(sum(turning, coupling), path)) <= c.max_jerk;
}

//! v: the speeds (>= 0) of the part, a: its path accelerations, j its jerk.
bool part_fits(const CheckedSpan& span, SignedRange v, SignedRange a, double j) {
    const double a_top = magnitude(a);
    const double j_abs = std::abs(j);
    if (span.limits != nullptr && span.check->count == 0) {
        const ProfileLimits& l = *span.limits;
        return v.hi <= l.max_velocity && a_top <= l.max_acceleration && j_abs <= l.max_jerk;
    }
    const PieceCheck& check = *span.check;
    if (v.hi > check.speed_limit || a_top > check.straight_acceleration || j_abs > check.straight_jerk) return false;
    for (int k = 0; k < check.count; ++k) {
        if (!axis_fits(check.axes[static_cast<std::size_t>(k)], v, a, j)) return false;
    }
    return true;
}

//! Whether the motion of one phase from time x0 to x1 after its start (state v, a, jerk j at
//! the phase start) keeps the check, in two halves.
bool phase_part_fits(const CheckedSpan& span, double v, double a, double j, double x0, double x1) {
    const double mid = 0.5 * (x0 + x1);
    const double cuts[3] = {x0, mid, x1};
    for (int h = 0; h < 2; ++h) {
        const Motion s = advance(v, a, j, cuts[h]);
        const Motion e = advance(v, a, j, cuts[h + 1]);
        SignedRange speed{std::min(s.v, e.v), std::max(s.v, e.v)};
        // The speed has its extreme inside where the acceleration passes through 0.
        if (j != 0) {
            const double x_zero = -a / j;
            if (x_zero > cuts[h] && x_zero < cuts[h + 1]) {
                const double v_zero = advance(v, a, j, x_zero).v;
                speed = {std::min(speed.lo, v_zero), std::max(speed.hi, v_zero)};
            }
        }
        speed.lo = std::max(0.0, speed.lo);
        if (!part_fits(span, speed, {std::min(s.a, e.a), std::max(s.a, e.a)}, j)) return false;
    }
    return true;
}

//! Where a walk along a profile's phases stands: the phase, its start time and its start speed.
//! Spans are checked with non-decreasing times, each from the phase the last one ended in.
struct PhaseCursor {
    int phase = 0;
    double phase_start_s = 0;
    double v = 0;  //!< mm/s at the phase start

    //! Whether the span whose time in the profile is [t0, t1] keeps its check.
    bool span_fits(const Profile& profile, const CheckedSpan& span, double t0, double t1) {
        while (phase < profile.phase_count) {
            const ProfilePhase& ph = profile.phases[static_cast<std::size_t>(phase)];
            const double phase_end_s = phase_start_s + ph.duration_s;
            const double x0 = std::max(0.0, t0 - phase_start_s);
            const double x1 = std::min(ph.duration_s, t1 - phase_start_s);
            if (x1 >= x0 && !phase_part_fits(span, v, ph.acceleration, ph.jerk, x0, x1)) return false;
            if (t1 < phase_end_s || phase + 1 == profile.phase_count) break;
            v = advance(v, ph.acceleration, ph.jerk, ph.duration_s).v;
            phase_start_s = phase_end_s;
            ++phase;
        }
        return true;
    }
};

}  // namespace

bool profile_keeps_pieces(const Profile& profile, const std::vector<CheckedSpan>& spans, FailedSpan* failed) {
    const double total_s = profile.duration_s();
    // The span that failed the last profile first: profiles tried one after the other mostly
    // fail at the same place.
    if (failed != nullptr && failed->index < spans.size()) {
        ProfileWalker hint_walker(profile);
        const CheckedSpan& span = spans[failed->index];
        const double t0 = hint_walker.time_at(profile.start_position + failed->offset_mm);
        const double t1 =
            failed->index + 1 == spans.size()
                ? total_s
                : std::max(t0, hint_walker.time_at(profile.start_position + failed->offset_mm + span.length));
        PhaseCursor from_start{0, 0.0, profile.start_velocity};
        if (!from_start.span_fits(profile, span, t0, t1)) return false;
    }
    ProfileWalker walker(profile);
    PhaseCursor cursor{0, 0.0, profile.start_velocity};
    double offset_mm = 0;
    double t0 = 0;
    for (std::size_t n = 0; n < spans.size(); ++n) {
        const CheckedSpan& span = spans[n];
        const double start_mm = offset_mm;
        offset_mm += span.length;
        const double t1 =
            n + 1 == spans.size() ? total_s : std::max(t0, walker.time_at(profile.start_position + offset_mm));
        if (!cursor.span_fits(profile, span, t0, t1)) {
            if (failed != nullptr) *failed = {n, start_mm};
            return false;
        }
        t0 = t1;
    }
    return true;
}

Profile raised_profile(const Profile& planned, double distance, const ProfileLimits& limits, double cruise_velocity,
                       const std::vector<CheckedSpan>& spans) {
    Profile best = planned;
    double lo = limits.max_velocity;
    double hi = cruise_velocity;
    for (int k = 0; k < raise_steps && hi > lo * (1.0 + 1e-4); ++k) {
        // The top first: a run whose profile holds its speed on the tight pieces takes it at once.
        const double top = k == 0 ? hi : 0.5 * (lo + hi);
        ProfileLimits raised = limits;
        raised.max_velocity = top;
        const Profile candidate =
            plan_profile(distance, planned.start_velocity, planned.end_velocity, raised, ProfileKind::scurve);
        // The passes chose the end speeds with the pieces' limits: a candidate must keep them.
        const bool same_ends =
            candidate.start_velocity == planned.start_velocity && candidate.end_velocity == planned.end_velocity;
        if (same_ends && profile_keeps_pieces(candidate, spans)) {
            if (candidate.duration_s() < best.duration_s()) best = candidate;
            if (k == 0) break;
            lo = top;
        } else {
            hi = top;
        }
    }
    return best;
}

}  // namespace nckit::plan_detail
