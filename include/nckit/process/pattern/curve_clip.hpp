#pragma once
// Exact clipping of plane curves to a closed border: the crossings of a motif curve with the
// border's cubic pieces are roots of polynomials (a line against a cubic: degree 3; a circle
// against a cubic: degree 6; two cubics: a 2×2 system), bracketed on a fine grid and then solved
// to machine precision by bisection and Newton steps on the curves themselves, never taken from
// a sampled polyline. Every clipped end therefore lies on the border to about 1e-12 mm.
#include <vector>

#include "nckit/process/pattern/plane_curve.hpp"

namespace nckit::pattern {

//! A closed border (counter-clockwise) with what the clipper needs prepared once.
class ClipBorder {
public:
    explicit ClipBorder(CubicPath border);

    [[nodiscard]] const CubicPath& path() const { return path_; }
    [[nodiscard]] const Box& box() const { return box_; }
    //! Inside (true) or outside: winding number of a dense polygon, refined by the side of the
    //! nearest border point when p is close to the border.
    [[nodiscard]] bool contains(Vec2 p) const;
    //! Parameters s on `curve` where it crosses the border, ascending, without duplicates.
    [[nodiscard]] std::vector<double> crossings(const PlaneCurve& curve) const;

private:
    CubicPath path_;
    std::vector<Box> piece_boxes_;
    std::vector<Vec2> polygon_;
    double polygon_error_mm_ = 0;
    Box box_;
};

//! A piece of a motif curve kept by the clip.
struct ClippedCurve {
    PlaneCurve curve;
    bool start_on_border = false;  //!< its start was cut by the border
    bool end_on_border = false;
};

//! The parts of `curve` inside the border; parts shorter than `min_length_mm` are dropped.
[[nodiscard]] std::vector<ClippedCurve> clip_to_border(const PlaneCurve& curve, const ClipBorder& border,
                                                       double min_length_mm);

}  // namespace nckit::pattern
