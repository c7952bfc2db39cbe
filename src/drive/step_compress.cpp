// Greedy step compression. A run is fitted through its first and last steps (interval from the
// first, add from the last), then checked against every step in between; the longest valid
// run is found by doubling the count and then bisecting between the last valid and the first
// invalid count, so a long smooth stretch costs O(n log n), never O(n²).
#include "nckit/drive/step_compress.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace nckit {

namespace {

// The run of `count` steps from `first` fitted to times[first .. first+count), or nothing.
bool fit(std::span<const std::int64_t> times, std::size_t first, std::size_t count, std::int64_t t_prev,
         std::int64_t max_error, StepRun& run) {
    const auto k = static_cast<std::int64_t>(count);
    // The first step may move within the error; try the exact first interval and its two limits.
    const std::int64_t base = times[first] - t_prev;
    for (std::int64_t shift : {std::int64_t{0}, -max_error / 2, max_error / 2}) {
        StepRun r;
        r.count = static_cast<std::uint32_t>(count);
        r.interval_ns = std::max<std::int64_t>(0, base + shift);
        if (count > 1) {
            const double rest = static_cast<double>(times[first + count - 1] - t_prev - k * r.interval_ns);
            r.add_ns = std::llround(rest / (0.5 * static_cast<double>(k * (k - 1))));
        }
        bool ok = true;
        std::int64_t t = t_prev;
        std::int64_t interval = r.interval_ns;
        for (std::size_t j = 0; j < count && ok; ++j) {
            if (interval < 0) ok = false;
            t += interval;
            interval += r.add_ns;
            if (std::llabs(t - times[first + j]) > max_error) ok = false;
        }
        if (ok) {
            run = r;
            return true;
        }
    }
    return false;
}

}  // namespace

std::vector<std::int64_t> expand_run(const StepRun& run, std::int64_t t_prev_ns) {
    std::vector<std::int64_t> out;
    out.reserve(run.count);
    std::int64_t interval = run.interval_ns;
    for (std::uint32_t j = 0; j < run.count; ++j) {
        t_prev_ns += interval;
        interval += run.add_ns;
        out.push_back(t_prev_ns);
    }
    return out;
}

std::vector<StepRun> compress_steps(std::span<const std::int64_t> times, std::int64_t& t_prev_ns,
                                    std::int64_t max_error_ns) {
    std::vector<StepRun> runs;
    std::size_t first = 0;
    while (first < times.size()) {
        // queue_step's count is 16 bits on the controller.
        const std::size_t left = std::min<std::size_t>(times.size() - first, 65535);
        StepRun best;
        best.interval_ns = std::max<std::int64_t>(0, times[first] - t_prev_ns);
        best.count = 1;  // a single step always fits exactly
        // The longest run that fits: doubling until one fails, then bisecting between.
        auto fits = [&](std::size_t count) {
            StepRun r;
            if (!fit(times, first, count, t_prev_ns, max_error_ns, r)) return false;
            best = r;
            return true;
        };
        std::size_t good = 1;
        std::size_t bad = 0;
        for (std::size_t count = 2; count <= left; count *= 2) {
            if (!fits(count)) {
                bad = count;
                break;
            }
            good = count;
        }
        if (bad == 0 && good < left) (fits(left) ? good : bad) = left;
        while (bad > good + 1) {
            const std::size_t mid = good + (bad - good) / 2;
            (fits(mid) ? good : bad) = mid;
        }
        // The run's last reproduced step (StepRun's formula with k = count): the next run starts there.
        const auto count = static_cast<std::int64_t>(best.count);
        t_prev_ns += count * best.interval_ns + count * (count - 1) / 2 * best.add_ns;
        runs.push_back(best);
        first += good;
    }
    return runs;
}

}  // namespace nckit
