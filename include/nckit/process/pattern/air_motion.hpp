#pragma once
// What an air move costs on the machine as nckit's planner runs it: every move of a pattern
// program starts and ends at rest (the program runs under G61), so an air move is one
// rest-to-rest profile along a straight line whose limits are the axes' limits divided by the
// line's direction cosines (segment_limits of a line), and each reversal of X or Y costs the
// backlash take-up the step generator inserts.
#include <array>

#include "nckit/core/machine.hpp"
#include "nckit/process/pattern/plane_curve.hpp"

namespace nckit::pattern {

//! Direction signs (−1, 0, +1) of X and Y.
using Signs = std::array<int, 2>;

class AirTimer {
public:
    explicit AirTimer(const MachineConfig& machine);

    //! s, the rest-to-rest time of a straight rapid by (dx, dy, dz) mm.
    [[nodiscard]] double rapid_s(double dx, double dy, double dz) const;
    [[nodiscard]] double rapid_s(Vec2 d) const { return rapid_s(d.x, d.y, 0.0); }
    //! s, the backlash take-up of one reversal of X (axis 0) or Y (1): round(backlash·spu) steps
    //! at the take-up rate; 0 when the machine has no backlash.
    [[nodiscard]] double reversal_s(int axis) const { return reversal_s_[static_cast<std::size_t>(axis)]; }

private:
    const MachineConfig* machine_;
    std::array<double, 3> vmax_{}, amax_{}, jmax_{};
    std::array<double, 2> reversal_s_{};
};

//! Reversals where a motion of direction `from` is followed by one of direction `to` (an axis
//! that does not move in one of them cannot reverse there).
[[nodiscard]] inline int reversals_between(Signs from, Signs to) {
    int n = 0;
    for (std::size_t i = 0; i < 2; ++i) n += (from[i] != 0 && to[i] != 0 && from[i] != to[i]) ? 1 : 0;
    return n;
}
[[nodiscard]] inline Signs signs_of(Vec2 d, double tolerance = 1e-9) {
    auto s = [&](double v) { return v > tolerance ? 1 : v < -tolerance ? -1 : 0; };
    return {s(d.x), s(d.y)};
}

//! Counts reversals along a sequence of XY motions, remembering each axis's last direction
//! (an axis at rest keeps it), as the drive does.
struct ReversalCounter {
    Signs last{0, 0};
    int count = 0;
    std::array<int, 2> per_axis{0, 0};
    void move(Vec2 d) {
        const Signs s = signs_of(d, 1e-7);
        for (std::size_t i = 0; i < 2; ++i) {
            if (s[i] == 0) continue;
            if (last[i] != 0 && last[i] != s[i]) {
                ++count;
                ++per_axis[i];
            }
            last[i] = s[i];
        }
    }
};

}  // namespace nckit::pattern
