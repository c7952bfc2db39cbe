#include "nckit/cam/drawing_function.hpp"

#include <array>
#include <stdexcept>

namespace nckit::cam {

DrawingFunction::DrawingFunction(NaturalSpline table) : kind_(std::move(table)) {}

DrawingFunction::DrawingFunction(Formula formula) : kind_(std::move(formula)) {
    if (std::get<Formula>(kind_).variables().size() != 1) {
        throw std::invalid_argument("a drawing formula has the one variable Z");
    }
}

DrawingFunction::DrawingFunction(std::vector<FormulaSegment> segments) : kind_(std::move(segments)) {
    const auto& list = std::get<std::vector<FormulaSegment>>(kind_);
    if (list.empty()) throw std::invalid_argument("a segmented drawing function needs a segment");
    for (const FormulaSegment& segment : list) {
        if (segment.formula.variables().size() != 1) {
            throw std::invalid_argument("a drawing formula has the one variable Z");
        }
    }
}

DrawingFunction DrawingFunction::constant(double value) {
    // Two points make the natural spline a straight line; equal values make it flat.
    return DrawingFunction(NaturalSpline({0.0, 1.0}, {value, value}));
}

double DrawingFunction::value(double z_mm) const {
    if (const auto* table = std::get_if<NaturalSpline>(&kind_)) return table->value(z_mm);
    const std::array<double, 1> z{z_mm};
    if (const auto* formula = std::get_if<Formula>(&kind_)) return formula->evaluate(z);
    const auto& segments = std::get<std::vector<FormulaSegment>>(kind_);
    // A shared end belongs to the earlier interval; the job reader has checked that the
    // formulas agree there, so the choice does not show.
    for (const FormulaSegment& segment : segments) {
        if (z_mm <= segment.z_to_mm) return segment.formula.evaluate(z);
    }
    return segments.back().formula.evaluate(z);
}

}  // namespace nckit::cam
