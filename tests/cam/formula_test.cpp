#include <array>
#include <cmath>
#include <numbers>
#include <variant>

#include <gtest/gtest.h>

#include "nckit/cam/drawing_function.hpp"
#include "nckit/cam/formula.hpp"

namespace nckit::cam {
namespace {

Formula compiled(const std::string& text, std::vector<std::string> variables = {"Z"}) {
    auto result = Formula::compile(text, std::move(variables));
    if (auto* error = std::get_if<FormulaError>(&result)) {
        ADD_FAILURE() << text << ": " << error->message;
        return std::get<Formula>(Formula::compile("0", {"Z"}));
    }
    return std::get<Formula>(std::move(result));
}

FormulaError error_of(const std::string& text, std::vector<std::string> variables = {"Z"}) {
    auto result = Formula::compile(text, std::move(variables));
    EXPECT_TRUE(std::holds_alternative<FormulaError>(result)) << text << " compiled";
    if (auto* error = std::get_if<FormulaError>(&result)) return *error;
    return {};
}

TEST(CamFormula, EvaluatesWithItsVariables) {
    const Formula f = compiled("E/4*(1 - cos(2*PHI*_pi/180)) + Z*0 + D*0", {"Z", "PHI", "D", "E"});
    const std::array<double, 4> at45{10, 45, 89.9, 0.5};
    EXPECT_NEAR(f.evaluate(at45), 0.125, 1e-13);
    const Formula d = compiled("89.98 - 0.0002*(Z - 30)^2");
    const std::array<double, 1> z{0};
    EXPECT_NEAR(d.evaluate(z), 89.80, 1e-12);
}

TEST(CamFormula, DegreeFunctions) {
    const Formula f = compiled("sind(Z) + 10*cosd(Z)");
    for (double deg : {0.0, 30.0, 45.0, 90.0, 123.4}) {
        const std::array<double, 1> z{deg};
        const double rad = deg * std::numbers::pi / 180;
        EXPECT_NEAR(f.evaluate(z), std::sin(rad) + 10 * std::cos(rad), 1e-14);
    }
}

TEST(CamFormula, CopiesAreIndependent) {
    const Formula a = compiled("2*Z");
    Formula b = a;
    const std::array<double, 1> one{1}, three{3};
    EXPECT_EQ(b.evaluate(three), 6);
    EXPECT_EQ(a.evaluate(one), 2);
    EXPECT_EQ(b.evaluate(three), 6);
    b = compiled("Z + 1");
    EXPECT_EQ(b.evaluate(one), 2);
    EXPECT_EQ(a.evaluate(three), 6);
}

TEST(CamFormula, SyntaxErrorsSayWhereAndWhat) {
    FormulaError e = error_of("0.4 + * Z");
    EXPECT_EQ(e.position, 6u);
    EXPECT_NE(e.message.find("unexpected operator"), std::string::npos) << e.message;
    EXPECT_EQ(e.message.find("position"), std::string::npos) << e.message;

    e = error_of("0.4 + Q");  // only the variables given exist
    EXPECT_EQ(e.position, 6u);
    EXPECT_NE(e.message.find("\"Q\""), std::string::npos) << e.message;

    e = error_of("PHI", {"Z"});
    EXPECT_EQ(e.position, 0u);

    e = error_of("sin(Z");  // muparser points one past the end; kept inside the text
    EXPECT_EQ(e.position, 5u);

    e = error_of("");
    EXPECT_EQ(e.position, 0u);

    e = error_of("1, Z");
    EXPECT_EQ(e.position, 1u);
    EXPECT_NE(e.message.find("one value"), std::string::npos) << e.message;
}

TEST(CamDrawingFunction, SegmentsPickTheirInterval) {
    std::vector<FormulaSegment> pieces;
    pieces.push_back({0, 30, compiled("0.4 + 0.01*Z")});
    pieces.push_back({30, 50, compiled("0.7 + 0.005*(Z - 30)")});
    const DrawingFunction e(std::move(pieces));
    EXPECT_NEAR(e(10), 0.5, 1e-15);
    EXPECT_NEAR(e(30), 0.7, 1e-15);
    EXPECT_NEAR(e(40), 0.75, 1e-15);
    EXPECT_NEAR(e(-10), 0.3, 1e-15);  // the first formula holds on before its interval
    EXPECT_NEAR(e(60), 0.85, 1e-15);  // and the last after
}

TEST(CamDrawingFunction, ConstantAndTable) {
    const DrawingFunction c = DrawingFunction::constant(0.5);
    EXPECT_EQ(c(-100), 0.5);
    EXPECT_EQ(c(1e4), 0.5);
    EXPECT_TRUE(c.is_table());
    const DrawingFunction t(NaturalSpline({0, 10, 20}, {1, 2, 3}));
    EXPECT_NEAR(t(15), 2.5, 1e-15);
    EXPECT_NEAR(t(25), 3.5, 1e-15);
}

}  // namespace
}  // namespace nckit::cam
