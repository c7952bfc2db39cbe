#include "nckit/cam/section_shape.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace nckit::cam {

namespace {
constexpr double rad_per_deg = std::numbers::pi / 180.0;
}  // namespace

std::string_view name(ShapeKind kind) {
    switch (kind) {
        case ShapeKind::ellipse2:
            return "ellipse2";
        case ShapeKind::ellipse4:
            return "ellipse4";
        case ShapeKind::ellipse:
            return "ellipse";
        case ShapeKind::formula:
            return "formula";
    }
    return "formula";
}

std::optional<ShapeKind> parse_shape_name(std::string_view text) {
    for (ShapeKind kind : {ShapeKind::ellipse2, ShapeKind::ellipse4, ShapeKind::ellipse}) {
        if (text == name(kind)) return kind;
    }
    return std::nullopt;
}

std::vector<std::string> shape_formula_variables() {
    return {"Z", "PHI", "D", "E"};
}

SectionShape SectionShape::ellipse2() {
    return SectionShape(ShapeKind::ellipse2);
}

SectionShape SectionShape::ellipse4(DrawingFunction e4_mm) {
    SectionShape shape(ShapeKind::ellipse4);
    shape.e4_mm_ = std::move(e4_mm);
    return shape;
}

SectionShape SectionShape::ellipse() {
    return SectionShape(ShapeKind::ellipse);
}

SectionShape SectionShape::formula(Formula drop_mm) {
    if (drop_mm.variables() != shape_formula_variables()) {
        throw std::invalid_argument("a shape formula has the variables Z, PHI, D, E");
    }
    SectionShape shape(ShapeKind::formula);
    shape.drop_formula_ = std::move(drop_mm);
    return shape;
}

double SectionShape::drop_mm(double phi_deg, double z_mm, double d_mm, double e_mm) const {
    const double phi = phi_deg * rad_per_deg;
    switch (kind_) {
        case ShapeKind::ellipse2:
            return 0.25 * e_mm * (1.0 - std::cos(2.0 * phi));
        case ShapeKind::ellipse4:
            return 0.25 * e_mm * (1.0 - std::cos(2.0 * phi)) + 0.25 * e4_mm_->value(z_mm) * (1.0 - std::cos(4.0 * phi));
        case ShapeKind::ellipse: {
            // Polar radius of the ellipse at polar angle φ: a b / sqrt((b cos φ)² + (a sin φ)²).
            const double a = 0.5 * d_mm;
            const double b = 0.5 * (d_mm - e_mm);
            return a - a * b / std::hypot(b * std::cos(phi), a * std::sin(phi));
        }
        case ShapeKind::formula: {
            const std::array<double, 4> values{z_mm, phi_deg, d_mm, e_mm};
            return drop_formula_->evaluate(values);
        }
    }
    return 0.0;
}

}  // namespace nckit::cam
