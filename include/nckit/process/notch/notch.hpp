#pragma once
// Laser notching (seed process: the fracture-split notch of a connecting rod). A laser-on
// M-code that forces an exact stop makes the head start the notch from rest, so the notch start
// is cut slow (deeper, wider). The rewrite moves the switch point back along the cut line by the
// S-curve's run-up distance, so the head passes the programmed notch start at the programmed
// feed, and lets the stroke run on past the programmed end by the stopping distance, with the
// beam switched off at the programmed end by position (a laser-off M-code that is not an exact
// stop, which the planner places at its point on the path, at speed).
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "nckit/core/diagnostic.hpp"
#include "nckit/core/machine.hpp"
#include "nckit/interp/move.hpp"
#include "nckit/plan/trajectory.hpp"

namespace nckit {

//! The planned path speed over the programmed cut, from the planner's exact trajectory.
struct CutSpeed {
    double min_mm_min = 0;   //!< mm/min, lowest path speed between the programmed start and end
    double max_mm_min = 0;   //!< mm/min
    double mean_mm_min = 0;  //!< mm/min, mean over the cut's length (∫v ds / covered length)
    double covered_mm = 0;   //!< mm of the programmed cut the trajectory runs along it (a corner
                             //!< blend at the end may cut off a few µm)
    //! [coordinate, speed mm/min] points in path order: the coordinate is the moving axis's
    //! position (mm) when the cut moves one axis, else s (mm from the programmed start).
    std::vector<std::array<double, 2>> profile;
};

//! One laser-on M-code followed by a straight cutting move at feed F.
struct NotchCut {
    SourceLocation where;               //!< the cutting move's block
    std::int64_t sequence_number = -1;  //!< its N number, -1 when none
    int laser_on_mcode = 0;
    AxisVector start;                  //!< programmed notch start, machine coordinates, mm
    AxisVector end;                    //!< programmed notch end
    double length_mm = 0;              //!< |end - start|
    double feed_mm_min = 0;            //!< programmed F
    double cut_speed_mm_min = 0;       //!< speed along the cut: F, unless an axis limit caps it
    double run_up_mm = 0;              //!< S-curve distance from rest to the cut speed
    double run_up_placed_mm = 0;       //!< run-up as written: rounded up to the 0.1 µm grid
    double overrun_mm = 0;             //!< stopping distance placed past the programmed end
    bool approach_shortened = false;   //!< the run-up lies on the approach, which now ends there
    std::optional<Axis> profile_axis;  //!< the one axis the cut moves, if it moves one
    CutSpeed before;                   //!< the original program
    CutSpeed after;                    //!< the rewritten program, as read back from its text
};

struct NotchOptions {
    //! mm: a run-up or overrun closer than this to another move's path crosses it.
    double clearance_mm = 0.001;
    //! Points of each CutSpeed::profile (at least 2); min/max/mean use every sample.
    std::size_t profile_points = 201;
    //! s between speed samples on the trajectory (piece ends are always sampled).
    double sample_period_s = 0.0002;
};

//! The rewrite of a move list: the cuts found, and the new moves.
struct NotchRewrite {
    std::vector<NotchCut> cuts;
    std::vector<Move> moves;
};

//! Finds every cut and rewrites it (see the file comment). Errors (with the cut's location): a
//! run-up or overrun that leaves an axis's travel or comes within clearance of another move's
//! path, a machine without a laser-off M-code that switches at speed.
[[nodiscard]] Result<NotchRewrite> rewrite_notches(const std::vector<Move>& moves, const MachineConfig& machine,
                                                   const NotchOptions& options = {});

//! The planned speed along `cut` (start to end, travelling towards the end) in a trajectory.
[[nodiscard]] CutSpeed measure_cut_speed(const Trajectory& trajectory, const NotchCut& cut,
                                         const NotchOptions& options = {});

//! The whole job: rewrite, write the plain program (GcodeWriter, as `nckit expand` does), read
//! that text back through the interpreter, plan the original and the rewritten moves, and fill
//! each cut's before/after speeds.
struct NotchJob {
    std::vector<NotchCut> cuts;
    std::string program;  //!< the rewritten program text
};
[[nodiscard]] Result<NotchJob> notch_program(const std::vector<Move>& moves, const MachineConfig& machine,
                                             const std::string& source_name, const NotchOptions& options = {});

}  // namespace nckit
