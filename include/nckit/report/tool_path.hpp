#pragma once
// What the report page shows of a planned program: every move with its source line, the planned
// path as a polyline carrying the planned speed, where the feed was not reached and why, and the
// axes' state sampled against time. Built while the program streams through the planner.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "nckit/core/machine.hpp"
#include "nckit/interp/move.hpp"
#include "nckit/plan/trajectory.hpp"
#include "nckit/plan/trajectory_stats.hpp"
#include "nckit/report/slowdown.hpp"
#include "nckit/report/time_samples.hpp"

namespace nckit {

enum class ReportMoveKind : std::uint8_t { rapid, feed, arc, sync };

//! One move of the program (a G0, G1, G2/G3 or G32/G33), in program order.
struct ReportMove {
    ReportMoveKind kind = ReportMoveKind::feed;
    std::uint32_t file = 0;              //!< index into ToolPathReport::files
    std::uint32_t line = 0;              //!< 1-based source line of the block
    double feed_mm_s = 0;                //!< programmed feed, mm/s (0 for rapids)
    std::uint32_t vertex_end = 0;        //!< its polyline is vertices [previous move's vertex_end, vertex_end]
    double start_s = 0;                  //!< s, planned start
    double end_s = 0;                    //!< s, planned end (of its corner blend too)
    double peak_mm_s = 0;                //!< planned top speed on the move, mm/s
    Slowdown slowdown = Slowdown::none;  //!< why the programmed feed was not reached
};

//! A point of the planned path (machine X Y Z) with the planned tool speed there.
struct ReportVertex {
    double x_mm = 0, y_mm = 0, z_mm = 0;
    double speed_mm_s = 0;
};

struct ToolPathOptions {
    //! mm: interior points of a move are dropped while the drawn polyline stays this close to
    //! the planned path (and the speed within speed_tolerance of the fastest speed); a move's
    //! end point is never dropped, so every move stays a drawn segment with its line.
    double tolerance_mm = 0.01;
    double speed_tolerance = 0.02;   //!< fraction of the top speed
    double arc_step_deg = 5;         //!< at most this sweep between points of an arc
    std::size_t max_samples = 8192;  //!< time samples kept: between this and twice this
    //! The program's own file, listed first (before called programs) even if its first move
    //! comes from a called one; empty: files in the order their first moves come.
    std::string first_file;
};

struct ToolPathReport {
    std::vector<std::string> files;  //!< program files, as the user named them
    std::vector<ReportMove> moves;
    std::vector<ReportVertex> vertices;  //!< vertex 0 is where the path starts
    //! Where each move with an empty polyline is drawn as a dot, in move order: a move to where
    //! the tool stands is at its vertex; a move whose whole length went into the transitions
    //! of its two corners is where those transitions meet (the planned path passes there).
    std::vector<ReportVertex> point_places;
    TimeSamples samples;
    AxisPeaks peaks;
    double cycle_time_s = 0;
    double tolerance_mm = 0;
    std::uint64_t points_before_decimation = 0;
};

//! Feed it the interpreter's moves and the planner's pieces, both in order (a piece after the
//! move it comes from), then finish().
class ToolPathRecorder {
public:
    ToolPathRecorder(const MachineConfig& machine, ProfileKind kind, ToolPathOptions options = {});
    ~ToolPathRecorder();
    ToolPathRecorder(ToolPathRecorder&&) noexcept;
    ToolPathRecorder& operator=(ToolPathRecorder&&) noexcept;

    void add_move(const Move& move);
    void add_piece(const TrajectoryPiece& piece);
    [[nodiscard]] ToolPathReport finish();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace nckit
