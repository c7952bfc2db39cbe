#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "nckit/cam/natural_spline.hpp"

namespace nckit::cam {
namespace {

//! Random strictly increasing stations and values, as a drawing table might give.
NaturalSpline random_spline(std::mt19937_64& rng, std::vector<double>& x, std::vector<double>& y) {
    std::uniform_int_distribution<int> count(2, 12);
    std::uniform_real_distribution<double> gap(0.2, 15.0);
    std::uniform_real_distribution<double> value(-5.0, 5.0);
    const int n = count(rng);
    x.assign(1, value(rng));
    y.assign(1, value(rng));
    for (int i = 1; i < n; ++i) {
        x.push_back(x.back() + gap(rng));
        y.push_back(value(rng));
    }
    return NaturalSpline(x, y);
}

TEST(NaturalSpline, HandWorkedThreePoints) {
    // (0,0), (1,1), (2,0): 4 M1 = 6 (-1 - 1), M1 = -3; at 0.5: 0.5 + (0.125 - 0.5)(-3)/6.
    const NaturalSpline s({0, 1, 2}, {0, 1, 0});
    EXPECT_DOUBLE_EQ(s.second_derivatives()[1], -3.0);
    EXPECT_DOUBLE_EQ(s.value(0.5), 0.6875);
    EXPECT_DOUBLE_EQ(s.value(1.5), 0.6875);
    EXPECT_DOUBLE_EQ(s.slope(1.0), 0.0);
    EXPECT_DOUBLE_EQ(s.slope(0.0), 1.5);  // (1 - 0)/1 - 1 * (-3)/6
    EXPECT_DOUBLE_EQ(s.curvature(1.0), -3.0);
}

TEST(NaturalSpline, TwoPointsAreAStraightLine) {
    const NaturalSpline s({2, 6}, {1, 3});
    for (double x : {-10.0, 2.0, 3.0, 5.5, 6.0, 20.0}) {
        EXPECT_DOUBLE_EQ(s.value(x), 1 + 0.5 * (x - 2));
        EXPECT_DOUBLE_EQ(s.slope(x), 0.5);
        EXPECT_EQ(s.curvature(x), 0.0);
    }
}

TEST(NaturalSpline, ReproducesAStraightLineEverywhere) {
    std::vector<double> x{0, 3, 4, 10, 11.5, 30}, y;
    for (double v : x) y.push_back(89.8 + 0.004 * v);
    const NaturalSpline s(x, y);
    for (double v = -20; v <= 50; v += 0.37) EXPECT_NEAR(s.value(v), 89.8 + 0.004 * v, 1e-12);
}

TEST(NaturalSpline, ConvergesToAFunctionWithFreeEnds) {
    // sin has sin'' = 0 at 0 and pi, so the natural spline's ends are right and the error is
    // the interior's: at most 5/384 h^4 max|f''''|.
    const int n = 21;
    const double h = std::numbers::pi / (n - 1);
    std::vector<double> x, y;
    for (int i = 0; i < n; ++i) {
        x.push_back(i * h);
        y.push_back(std::sin(i * h));
    }
    const NaturalSpline s(x, y);
    const double bound = 5.0 / 384.0 * std::pow(h, 4);
    for (double v = 0; v <= std::numbers::pi; v += 0.001) {
        EXPECT_NEAR(s.value(v), std::sin(v), bound);
    }
}

TEST(NaturalSpline, RandomTablesInterpolateWithFreeEndsAndSmoothJoins) {
    std::mt19937_64 rng(20240611);
    std::vector<double> x, y;
    for (int trial = 0; trial < 2000; ++trial) {
        const NaturalSpline s = random_spline(rng, x, y);
        const std::size_t n = x.size();
        for (std::size_t i = 0; i < n; ++i) EXPECT_NEAR(s.value(x[i]), y[i], 1e-12);
        EXPECT_EQ(s.curvature(x.front()), 0.0);
        EXPECT_EQ(s.curvature(x.back()), 0.0);
        const auto m = s.second_derivatives();
        for (std::size_t i = 1; i + 1 < n; ++i) {
            // The slope at an inner point from the piece on its left and from the piece on its
            // right (textbook forms in the second derivatives M): equal, and slope() gives it.
            const double h0 = x[i] - x[i - 1], h1 = x[i + 1] - x[i];
            const double left = (y[i] - y[i - 1]) / h0 + h0 * (2 * m[i] + m[i - 1]) / 6;
            const double right = (y[i + 1] - y[i]) / h1 - h1 * (2 * m[i] + m[i + 1]) / 6;
            EXPECT_NEAR(left, right, 1e-9 * (1 + std::abs(left))) << "trial " << trial;
            EXPECT_NEAR(s.slope(x[i]), left, 1e-9 * (1 + std::abs(left))) << "trial " << trial;
            EXPECT_NEAR(s.curvature(x[i]), m[i], 1e-12 * (1 + std::abs(m[i])));
        }
    }
}

TEST(NaturalSpline, RandomTablesContinueStraightWithTheEndSlopes) {
    std::mt19937_64 rng(7);
    std::vector<double> x, y;
    std::uniform_real_distribution<double> beyond(0.0, 40.0);
    for (int trial = 0; trial < 1000; ++trial) {
        const NaturalSpline s = random_spline(rng, x, y);
        const double first_slope = s.slope(x.front());
        const double last_slope = s.slope(x.back());
        // The end slope from the spline's own formula: (y1 - y0)/h0 - h0 M1 / 6.
        const double h0 = x[1] - x[0];
        EXPECT_NEAR(first_slope, (y[1] - y[0]) / h0 - h0 * s.second_derivatives()[1] / 6, 1e-12);
        const double d = beyond(rng);
        EXPECT_NEAR(s.value(x.front() - d), y.front() - first_slope * d, 1e-9);
        EXPECT_NEAR(s.value(x.back() + d), y.back() + last_slope * d, 1e-9);
        EXPECT_EQ(s.slope(x.front() - d), first_slope);
        EXPECT_EQ(s.slope(x.back() + d), last_slope);
        EXPECT_EQ(s.curvature(x.back() + d), 0.0);
        // The straight piece joins with matching slope (curvature is 0 on both sides).
        EXPECT_NEAR((s.value(x.back() + 1e-6) - s.value(x.back() - 1e-6)) / 2e-6, last_slope, 1e-5);
    }
}

TEST(NaturalSpline, RejectsTablesNoDrawingCanHave) {
    EXPECT_THROW(NaturalSpline({1}, {1}), std::invalid_argument);
    EXPECT_THROW(NaturalSpline({1, 2}, {1}), std::invalid_argument);
    EXPECT_THROW(NaturalSpline({1, 1}, {1, 2}), std::invalid_argument);
    EXPECT_THROW(NaturalSpline({2, 1}, {1, 2}), std::invalid_argument);
    EXPECT_THROW(NaturalSpline({1, NAN}, {1, 2}), std::invalid_argument);
}

}  // namespace
}  // namespace nckit::cam
