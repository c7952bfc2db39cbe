// Runs of curved pieces raised above the pieces' own speed limits (src/plan/cruise_raise.hpp):
// the check must refuse a speed change at the turning limit and accept a profile that holds its
// speed there; a raised profile keeps the end speeds, passes the check and is never slower.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "../../src/plan/cruise_raise.hpp"

namespace nckit::plan_detail {
namespace {

//! One axis of a circle of radius 4 mm where that axis takes the whole curvature (d2 = 1/r,
//! d3 = 1/r²) and also the path acceleration (d1 = 1): 500 mm/s², 50,000 mm/s³.
PieceCheck tight_piece() {
    PieceCheck check;
    check.axes[0] = {1.0, 0.25, 0.0625, 500.0, 50000.0};
    check.count = 1;
    check.cruise_velocity = std::sqrt(500.0 / 0.25) * (1.0 - 1e-9);  // 44.72 mm/s
    check.speed_limit = 100.0;                                       // the feed
    return check;
}

std::vector<CheckedSpan> spans_of(const PieceCheck& check, int count, double length_mm) {
    return std::vector<CheckedSpan>(static_cast<std::size_t>(count), CheckedSpan{length_mm, &check});
}

TEST(CruiseRaise, AcceptsAProfileThatHoldsItsSpeedBelowTheTurningLimit) {
    const PieceCheck check = tight_piece();
    const ProfileLimits limits{44.0, 150.0, 20000.0};
    const Profile cruise = plan_profile(10.0, 44.0, 44.0, limits, ProfileKind::scurve);
    EXPECT_TRUE(profile_keeps_pieces(cruise, spans_of(check, 20, 0.5)));
}

TEST(CruiseRaise, RefusesASpeedChangeWhereTheTurningTakesTheAcceleration) {
    // Speeding up at 150 mm/s² past 41.8 mm/s needs 0.25·v² + 150 > 500 on the axis.
    const PieceCheck check = tight_piece();
    const ProfileLimits limits{44.0, 150.0, 20000.0};
    const Profile speed_up = plan_profile(10.0, 30.0, 44.0, limits, ProfileKind::scurve);
    EXPECT_FALSE(profile_keeps_pieces(speed_up, spans_of(check, 20, 0.5)));
    // The same speed change over a straight stretch first (no curved axis), then the tight
    // pieces at the speed reached: accepted.
    PieceCheck straight;
    straight.cruise_velocity = 100.0;
    straight.speed_limit = 100.0;
    std::vector<CheckedSpan> spans = spans_of(straight, 10, 0.5);
    for (const CheckedSpan& s : spans_of(check, 10, 0.5)) spans.push_back(s);
    const Profile early = plan_profile(10.0, 30.0, 30.0, {30.0, 150.0, 20000.0}, ProfileKind::scurve);
    EXPECT_TRUE(profile_keeps_pieces(early, spans));
}

TEST(CruiseRaise, RaisedProfileKeepsEndSpeedsAndPiecesAndIsNeverSlower) {
    const PieceCheck check = tight_piece();
    for (double start : {20.0, 30.0, 35.0}) {
        for (double end : {20.0, 30.0, 35.0}) {
            const ProfileLimits limits{35.0, 150.0, 20000.0};
            const Profile planned = plan_profile(12.0, start, end, limits, ProfileKind::scurve);
            const std::vector<CheckedSpan> spans = spans_of(check, 24, 0.5);
            const Profile raised = raised_profile(planned, 12.0, limits, check.cruise_velocity, spans);
            SCOPED_TRACE(testing::Message() << "start " << start << " end " << end);
            EXPECT_EQ(raised.start_velocity, planned.start_velocity);
            EXPECT_EQ(raised.end_velocity, planned.end_velocity);
            EXPECT_LE(raised.duration_s(), planned.duration_s());
            EXPECT_TRUE(profile_keeps_pieces(raised, spans));
            if (start == 35.0 && end == 35.0) {
                // From 35 mm/s the axis can still take 150 mm/s² of path acceleration up to
                // sqrt((500 − 150)/0.25) = 37.4 mm/s: the middle of the run must go faster.
                EXPECT_LT(raised.duration_s(), planned.duration_s() * 0.99);
            }
        }
    }
}

TEST(CruiseRaise, SignsLetThePathJerkWorkAgainstTheTurning) {
    // An axis along the tangent of a circle of radius 4 mm: q' = 1, q''' = -1/r² (the turning
    // pulls the tangent's jerk back). Speeding up with s⃛ > 0 at 40 mm/s: q'''·v³ + q'·s⃛ =
    // -4,000 + 4,000 = 0 on the axis, though |q'''|·v³ + |q'|·|s⃛| = 8,000 > 5,000.
    PieceCheck check;
    check.axes[0] = {1.0, 0.0, 0.0625, 500.0, 5000.0};
    check.count = 1;
    check.cruise_velocity = 41.0;
    check.speed_limit = 100.0;
    const double t = 0.002;
    Profile p;
    p.start_velocity = 40.0;
    p.phases[0] = {t, 4000.0, 0.0};
    p.phase_count = 1;
    p.distance = t * 40.0 + 4000.0 * t * t * t / 6.0;
    p.end_velocity = 40.0 + 0.5 * 4000.0 * t * t;
    EXPECT_FALSE(profile_keeps_pieces(p, {{p.distance, &check}}));  // signs unknown: the bounds add up
    check.axes[0].signs_known = true;
    check.axes[0].q1 = {0.999, 1.0};
    check.axes[0].q2 = {0.0, 0.0};
    check.axes[0].q3 = {-0.0625, -0.062};
    EXPECT_TRUE(profile_keeps_pieces(p, {{p.distance, &check}}));
    // Braking (s⃛ < 0) adds to the turning: refused with the signs as well.
    p.phases[0].jerk = -4000.0;
    p.distance = t * 40.0 - 4000.0 * t * t * t / 6.0;
    p.end_velocity = 40.0 - 0.5 * 4000.0 * t * t;
    EXPECT_FALSE(profile_keeps_pieces(p, {{p.distance, &check}}));
}

TEST(CruiseRaise, SpeedingUpOutOfACurvePassesFasterThanItCouldCruise) {
    // The tangent axis of a circle of radius 4 mm at 5,000 mm/s³: holding a speed it allows
    // cbrt(5,000 · 16) = 43.09 mm/s (q'''·v³ alone). Speeding up through 44 mm/s with s⃛ =
    // +2,000: -0.0625 · 44³ + 2,000 = -3,324 on the axis, within the limit. The check takes the
    // signed terms, not the cruise speed, and only the feed caps the speed outright.
    PieceCheck check;
    check.axes[0] = {1.0, 0.0, 0.0625, 500.0, 5000.0};
    check.axes[0].signs_known = true;
    check.axes[0].q1 = {0.999, 1.0};
    check.axes[0].q2 = {0.0, 0.0};
    check.axes[0].q3 = {-0.0625, -0.062};
    check.count = 1;
    check.cruise_velocity = std::cbrt(5000.0 / 0.0625) * (1.0 - 1e-9);
    check.speed_limit = 100.0;
    const double t = 0.002;
    const auto at_44 = [t](double jerk) {
        Profile p;
        p.start_velocity = 44.0;
        p.phases[0] = {t, jerk, 0.0};
        p.phase_count = 1;
        p.distance = t * 44.0 + jerk * t * t * t / 6.0;
        p.end_velocity = 44.0 + 0.5 * jerk * t * t;
        return p;
    };
    const Profile speeding_up = at_44(2000.0);
    ASSERT_GT(speeding_up.start_velocity, check.cruise_velocity);
    EXPECT_TRUE(profile_keeps_pieces(speeding_up, {{speeding_up.distance, &check}}));
    // Holding 44 mm/s, or braking through it, the turning's jerk alone is over the limit.
    const Profile holding = at_44(0.0);
    EXPECT_FALSE(profile_keeps_pieces(holding, {{holding.distance, &check}}));
    const Profile braking = at_44(-2000.0);
    EXPECT_FALSE(profile_keeps_pieces(braking, {{braking.distance, &check}}));
    // The feed does cap it.
    check.speed_limit = 43.0;
    EXPECT_FALSE(profile_keeps_pieces(speeding_up, {{speeding_up.distance, &check}}));
}

}  // namespace
}  // namespace nckit::plan_detail
