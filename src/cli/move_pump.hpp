#pragma once
// Runs an interpreter on a second thread and hands its results out in batches, so that
// interpreting and printing a long program overlap on two cores. The order of the stream is
// kept exactly; memory stays bounded (a few batches in flight).
#include <condition_variable>
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

private:
    void produce();

    static constexpr std::size_t batch_size = 1024;
    static constexpr std::size_t max_batches_in_flight = 4;

    Interpreter& interpreter_;
    std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<std::vector<InterpResult>> batches_;
    bool done_ = false;      // the producer has queued its last batch
    bool stopping_ = false;  // the consumer has gone: the producer must stop
    std::thread thread_;
};

}  // namespace nckit::cli
