// The one bracketed Newton search: it converges, never leaves its bracket, and stops within its
// iteration cap whatever the function's slope does.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "nckit/core/bracketed_newton.hpp"

namespace nckit {
namespace {

TEST(BracketedNewton, FindsTheCubeRootQuadratically) {
    int calls = 0;
    const auto f = [&](double x) {
        ++calls;
        return ValueSlope{x * x * x - 2.0, 3.0 * x * x};
    };
    const NewtonRoot root = bracketed_newton(f, 0.0, 2.0, 1.0, NewtonStop{.value_tolerance = 1e-15});
    EXPECT_TRUE(root.converged);
    EXPECT_NEAR(root.x, std::cbrt(2.0), 1e-15);
    EXPECT_EQ(root.evaluations, calls);
    // Newton from 1 doubles its digits each step: far fewer calls than bisection's ~50.
    EXPECT_LE(root.evaluations, 8);
}

TEST(BracketedNewton, TheBracketKeepsTheRootAndShrinks) {
    const auto f = [](double x) {
        return ValueSlope{std::tanh(5.0 * (x - 0.3)), 5.0 / std::pow(std::cosh(5.0 * (x - 0.3)), 2)};
    };
    // From the far end Newton on tanh overshoots out of the bracket: bisection takes over.
    const NewtonRoot root = bracketed_newton(f, -10.0, 10.0, 10.0, NewtonStop{.step_tolerance = 1e-14});
    EXPECT_TRUE(root.converged);
    EXPECT_NEAR(root.x, 0.3, 1e-12);
    EXPECT_LE(root.lo, 0.3);
    EXPECT_GE(root.hi, 0.3);
    EXPECT_GE(root.lo, -10.0);
    EXPECT_LE(root.hi, 10.0);
}

TEST(BracketedNewton, AFlatOrWrongSlopeFallsBackToBisection) {
    // The slope reported is zero or negative: every step is a bisection, still converging.
    for (double reported : {0.0, -1.0, std::nan("")}) {
        const auto f = [&](double x) { return ValueSlope{x - 0.25, reported}; };
        const NewtonRoot root = bracketed_newton(f, 0.0, 1.0, 0.9, NewtonStop{.bracket_tolerance = 1e-12});
        EXPECT_TRUE(root.converged) << reported;
        EXPECT_NEAR(root.x, 0.25, 1e-12) << reported;
        EXPECT_LE(root.evaluations, 45) << reported;
    }
}

TEST(BracketedNewton, EndsAtAdjacentDoublesWithoutATolerance) {
    // All tolerances off: the search still ends, with the bracket down to neighbouring doubles.
    const auto f = [](double x) { return ValueSlope{x * x - 2.0, 2.0 * x}; };
    const NewtonRoot root = bracketed_newton(f, 1.0, 2.0, 2.0, NewtonStop{.max_iterations = 2000});
    EXPECT_TRUE(root.converged);
    EXPECT_NEAR(root.x, std::sqrt(2.0), 4e-16);
    EXPECT_LT(root.evaluations, 2000);
}

TEST(BracketedNewton, TheIterationCapBoundsTheWork) {
    int calls = 0;
    const auto f = [&](double x) {
        ++calls;
        return ValueSlope{x - 1e-3, 0.0};  // bisection only: 1 bit per call
    };
    const NewtonRoot root = bracketed_newton(f, 0.0, 1.0, 0.5, NewtonStop{.max_iterations = 5});
    EXPECT_FALSE(root.converged);
    EXPECT_EQ(root.evaluations, 5);
    EXPECT_EQ(calls, 5);
    EXPECT_GE(root.x, 0.0);
    EXPECT_LE(root.x, 1.0);
    EXPECT_LE(root.lo, 1e-3);
    EXPECT_GE(root.hi, 1e-3);
}

TEST(BracketedNewton, StartsOutsideOrNaNAreClampedIntoTheBracket) {
    const auto f = [](double x) { return ValueSlope{x - 3.0, 1.0}; };
    for (double start : {-100.0, 100.0, std::nan("")}) {
        const NewtonRoot root = bracketed_newton(f, 2.0, 4.0, start, NewtonStop{.value_tolerance = 1e-12});
        EXPECT_NEAR(root.x, 3.0, 1e-12) << start;
    }
}

// Property: random monotone cubics p(t) = v t + a t²/2 + j t³/6 - target (the shape of a
// profile phase) are inverted to within the stop rule, inside [0, tau], within the cap.
TEST(BracketedNewton, InvertsRandomProfilePhases) {
    std::mt19937_64 random(15);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int n = 0; n < 20000; ++n) {
        const double tau = 1e-3 + unit(random);
        const double v = 100.0 * unit(random);
        const double j = 1e4 * (unit(random) - 0.5);
        // a chosen so that v(t) = v + a t + j t²/2 stays >= 0 on [0, tau]
        const double a = std::max(1e3 * (unit(random) - 0.5), -(v + std::min(0.0, 0.5 * j * tau * tau)) / tau);
        const auto position = [&](double t) { return t * (v + t * (0.5 * a + t * j / 6.0)); };
        const double end = position(tau);
        if (!(end > 0)) continue;
        const double target = unit(random) * end;
        const auto f = [&](double t) { return ValueSlope{position(t) - target, v + t * (a + 0.5 * t * j)}; };
        const NewtonRoot root =
            bracketed_newton(f, 0.0, tau, 0.5 * tau, NewtonStop{.step_tolerance = 1e-13, .max_iterations = 100});
        ASSERT_GE(root.x, 0.0);
        ASSERT_LE(root.x, tau);
        ASSERT_LE(root.lo, root.hi);
        ASSERT_TRUE(root.converged) << n;
        ASSERT_NEAR(position(root.x), target, 1e-9 * std::max(1.0, end)) << n;
    }
}

}  // namespace
}  // namespace nckit
