#pragma once
// Restarting a program in the middle (after a power cut or a broken tool): the program runs in
// search mode up to a target block, then a new program is written that rebuilds the state the
// rest depends on, brings the tool back to where the target block starts, and goes on with the
// rest of the original run as plain absolute moves (docs/restart.md).
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "nckit/core/axes.hpp"
#include "nckit/core/result.hpp"
#include "nckit/interp/interpreter.hpp"
#include "nckit/interp/modal_view.hpp"
#include "nckit/interp/restart_state.hpp"

namespace nckit {

//! Where to restart: the k-th time sequence number N is reached, the k-th time a block of the
//! main program's source line L runs, or the B-th executed block. Only blocks that make a move
//! or an I/O event count; a block run again in a loop or a call counts again.
struct RestartTarget {
    enum class Kind { sequence, line, block };
    Kind kind = Kind::block;
    std::int64_t number = 1;      //!< N, L or B
    std::int64_t occurrence = 1;  //!< k (sequence and line)
};

struct RestartReport {
    SourceLocation where;  //!< the target block
    std::int64_t sequence_number = -1;
    std::int64_t block = 0;         //!< the target's ordinal among executed blocks, 1-based
    std::int64_t first_record = 0;  //!< index of its first move in the original run, 0-based
    std::uint32_t rest_line = 0;    //!< line of the restart program where the rest begins
    ModalView state;                //!< modal state in force before the target block
    RestartIo io;
    RestartApproach approach;
    double worst_deviation_mm = 0;           //!< with rounding (decimals >= 0)
    std::vector<RetainedVariable> retained;  //!< #500-#999 as the blocks before the target left them
};

struct RestartSettings {
    int decimals = -1;  //!< < 0: coordinates exact (see GcodeWriter::round_to_decimals)
    //! From a run journal: #500-#999 as the interrupted run left them before the target. The
    //! search must arrive at the same values (else `restart-journal-mismatch`); the preamble
    //! sets them and the rest sets them again wherever the original run changed them.
    std::optional<std::vector<RetainedVariable>> retained_at_target;
};

//! Runs `interpreter` from its start to the target without motion and writes the restart
//! program into `out`. Refuses a target inside cutter compensation or in the middle of a thread
//! (the error names the block and, for a thread, the pass's first block), or one never reached.
[[nodiscard]] Result<RestartReport> write_restart(Interpreter& interpreter, const RestartTarget& target,
                                                  const std::string& source_name, std::string& out,
                                                  const RestartSettings& settings = {});

}  // namespace nckit
