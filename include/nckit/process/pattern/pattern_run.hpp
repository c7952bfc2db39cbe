#pragma once
// One sole from job to program: layout, cut order (drawing order, optimised order, lower
// bound), the program, and its cycle time as nckit's planner plans it.
#include <optional>
#include <string>

#include "nckit/core/machine.hpp"
#include "nckit/process/pattern/cut_order.hpp"
#include "nckit/process/pattern/order_bound.hpp"
#include "nckit/process/pattern/pattern_layout.hpp"
#include "nckit/process/pattern/pattern_program.hpp"

namespace nckit::pattern {

struct SoleRun {
    SoleLayout layout;
    std::vector<CutEnds> ends;
    Tour tour;                     //!< the order the program cuts
    TourCost drawing;              //!< air of the drawing order (lattice rows)
    TourCost optimised;            //!< air of `tour`
    OrderResult search;            //!< passes and evaluations of the optimiser
    double bound_distance_mm = 0;  //!< no order has less XY air distance
    double bound_time_s = 0;       //!< no order has less XY air time (rapids, no reversals)
    double z_air_time_s = 0;       //!< retracts and rapid approaches: the same in every order
    double cut_length_mm = 0;
    std::vector<ProgramCut> program_cuts;
    std::string program;
    double planned_cycle_s = 0;  //!< the program through the interpreter and planner
    double planned_air_s = 0;    //!< the rapids of that plan
    double planned_cut_s = 0;    //!< everything else (plunges and grooves)
};

//! `optimise` false keeps the drawing order (for comparisons).
[[nodiscard]] Result<SoleRun> run_pattern_sole(const PatternJob& job, const OutlinePoints& points,
                                               const Grading& grading, const MachineConfig& machine,
                                               const std::string& title, bool optimise = true);

}  // namespace nckit::pattern
