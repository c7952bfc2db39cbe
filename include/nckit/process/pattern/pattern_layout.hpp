#pragma once
// The layout of one sole: the outline graded to the size (and mirrored for the other foot),
// its border, and the motif tiled over it by the lattice and clipped to the border. Everything
// comes out in program coordinates: mm from the reference hole.
#include <optional>
#include <vector>

#include "nckit/core/result.hpp"
#include "nckit/process/pattern/pattern_job.hpp"
#include "nckit/process/pattern/sole_outline.hpp"

namespace nckit::pattern {

//! One groove: a curve cut at one depth, in the direction it is drawn.
struct Cut {
    PlaneCurve curve;
    double depth_mm = 0;
    bool start_on_border = false;
    bool end_on_border = false;
};

//! How a size is made from the base outline: x' = c + (sx·(x − c.x), sy·(y − c.y)), c the
//! outline's box centre, then for the other foot y' = 2·c.y − y'.
struct Grading {
    double size = 0;
    double scale_x = 1;  //!< along the sole's length
    double scale_y = 1;  //!< across it
    bool mirror = false;
};

struct SoleLayout {
    Grading grading;
    CubicPath outline;  //!< graded, program coordinates
    CubicPath border;
    std::vector<Cut> cuts;    //!< drawing order: lattice rows, then along each row
    double fit_error_mm = 0;  //!< the outline spline against the digitised points
    double border_offset_error_mm = 0;
    std::size_t control_points = 0;
    std::size_t motif_instances = 0;  //!< lattice places whose motif reaches the border's box
};

//! The grading of `size` (the base size or one listed in the series; nothing: the outline as
//! it is). An unknown size is an error at the series.
[[nodiscard]] Result<Grading> grading_for(const PatternJob& job, std::optional<double> size, bool mirror);

//! Fits, grades, tiles and clips. Errors: the outline's (see fit_sole_outline), a border that
//! folds over, a motif larger than the border, a lattice of more than 200000 places.
[[nodiscard]] Result<SoleLayout> lay_out_sole(const PatternJob& job, const OutlinePoints& points,
                                              const Grading& grading);

}  // namespace nckit::pattern
