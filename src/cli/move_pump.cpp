#include "move_pump.hpp"

namespace nckit::cli {

MovePump::MovePump(Interpreter& interpreter) : interpreter_(interpreter), thread_([this] { produce(); }) {}

MovePump::~MovePump() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    changed_.notify_all();
    thread_.join();
}

void MovePump::produce() {
    for (bool last = false; !last;) {
        std::vector<InterpResult> batch;
        batch.reserve(batch_size);
        while (batch.size() < batch_size) {
            batch.push_back(interpreter_.next());
            if (!std::holds_alternative<Move>(batch.back())) {
                last = true;
                break;
            }
        }
        offset_read_.store(interpreter_.main_program_offset(), std::memory_order_relaxed);
        std::unique_lock lock(mutex_);
        changed_.wait(lock, [&] { return stopping_ || batches_.size() < max_batches_in_flight; });
        if (stopping_) return;
        batches_.push_back(std::move(batch));
        done_ = last;
        changed_.notify_all();
    }
}

std::vector<InterpResult> MovePump::next_batch() {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return !batches_.empty() || done_; });
    if (batches_.empty()) return {};
    std::vector<InterpResult> batch = std::move(batches_.front());
    batches_.pop_front();
    changed_.notify_all();
    return batch;
}

}  // namespace nckit::cli
