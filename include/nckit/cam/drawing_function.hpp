#pragma once
#include <variant>
#include <vector>

#include "nckit/cam/formula.hpp"
#include "nckit/cam/natural_spline.hpp"

namespace nckit::cam {

//! One formula valid on [z_from_mm, z_to_mm] of a function given piece by piece.
struct FormulaSegment {
    double z_from_mm = 0;  //!< mm from the crown
    double z_to_mm = 0;    //!< mm, > z_from_mm
    Formula formula;       //!< in the variable Z (mm)
};

//! A drawing quantity along the piston axis, such as the major diameter D(Z) or the ovality
//! E(Z): a table of points (natural cubic spline, straight beyond its ends), one formula in Z,
//! or formulas on consecutive Z intervals.
class DrawingFunction {
public:
    //! A table of points at Z stations.
    explicit DrawingFunction(NaturalSpline table);
    //! One formula in the variable Z (mm), valid everywhere.
    explicit DrawingFunction(Formula formula);
    //! Formulas on intervals sorted by Z that touch end to end (the job reader checks it).
    //! Before the first and after the last interval the nearest formula holds on.
    explicit DrawingFunction(std::vector<FormulaSegment> segments);
    //! The same value at every Z (tests, eccentrics, shapes without a 4th harmonic).
    [[nodiscard]] static DrawingFunction constant(double value);

    //! The value at z_mm (in the unit of the quantity, mm for D and E).
    [[nodiscard]] double value(double z_mm) const;
    [[nodiscard]] double operator()(double z_mm) const { return value(z_mm); }

    [[nodiscard]] bool is_table() const { return std::holds_alternative<NaturalSpline>(kind_); }
    [[nodiscard]] bool is_formula() const { return !is_table(); }

private:
    std::variant<NaturalSpline, Formula, std::vector<FormulaSegment>> kind_;
};

}  // namespace nckit::cam
