#pragma once
// What `nckit plan` reports about a trajectory while it streams past: each axis's peak |v|,
// |a|, |j|, and the samples of a trace at a fixed period.
#include <cstdint>
#include <string>

#include "nckit/core/machine.hpp"
#include "nckit/plan/setpoint_sampler.hpp"
#include "nckit/plan/trajectory.hpp"

namespace nckit {

struct AxisPeaks {
    AxisVector max_velocity;      //!< mm/s (deg/s), largest |v| reached
    AxisVector max_acceleration;  //!< mm/s², largest |a|
    AxisVector max_jerk;          //!< mm/s³, largest |j|
};

//! Peaks over every motion piece, evaluated exactly at each profile phase boundary (both
//! sides) and at `points_per_phase` times inside each phase.
class PeakTracker {
public:
    explicit PeakTracker(int points_per_phase = 16) : points_per_phase_(points_per_phase) {}
    void add(const TrajectoryPiece& piece);
    [[nodiscard]] const AxisPeaks& peaks() const { return peaks_; }

private:
    void take(const TrajectorySample& sample);
    int points_per_phase_;
    AxisPeaks peaks_;
};

//! CSV of the trajectory every `period_s`: `t,X,Y,...,vX,...,aX,...,jX,...` for the machine's
//! axes in X Y Z A B C U V W order, full double precision. Pieces are given in order; finish()
//! writes the samples at and after the last piece's end, up to the cycle time
//! (SetpointSampler, SamplerEnd::within_cycle).
class TraceWriter {
public:
    TraceWriter(const MachineConfig& machine, double period_s);
    [[nodiscard]] std::string header() const;
    //! Appends the rows of the sample times that fall in this piece.
    void add(const TrajectoryPiece& piece, std::string& out);
    void finish(std::string& out);

private:
    void row(const TrajectorySample& sample, std::string& out) const;
    AxisSet axes_;
    SetpointSampler sampler_;
};

}  // namespace nckit
