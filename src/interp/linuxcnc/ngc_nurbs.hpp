#pragma once
// LinuxCNC's splines (G5 cubic, G5.1 quadratic, G5.2/G5.3 NURBS) as its motion controller runs
// them: every spline is a NURBS curve of order k on a clamped uniform knot vector, cut into
// 4 x (control points) equal steps of its parameter; each step becomes a biarc (two tangent arcs)
// from the curve's point and tangent at one step to those at the next. The maths of
// docs/gcode-linuxcnc.md ("Splines"), in the plane's own first and second axes.
#include <vector>

namespace nckit::interp::ngc {

struct NurbsControlPoint {
    double first = 0;   //!< plane's first axis (X in G17, Y in G19, Z in G18), program units
    double second = 0;  //!< plane's second axis
    double weight = 1;
};

//! One element of the approximation, in the plane; it starts where the one before ends.
struct SplineElement {
    bool arc = false;  //!< false: a straight feed
    double end_first = 0;
    double end_second = 0;
    double center_first = 0;  //!< arcs only
    double center_second = 0;
    bool counterclockwise = false;
};

//! The biarcs LinuxCNC puts in place of the NURBS curve of `points` (at least `order` of them,
//! order >= 2). The first point is where the tool stands.
[[nodiscard]] std::vector<SplineElement> nurbs_biarcs(const std::vector<NurbsControlPoint>& points, unsigned order);

//! Largest order (L) and number of control points nckit reads: bounds the work of one curve.
inline constexpr unsigned max_nurbs_order = 20;
inline constexpr std::size_t max_nurbs_points = 20000;

}  // namespace nckit::interp::ngc
