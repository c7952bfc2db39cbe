#pragma once
// Step compression for step-compressing firmware (Klipper's queue_step): one axis's step times
// become runs of (interval, count, add) that reproduce every step within a given error.
#include <cstdint>
#include <span>
#include <vector>

namespace nckit {

//! count steps after the previous step time t_prev: step k (1-based) at
//! t_prev + Σ_{j=0}^{k-1} (interval_ns + j·add_ns) = t_prev + k·interval_ns + k(k−1)/2·add_ns.
struct StepRun {
    std::int64_t interval_ns = 0;  //!< ns from the previous step to the first of the run
    std::uint32_t count = 0;       //!< steps in the run, >= 1
    std::int64_t add_ns = 0;       //!< ns added to the interval after each step
};

//! The run's step times, starting after t_prev_ns (what the controller will produce).
[[nodiscard]] std::vector<std::int64_t> expand_run(const StepRun& run, std::int64_t t_prev_ns);

//! Compresses the step times `times_ns` (non-decreasing, all >= t_prev_ns) of one axis and one
//! direction, greedily into as few runs as it finds, each step within max_error_ns of its exact
//! time. Every run starts from the previous run's last *reproduced* time, so errors do not
//! accumulate. `t_prev_ns` is updated to the last reproduced step time.
[[nodiscard]] std::vector<StepRun> compress_steps(std::span<const std::int64_t> times_ns, std::int64_t& t_prev_ns,
                                                  std::int64_t max_error_ns);

}  // namespace nckit
