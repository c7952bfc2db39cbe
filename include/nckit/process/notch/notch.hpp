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
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "nckit/core/diagnostic.hpp"
#include "nckit/core/machine.hpp"
#include "nckit/interp/interpreter.hpp"
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
    //! Cuts whose run-ups and overruns are checked in one run of the program (run_notch_job):
    //! memory holds about two chunks of cuts, and a program with more cuts is run once more per
    //! chunk (docs/processes/notching.md, "Long programs").
    std::size_t cuts_per_chunk = 4096;
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

//! The whole job on a move list held in memory: rewrite, write the plain program (GcodeWriter,
//! as `nckit expand` does), read that text back through the interpreter, plan the original and
//! the rewritten moves, and fill each cut's before/after speeds. run_notch_job streams the same.
struct NotchJob {
    std::vector<NotchCut> cuts;
    std::string program;  //!< the rewritten program text
};
[[nodiscard]] Result<NotchJob> notch_program(const std::vector<Move>& moves, const MachineConfig& machine,
                                             const std::string& source_name, const NotchOptions& options = {});

//! One run of a program from its start: each call hands out the next move, then ProgramEnd (or
//! the Diagnostic that stopped it).
using MoveReader = std::function<InterpResult()>;

//! What the streamed job reads and where it writes. The original program is run once per pass
//! (see run_notch_job), so memory stays bounded whatever the program's length and number of
//! cuts: what is kept is the records of at most two chunks of cuts, never the moves, the
//! trajectories or the speed samples.
struct NotchStreams {
    //! A new run of the original program from its start; nothing when it cannot be opened (the
    //! opener has said why).
    std::function<std::optional<MoveReader>()> original;
    //! Receives the rewritten program's text, in order (pass 2).
    std::function<void(std::string_view)> write_rewritten;
    //! A run of the rewritten program as written (pass 3, after the last write_rewritten).
    std::function<std::optional<MoveReader>()> rewritten;
    //! Every check passed and the rewritten program is complete: the number of cuts, before the
    //! first on_cut. False stops the job (the callback has said why).
    std::function<bool(std::size_t)> on_checked;
    //! Each cut with its before and after speeds, in program order.
    std::function<void(NotchCut&&)> on_cut;
};

//! How a streamed job ended: ok when it ran to the end.
struct NotchRunStatus {
    Diagnostics diagnostics;
    bool stopped = false;  //!< an opener or on_checked stopped it (and reported why)
    [[nodiscard]] bool ok() const { return diagnostics.empty() && !stopped; }
};

//! The job in passes over the original program: (1) find the cuts and place their run-ups and
//! overruns, check that the planner takes the program; (2) per chunk of cuts
//! (NotchOptions::cuts_per_chunk), one run: check its run-ups and overruns against every other
//! move's path and write its part of the rewritten program; (3) plan the original and the
//! rewritten program side by side and measure each cut on both, handing the cuts out in order
//! (with one more run of the original that finds the cuts again when they fill several chunks).
//! Errors of passes 1 and 2 come before anything is handed out, in the order notch_program
//! gives them.
[[nodiscard]] NotchRunStatus run_notch_job(const MachineConfig& machine, const std::string& source_name,
                                           const NotchStreams& streams, const NotchOptions& options = {});

}  // namespace nckit
