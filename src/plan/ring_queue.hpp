#pragma once
// A first-in first-out queue that reuses its storage (the look-ahead window, the chain smoother).
#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace nckit::plan_detail {

//! A FIFO on one growing ring buffer. std::deque allocates a block per 512 bytes, i.e. one per
//! element for pieces, window segments and the chain smoother's moves; this reuses its storage,
//! so a streaming planner allocates nothing per move once the window has filled.
template <class T>
class RingQueue {
public:
    [[nodiscard]] bool empty() const { return size_ == 0; }
    [[nodiscard]] std::size_t size() const { return size_; }
    T& operator[](std::size_t i) { return slots_[(head_ + i) & mask_]; }
    const T& operator[](std::size_t i) const { return slots_[(head_ + i) & mask_]; }
    T& front() { return slots_[head_]; }
    T& back() { return (*this)[size_ - 1]; }
    const T& back() const { return (*this)[size_ - 1]; }
    void push_back(T&& value) {
        if (size_ == slots_.size()) grow();
        (*this)[size_] = std::move(value);
        ++size_;
    }
    void push_back(const T& value) {
        // Copied first only when the storage moves (value may be one of the elements).
        if (size_ == slots_.size()) {
            push_back(T(value));
            return;
        }
        (*this)[size_] = value;
        ++size_;
    }
    //! The slot a push_back would fill, now counted in: it holds a stale (moved-from) value that
    //! the caller must overwrite field by field. Saves building a large value and moving it in.
    T& push_back_slot() {
        if (size_ == slots_.size()) grow();
        ++size_;
        return back();
    }
    void pop_front() {
        head_ = (head_ + 1) & mask_;
        --size_;
    }

private:
    void grow() {
        std::vector<T> bigger(std::max<std::size_t>(16, 2 * slots_.size()));
        for (std::size_t i = 0; i < size_; ++i) bigger[i] = std::move((*this)[i]);
        slots_ = std::move(bigger);
        mask_ = slots_.size() - 1;
        head_ = 0;
    }
    std::vector<T> slots_;
    std::size_t head_ = 0;
    std::size_t size_ = 0;
    std::size_t mask_ = 0;
};

}  // namespace nckit::plan_detail
