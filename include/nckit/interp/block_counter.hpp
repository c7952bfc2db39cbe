#pragma once
// Numbers the executed blocks of a run as restart and the run journal count them: the moves
// of one refill of the interpreter (Interpreter::output_batch) with the same source file and
// line are one block; a block run again in a loop or a call is a new block. Blocks that only
// set a mode or a variable make no move and get no number (docs/restart.md).
#include <cstdint>
#include <string>

#include "nckit/interp/move.hpp"

namespace nckit {

class BlockCounter {
public:
    //! Notes the next move of the stream, returned while the interpreter's batch was `batch`;
    //! true when it starts a new block (its number is then count()).
    bool note(const Move& move, std::uint64_t batch) {
        const Key key{move.where.file.get(), move.where.line, batch};
        if (count_ > 0 && key == last_) return false;
        last_ = key;
        ++count_;
        return true;
    }
    //! Blocks seen so far: the number of the block of the last move noted, 1-based.
    [[nodiscard]] std::int64_t count() const { return count_; }

private:
    struct Key {
        const std::string* file = nullptr;
        std::uint32_t line = 0;
        std::uint64_t batch = 0;
        bool operator==(const Key&) const = default;
    };
    Key last_;
    std::int64_t count_ = 0;
};

}  // namespace nckit
