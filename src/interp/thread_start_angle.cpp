// Q on a threading block (G32/G33, G92 and the one-block G76): the spindle angle past the index
// pulse at which the cut starts, in 0.001 degree without a decimal point, 0 to 360 degrees, as a
// Fanuc control reads it. Cutting an n-start thread means n passes at Q = k·360000/n for the same
// path: each start then lies 1/n of a turn, lead/n along Z, from the last.
#include <cmath>

#include <fmt/format.h>

#include "executor.hpp"

namespace nckit::interp {

namespace {
constexpr double thousandths_per_turn = 360000.0;
}  // namespace

std::optional<Diagnostic> Executor::thread_start_angle(const Word& q, double& angle_deg) const {
    if (q.has_decimal_point) {
        return error(q.column, "bad-value",
                     "Q (thread start angle) is in 0.001 degree and takes no decimal point: Q180000 is 180 degrees");
    }
    if (!(q.value >= 0 && q.value <= thousandths_per_turn) || q.value != std::floor(q.value)) {
        return error(
            q.column, "bad-value",
            fmt::format("Q (thread start angle) must be a whole number from 0 to 360000 (0.001 degree), not {}",
                        q.value));
    }
    angle_deg = std::fmod(q.value, thousandths_per_turn) / 1000.0;
    return std::nullopt;
}

}  // namespace nckit::interp
