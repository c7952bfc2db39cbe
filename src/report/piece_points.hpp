#pragma once
// The points at which a motion piece is drawn, with the planned speed at each.
#include <vector>

#include "nckit/plan/trajectory.hpp"
#include "nckit/report/tool_path.hpp"

namespace nckit::report_detail {

struct PiecePoints {
    std::vector<ReportVertex> points;  //!< from the piece's start to its end
    double peak_mm_s = 0;              //!< top path speed on the piece
    double start_mm_s = 0;             //!< path speed at its start
    double end_mm_s = 0;               //!< and at its end
};

//! The piece's ends, every profile phase boundary inside it (where the speed changes its law),
//! and on arcs points at most arc_step_deg apart by angle. The speed of a phase's inside is
//! never above its ends' (the acceleration is 0 only at phase boundaries), so the peak over
//! these points is the piece's.
[[nodiscard]] PiecePoints piece_points(const TrajectoryPiece& piece, double arc_step_deg);

}  // namespace nckit::report_detail
