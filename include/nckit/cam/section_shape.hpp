#pragma once
#include <optional>
#include <string_view>

#include "nckit/cam/drawing_function.hpp"
#include "nckit/cam/formula.hpp"

namespace nckit::cam {

//! How the section falls away from the major radius D/2 with the angle φ from the major axis.
enum class ShapeKind {
    ellipse2,  //!< drop = (E/4)(1 − cos 2φ): the drawing's usual "oval"
    ellipse4,  //!< ellipse2 + (E4/4)(1 − cos 4φ); major and minor diameters stay D and D − E
    ellipse,   //!< a true ellipse with semi-axes D/2 and (D − E)/2
    formula,   //!< a drawing formula in Z, PHI (deg), D and E
};

//! The job spelling of a built-in shape ("ellipse2", ...); "formula" for ShapeKind::formula.
[[nodiscard]] std::string_view name(ShapeKind kind);
//! The built-in shape a job names, or nullopt (the formula kind has no name to give).
[[nodiscard]] std::optional<ShapeKind> parse_shape_name(std::string_view text);

//! The section shape: radial drop from D/2 at each angle, for the D and E of a station.
class SectionShape {
public:
    [[nodiscard]] static SectionShape ellipse2();
    //! `e4_mm` is E4(Z), the 4th-harmonic coefficient from the drawing, mm.
    [[nodiscard]] static SectionShape ellipse4(DrawingFunction e4_mm);
    [[nodiscard]] static SectionShape ellipse();
    //! `drop_mm` in the variables Z, PHI, D, E, in that order (see shape_formula_variables).
    [[nodiscard]] static SectionShape formula(Formula drop_mm);

    [[nodiscard]] ShapeKind kind() const { return kind_; }

    //! mm the radius lies below D/2 at `phi_deg` from the major axis, at `z_mm` where the
    //! major diameter is `d_mm` and the ovality `e_mm`.
    [[nodiscard]] double drop_mm(double phi_deg, double z_mm, double d_mm, double e_mm) const;

private:
    explicit SectionShape(ShapeKind kind) : kind_(kind) {}

    ShapeKind kind_;
    std::optional<DrawingFunction> e4_mm_;  //!< ellipse4 only
    std::optional<Formula> drop_formula_;   //!< formula only
};

//! The names a shape formula may use, in the order SectionShape::formula evaluates them.
[[nodiscard]] std::vector<std::string> shape_formula_variables();

}  // namespace nckit::cam
