#pragma once
// Runs an interpreter on a second thread and hands its results out in batches, so that
// interpreting and printing a long program overlap on two cores. The order of the stream is
// kept exactly; memory stays bounded (a few batches in flight).
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <mutex>
#include <thread>
#include <vector>

#include "nckit/interp/interpreter.hpp"

namespace nckit::cli {

class MovePump {
public:
    explicit MovePump(Interpreter& interpreter);
    ~MovePump();
    MovePump(const MovePump&) = delete;
    MovePump& operator=(const MovePump&) = delete;

    //! The next batch of results, in program order; the last batch ends with a ProgramEnd or a
    //! Diagnostic. Empty only after that last batch has been taken.
    [[nodiscard]] std::vector<InterpResult> next_batch();

    //! Share of the main program read by the last batch handed over; -1 when `total_bytes` is 0.
    [[nodiscard]] double fraction_read(std::uint64_t total_bytes) const {
        if (total_bytes == 0) return -1.0;
        return static_cast<double>(offset_read_.load(std::memory_order_relaxed)) / static_cast<double>(total_bytes);
    }

private:
    void produce();

    static constexpr std::size_t batch_size = 1024;
    static constexpr std::size_t max_batches_in_flight = 4;

    Interpreter& interpreter_;
    std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<std::vector<InterpResult>> batches_;
    std::atomic<std::uint64_t> offset_read_{0};
    bool done_ = false;      // the producer has queued its last batch
    bool stopping_ = false;  // the consumer has gone: the producer must stop
    std::thread thread_;
};

}  // namespace nckit::cli
