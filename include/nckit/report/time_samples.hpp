#pragma once
// The axes' state at evenly spaced times over a whole program, kept to a bounded number of
// samples however long the program: when the store is full the period doubles and every other
// sample goes (so the samples stay exact states at multiples of one period).
#include <cstddef>
#include <vector>

#include "nckit/core/machine.hpp"
#include "nckit/plan/trajectory.hpp"

namespace nckit {

struct TimeSamples {
    double period_s = 0;     //!< s between samples (the last one is the cycle's end)
    std::vector<Axis> axes;  //!< the machine's axes, in X Y Z A B C U V W order
    std::vector<double> t_s;
    //! Per axis (index as `axes`), one value per sample: mm (deg), mm/s, mm/s², mm/s³.
    std::vector<std::vector<double>> position, velocity, acceleration, jerk;
    std::vector<double> speed_mm_s;  //!< the tool's speed along X Y Z (path speed without XYZ)
};

class TimeSampler {
public:
    //! Starts at the machine's servo period; keeps between max_samples and 2·max_samples.
    TimeSampler(const MachineConfig& machine, std::size_t max_samples);
    void add(const TrajectoryPiece& piece);
    //! Adds the state at the cycle's end (the end of the last piece given).
    [[nodiscard]] TimeSamples finish();

private:
    void take(const TrajectorySample& sample);
    void halve();
    TimeSamples samples_;
    std::size_t max_samples_;
    std::int64_t next_index_ = 0;
    TrajectoryPiece last_;
    bool any_ = false;
};

}  // namespace nckit
