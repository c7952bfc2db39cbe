// Spline fits of outlines and the exactness of clipping to the border.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "nckit/process/pattern/curve_clip.hpp"
#include "nckit/process/pattern/sole_outline.hpp"
#include "nckit/process/pattern/spline_fit.hpp"

namespace nckit::pattern {
namespace {

constexpr double pi = 3.14159265358979323846;

std::vector<Vec2> ellipse_points(double a, double b, std::size_t n, double noise_mm = 0, unsigned seed = 1) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-noise_mm, noise_mm);
    std::vector<Vec2> p;
    for (std::size_t i = 0; i < n; ++i) {
        const double t = 2 * pi * static_cast<double>(i) / static_cast<double>(n);
        p.push_back({a * std::cos(t) + u(rng), b * std::sin(t) + u(rng)});
    }
    return p;
}

// Distance from p to the ellipse (x/a)² + (y/b)² = 1: Newton on the angle of the nearest point.
double ellipse_distance(Vec2 p, double a, double b) {
    double t = std::atan2(p.y * a, p.x * b);
    for (int i = 0; i < 50; ++i) {
        const Vec2 e{a * std::cos(t), b * std::sin(t)};
        const Vec2 d1{-a * std::sin(t), b * std::cos(t)};
        const Vec2 d2{-a * std::cos(t), -b * std::sin(t)};
        const double f = dot(e - p, d1);
        const double df = dot(d1, d1) + dot(e - p, d2);
        t -= f / df;
    }
    return length(Vec2{a * std::cos(t), b * std::sin(t)} - p);
}

TEST(PatternSpline, ClosedInterpolationPassesThroughEveryPointAndFollowsTheCurve) {
    const std::vector<Vec2> points = ellipse_points(120, 45, 100);
    const ClosedSpline spline = fit_closed_spline(points, 0);
    ASSERT_EQ(spline.path.pieces.size(), points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        EXPECT_LT(length(spline.path.pieces[i].point(0) - points[i]), 1e-9);
        // C1 and C2 at every join (the periodic spline wraps round).
        const CubicPiece& prev = spline.path.pieces[(i + points.size() - 1) % points.size()];
        EXPECT_LT(length(prev.point(1) - points[i]), 1e-9);
    }
    // Fit error against the true ellipse between the points: 100 points on a 240 x 90 mm
    // ellipse (chords of up to 7.6 mm) stay within 10 µm.
    double worst = 0;
    for (const CubicPiece& piece : spline.path.pieces) {
        for (double u = 0.05; u < 1; u += 0.1) worst = std::max(worst, ellipse_distance(piece.point(u), 120, 45));
    }
    EXPECT_LT(worst, 0.01);
    EXPECT_GT(worst, 1e-7);  // a spline is not an ellipse: the measure sees the difference
}

TEST(PatternSpline, SmoothingKeepsEveryPointWithinTheToleranceWithFewerControlPoints) {
    const std::vector<Vec2> points = ellipse_points(120, 45, 400, 0.02, 7);
    const ClosedSpline spline = fit_closed_spline(points, 0.05);
    EXPECT_LT(spline.control_points, points.size());
    EXPECT_LE(spline.max_fit_error_mm, 0.05);
    for (const Vec2& p : points) EXPECT_LE(nearest_on_path(spline.path, p).distance_mm, 0.05 + 1e-9);
    // The smooth curve is closer to the true ellipse than the noisy points are.
    double worst = 0;
    for (const CubicPiece& piece : spline.path.pieces)
        worst = std::max(worst, ellipse_distance(piece.point(0.5), 120, 45));
    EXPECT_LT(worst, 0.03);
}

TEST(PatternSpline, OpenSplineInterpolatesItsPoints) {
    const std::vector<Vec2> points{{0, 0}, {3, 2}, {6, -1}, {9, 0.5}};
    const CubicPath path = fit_open_spline(points);
    ASSERT_EQ(path.pieces.size(), 3u);
    for (std::size_t i = 0; i < 3; ++i) EXPECT_LT(length(path.pieces[i].point(0) - points[i]), 1e-12);
    EXPECT_LT(length(path.pieces[2].point(1) - points[3]), 1e-12);
    EXPECT_NEAR(length(path.pieces[0].second(0)), 0.0, 1e-9);  // natural end
}

