#pragma once
// The streamed notch job's passes over a program's moves: what each cut keeps between passes,
// and the stages that fill it. Each stage takes the moves (or trajectory pieces) one at a time.
#include <cstdint>
#include <deque>
#include <memory>
#include <functional>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "nckit/core/machine.hpp"
#include "nckit/interp/move.hpp"
#include "nckit/process/notch/notch.hpp"
#include "notch_index.hpp"

namespace nckit::notch_detail {

//! The first move (in program order) whose path a run-up or overrun comes within clearance of.
struct Crossing {
    std::int64_t sequence_number = -1;  //!< its N number, -1 when none
    std::uint32_t line = 0;             //!< its line
};

struct CutRecord;
//! The cuts in program order (a deque: a long program's records grow without the copy and
//! the doubled block of a growing vector).
using CutRecords = std::deque<CutRecord>;

//! One cut as the passes know it: found and placed in pass 1, checked for crossings in pass 2.
//! Indices count the moves of the original program in order, the same in every pass.
struct CutRecord {
    NotchCut info;  //!< before/after stay empty here
    std::uint64_t laser_on = 0;
    std::uint64_t line = 0;                       //!< the cutting move (laser_on + 1)
    std::optional<std::uint64_t> approach;        //!< last motion before the laser-on code
    std::optional<std::uint64_t> next;            //!< first motion after the cut
    std::optional<std::uint64_t> programmed_off;  //!< a laser-off code right after the cut
    AxisVector run_up_point;
    AxisVector overrun_point;
    double overrun_placed_mm = 0;
    std::unique_ptr<Diagnostic> local_error;  //!< no laser-off at speed, or outside the travel (rare: a pointer)
    std::optional<Crossing> run_up_crossing;
    std::optional<Crossing> overrun_crossing;
};

//! The machine's first laser-off M-code that switches without a stop (the rewrite's M128).
[[nodiscard]] std::optional<int> sync_off_mcode(const MachineConfig& machine);

//! Finds the cuts as a run of the program's moves goes by (a laser-on M-code, then a straight
//! feed move) and places each run-up and overrun. Holds the last motion and the cut not yet
//! complete (its next motion not yet seen), nothing else: each complete record goes to `out`,
//! in program order. Pass 1 counts them; later passes keep the chunk they need.
class CutFinder {
public:
    CutFinder(const MachineConfig& machine, const NotchOptions& options, std::function<void(CutRecord&&)> out);
    void add(const Move& move);
    //! The program has ended: the last cut is complete.
    void finish();

private:
    void start_cut(std::uint64_t laser_on, int laser_on_mcode, const Move& move);

    const MachineConfig& machine_;
    std::optional<int> sync_off_;
    std::function<void(CutRecord&&)> out_;
    std::uint64_t index_ = 0;
    std::optional<std::pair<std::uint64_t, Move>> last_motion_;
    std::optional<std::pair<std::uint64_t, int>> laser_on_;  // the previous move, when a laser-on code
    std::optional<CutRecord> open_;                          // the last cut, before its next motion
};

//! Pass 2a: the run-ups and overruns of cuts [0, count) of `cuts` against every other move's
//! path, the moves streamed once; fills each record's first crossing.
class ClearanceCheck {
public:
    ClearanceCheck(CutRecords& cuts, std::size_t count, const NotchOptions& options);
    void add(const Move& move);

private:
    struct Piece {
        std::size_t cut;
        bool run_up;  // else the overrun
    };
    void check(std::uint64_t k, const Move& move, const Piece& piece, const std::vector<AxisVector>& polyline);

    CutRecords& cuts_;
    const NotchOptions& options_;
    std::vector<Piece> pieces_;
    SweepIndex index_;
    std::uint64_t index_k_ = 0;
};

//! The errors of the checked cuts [0, count), in cut order (per cut: its local error, else the
//! run-up's crossing, else the overrun's).
[[nodiscard]] Diagnostics cut_errors(const CutRecords& cuts, std::size_t count);

//! Pass 2b: the rewritten moves, as the original moves go by. `cuts` are the cuts of moves
//! [from_move, until_move) in order, and the first cut after them (its approach, and the return
//! of the cut before, may come before its laser-on code); moves outside that range are not
//! written (another chunk's pass writes them).
class NotchEmitter {
public:
    NotchEmitter(const CutRecords& cuts, const MachineConfig& machine, std::function<void(const Move&)> out,
                 std::uint64_t from_move = 0, std::optional<std::uint64_t> until_move = std::nullopt);
    void add(const Move& move);

private:
    void emit_back(const CutRecord& cut);

    const CutRecords& cuts_;
    std::optional<int> sync_off_;
    std::function<void(const Move&)> out_;
    std::uint64_t from_move_;
    std::optional<std::uint64_t> until_move_;
    std::size_t next_cut_ = 0;
    std::uint64_t index_ = 0;
};

//! Pass 3's cuts: the records from cut `base` on (at most two chunks), with an index of their
//! lines. The job slides it on by a chunk once the first chunk's cuts are handed out, so a cut
//! is looked for on the trajectory from at least a chunk of cuts before its own.
struct CutWindow {
    CutRecords records;
    std::size_t base = 0;  //!< the cut number of records.front()
    SweepIndex lines;      //!< records[i]'s cut line is segment i
    //! A piece on a cut lies within on_line_mm of its line, off by at most on_line_mm·|rate| on
    //! one axis: a query's pad covers the largest rate of any cut in the window.
    double margin_mm = 0;
    //! After records changed: the index and margin over them.
    void reindex();
    [[nodiscard]] const CutRecord& at(std::size_t cut) const { return records[cut - base]; }
};

//! Pass 3: the speed along every cut of the window, the trajectory's pieces streamed once,
//! each cut measured from its first piece on the cut line to the first motion piece off it. A
//! cut's measurement is done once that piece has come (or the trajectory has ended); the cuts
//! are taken in order.
class CutMeter {
public:
    CutMeter(const CutWindow& window, const NotchOptions& options);
    ~CutMeter();
    CutMeter(const CutMeter&) = delete;
    CutMeter& operator=(const CutMeter&) = delete;
    void add(const TrajectoryPiece& piece);
    void finish();
    [[nodiscard]] bool done(std::size_t cut) const { return ended_ || finished_.count(cut) != 0; }
    //! The finished measurement of `cut` (once, in cut order).
    [[nodiscard]] CutSpeed take(std::size_t cut);

private:
    struct Active;
    const CutWindow& window_;
    const NotchOptions& options_;
    std::size_t next_take_ = 0;                // cuts before it are handed out: never measured again
    std::unordered_set<std::size_t> started_;  // active or finished, not yet taken
    std::vector<Active> active_;
    std::unordered_map<std::size_t, CutSpeed> finished_;
    bool ended_ = false;
};

}  // namespace nckit::notch_detail
