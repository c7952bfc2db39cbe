#pragma once
// A first-in first-out queue of moves in a ring of reused slots. The chain smoother holds every
// G1 line of a chain and hands each one out again; a std::deque of moves (a few hundred bytes
// each, one or two to a block) allocated and freed a block for nearly every line, about a tenth
// of the planning time of a chain of short lines (BENCHMARKS.md).
#include <cstddef>
#include <utility>
#include <vector>

#include "nckit/interp/move.hpp"

namespace nckit::plan_detail {

class MoveRing {
public:
    [[nodiscard]] bool empty() const { return count_ == 0; }
    [[nodiscard]] Move& front() { return slots_[head_]; }
    void push_back(const Move& move) {
        if (count_ == slots_.size()) grow();
        slots_[(head_ + count_) & (slots_.size() - 1)] = move;
        ++count_;
    }
    void push_back(Move&& move) {
        if (count_ == slots_.size()) grow();
        slots_[(head_ + count_) & (slots_.size() - 1)] = std::move(move);
        ++count_;
    }
    //! Drops the front move (its slot keeps whatever was left in it until it is reused).
    void pop_front() {
        head_ = (head_ + 1) & (slots_.size() - 1);
        --count_;
    }

private:
    //! Twice the slots (a power of two, so an index wraps by masking), the moves in order from
    //! slot 0. A chain holds about 2·chain_half_width lines, so this happens a few times per planner.
    void grow() {
        std::vector<Move> larger(slots_.empty() ? 8 : 2 * slots_.size());
        for (std::size_t k = 0; k < count_; ++k) larger[k] = std::move(slots_[(head_ + k) & (slots_.size() - 1)]);
        slots_ = std::move(larger);
        head_ = 0;
    }

    std::vector<Move> slots_;  //!< size 0 or a power of two
    std::size_t head_ = 0;     //!< slot of the front move
    std::size_t count_ = 0;
};

}  // namespace nckit::plan_detail