TEST(PatternOutline, SelfCrossingOutlineIsRejectedAtTheNearestPoint) {
    OutlinePoints bow;
    auto file = std::make_shared<const std::string>("bow.csv");
    const std::vector<Vec2> p{{0, 0}, {10, 10}, {20, 0}, {20, 10}, {10, 0}, {0, 10}};
    for (std::size_t i = 0; i < p.size(); ++i) {
        bow.points.push_back(p[i]);
        bow.where.push_back(SourceLocation{file, static_cast<std::uint32_t>(i + 2), 1});
    }
    Result<SoleOutline> outline = fit_sole_outline(bow, 0);
    ASSERT_FALSE(outline);
    EXPECT_EQ(outline.diagnostics()[0].code, "outline-crosses");
    EXPECT_EQ(outline.diagnostics()[0].location.file_name(), "bow.csv");
    EXPECT_GE(outline.diagnostics()[0].location.line, 2u);
}

class PatternClip : public ::testing::Test {
protected:
    PatternClip() : border_(fit_closed_spline(ellipse_points(100, 40, 60), 0).path) {}
    // Every end the border made lies on the border within 1 µm, every kept piece is inside.
    void check(const PlaneCurve& curve) {
        for (const ClippedCurve& piece : clip_to_border(curve, border_, 0)) {
            const double end = parameter_end(piece.curve);
            if (piece.start_on_border) {
                EXPECT_LT(nearest_on_path(border_.path(), point_at(piece.curve, 0)).distance_mm, 1e-6);
                ++ends_on_border_;
            }
            if (piece.end_on_border) {
                EXPECT_LT(nearest_on_path(border_.path(), point_at(piece.curve, end)).distance_mm, 1e-6);
                ++ends_on_border_;
            }
            EXPECT_TRUE(border_.contains(point_at(piece.curve, 0.5 * end)));
            ++pieces_;
        }
    }
    ClipBorder border_;
    int ends_on_border_ = 0;
    int pieces_ = 0;
};

TEST_F(PatternClip, LinesArcsAndSplinesEndOnTheBorderWithinOneMicrometre) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> x(-130, 130), y(-60, 60), r(2, 70), a(-180, 180), sweep(-360, 360);
    for (int i = 0; i < 150; ++i) {
        check(Segment{{x(rng), y(rng)}, {x(rng), y(rng)}});
        check(ArcCurve{{x(rng), y(rng)}, r(rng), a(rng), sweep(rng)});
        check(fit_open_spline({{x(rng), y(rng)}, {x(rng), y(rng)}, {x(rng), y(rng)}, {x(rng), y(rng)}}));
    }
    EXPECT_GT(ends_on_border_, 500);  // the test really crosses the border
    EXPECT_GT(pieces_, 300);
}

TEST_F(PatternClip, ALineThroughTheMiddleIsCutExactlyWhereTheBorderIs) {
    // The horizontal line y = 0 crosses the (symmetric) border at its x extremes, ±100.
    const std::vector<ClippedCurve> pieces = clip_to_border(Segment{{-150, 0}, {150, 0}}, border_, 0);
    ASSERT_EQ(pieces.size(), 1u);
    EXPECT_NEAR(point_at(pieces[0].curve, 0).x, -100.0, 1e-9);
    EXPECT_NEAR(point_at(pieces[0].curve, 1).x, 100.0, 1e-9);
    // Fully inside: unchanged, no border ends. Fully outside: nothing.
    const auto inside = clip_to_border(Segment{{-5, 0}, {5, 1}}, border_, 0);
    ASSERT_EQ(inside.size(), 1u);
    EXPECT_FALSE(inside[0].start_on_border || inside[0].end_on_border);
    EXPECT_TRUE(clip_to_border(Segment{{-150, 50}, {150, 55}}, border_, 0).empty());
}

TEST(PatternBorder, BorderIsTheGivenWidthInside) {
    OutlinePoints pts;
    for (const Vec2& p : ellipse_points(120, 45, 120)) {
        pts.points.push_back(p);
        pts.where.push_back({});
    }
    Result<SoleOutline> outline = fit_sole_outline(pts, 0);
    ASSERT_TRUE(outline);
    Result<Border> border = inner_border(*outline, 4.0, {});
    ASSERT_TRUE(border);
    EXPECT_LT(border->offset_error_mm, 1e-3);
    for (const CubicPiece& piece : border->curve.pieces) {
        EXPECT_NEAR(nearest_on_path(outline->curve, piece.point(0.5)).distance_mm, 4.0, 2e-3);
    }
    // A width larger than the tightest turn (ends of the ellipse: radius 45²/120 = 16.9 mm)
    // folds over.
    EXPECT_FALSE(inner_border(*outline, 30.0, {}));
}

}  // namespace
}  // namespace nckit::pattern
