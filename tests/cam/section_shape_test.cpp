#include <cmath>
#include <numbers>
#include <random>
#include <variant>

#include <gtest/gtest.h>

#include "nckit/cam/piston_profile.hpp"
#include "nckit/cam/section_shape.hpp"

namespace nckit::cam {
namespace {

PistonProfile constant_profile(double d, double e, SectionShape shape) {
    return PistonProfile(DrawingFunction::constant(d), DrawingFunction::constant(e), std::move(shape));
}

Formula shape_formula(const std::string& text) {
    return std::get<Formula>(Formula::compile(text, shape_formula_variables()));
}

TEST(CamSectionShape, WorkedNumbersOfTheDrawingRule) {
    // docs/processes/piston.md: D 89.9, E 0.5.
    const PistonProfile p = constant_profile(89.9, 0.5, SectionShape::ellipse2());
    EXPECT_NEAR(p.radius_mm(0, 0), 44.95, 1e-12);
    EXPECT_NEAR(p.radius_mm(30, 0), 44.8875, 1e-12);
    EXPECT_NEAR(p.radius_mm(45, 0), 44.825, 1e-12);
    EXPECT_NEAR(p.radius_mm(90, 0), 44.7, 1e-12);
    // Two lobes: the same at θ + 180° and mirrored about the major axis.
    EXPECT_NEAR(p.radius_mm(210, 0), 44.8875, 1e-12);
    EXPECT_NEAR(p.radius_mm(-30, 0), 44.8875, 1e-12);
}

TEST(CamSectionShape, TrueEllipseDiffersFromTheCosineRuleByAboutHalfAMicrometre) {
    // docs/processes/piston.md: D 80, E 0.5, at 45° ≈ 0.59 µm.
    const PistonProfile cosine = constant_profile(80, 0.5, SectionShape::ellipse2());
    const PistonProfile ellipse = constant_profile(80, 0.5, SectionShape::ellipse());
    // The ellipse lies inside the cosine rule there.
    const double difference_um = (cosine.radius_mm(45, 0) - ellipse.radius_mm(45, 0)) * 1000;
    EXPECT_NEAR(difference_um, 0.59, 0.005);
    // Same axes: major radius D/2 at 0°, minor (D − E)/2 at 90°.
    EXPECT_NEAR(ellipse.radius_mm(0, 0), 40.0, 1e-12);
    EXPECT_NEAR(ellipse.radius_mm(90, 0), 39.75, 1e-12);
    // And it is an ellipse: (x/a)² + (y/b)² = 1 on random angles.
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> angle(0, 360);
    for (int i = 0; i < 1000; ++i) {
        const double phi = angle(rng);
        const double r = ellipse.radius_mm(phi, 0);
        const double x = r * std::cos(phi * std::numbers::pi / 180) / 40.0;
        const double y = r * std::sin(phi * std::numbers::pi / 180) / 39.75;
        EXPECT_NEAR(x * x + y * y, 1.0, 1e-14);
    }
}

TEST(CamSectionShape, FourthHarmonicKeepsTheAxes) {
    const PistonProfile p = constant_profile(89.9, 0.5, SectionShape::ellipse4(DrawingFunction::constant(0.02)));
    EXPECT_NEAR(p.radius_mm(0, 0), 44.95, 1e-12);
    EXPECT_NEAR(p.radius_mm(90, 0), 44.7, 1e-12);
    // At 45° the 4φ term is at its full (E4/4)(1 − cos 180°) = E4/2.
    EXPECT_NEAR(p.radius_mm(45, 0), 44.825 - 0.01, 1e-12);
    // At 22.5°: (E/4)(1 − cos 45°) + (E4/4)(1 − cos 90°).
    EXPECT_NEAR(p.radius_mm(22.5, 0), 44.95 - 0.125 * (1 - std::sqrt(0.5)) - 0.005, 1e-12);
}

TEST(CamSectionShape, FormulaShapeMatchesTheBuiltIns) {
    const auto d = DrawingFunction(NaturalSpline({0, 25, 50}, {89.8, 89.98, 89.92}));
    const auto e = DrawingFunction(NaturalSpline({0, 25, 50}, {0.4, 0.6, 0.8}));
    const PistonProfile builtin(d, e, SectionShape::ellipse2());
    const PistonProfile formula(d, e, SectionShape::formula(shape_formula("E/4*(1 - cosd(2*PHI))")));
    const PistonProfile ellipse(d, e, SectionShape::ellipse());
    const PistonProfile ellipse_formula(
        d, e,
        SectionShape::formula(shape_formula("D/2 - D/2*(D-E)/2 / sqrt(((D-E)/2*cosd(PHI))^2 + (D/2*sind(PHI))^2)")));
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> angle(-720, 720), z(-10, 60);
    for (int i = 0; i < 5000; ++i) {
        const double t = angle(rng), zz = z(rng);
        EXPECT_NEAR(formula.radius_mm(t, zz), builtin.radius_mm(t, zz), 1e-13);
        EXPECT_NEAR(ellipse_formula.radius_mm(t, zz), ellipse.radius_mm(t, zz), 1e-12);
    }
}

TEST(CamSectionShape, Names) {
    for (ShapeKind kind : {ShapeKind::ellipse2, ShapeKind::ellipse4, ShapeKind::ellipse}) {
        EXPECT_EQ(parse_shape_name(name(kind)), kind);
    }
    EXPECT_FALSE(parse_shape_name("formula"));
    EXPECT_FALSE(parse_shape_name("oval"));
}

}  // namespace
}  // namespace nckit::cam
