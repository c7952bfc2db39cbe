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

//! Pass 1: finds the cuts as the moves go by (a laser-on M-code, then a straight feed move) and
//! places each run-up and overrun. Holds the last motion and the cuts found, nothing else.
class CutFinder {
public:
    CutFinder(const MachineConfig& machine, const NotchOptions& options);
    void add(const Move& move);
    [[nodiscard]] CutRecords take() { return std::move(cuts_); }

private:
    void start_cut(std::uint64_t laser_on, int laser_on_mcode, const Move& move);

    const MachineConfig& machine_;
    std::optional<int> sync_off_;
    std::uint64_t index_ = 0;
    std::optional<std::pair<std::uint64_t, Move>> last_motion_;
    std::optional<std::pair<std::uint64_t, int>> laser_on_;  // the previous move, when a laser-on code
    CutRecords cuts_;
};

//! Pass 2a: every run-up and overrun against every other move's path, the moves streamed once;
//! fills each record's first crossing.
class ClearanceCheck {
public:
    ClearanceCheck(CutRecords& cuts, const NotchOptions& options);
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

//! The errors of the checked cuts, in cut order (per cut: its local error, else the run-up's
//! crossing, else the overrun's).
[[nodiscard]] Diagnostics cut_errors(const CutRecords& cuts);

//! Pass 2b: the rewritten moves, as the original moves go by (the cuts are known from pass 1).
class NotchEmitter {
public:
    NotchEmitter(const CutRecords& cuts, const MachineConfig& machine, std::function<void(const Move&)> out);
    void add(const Move& move);

private:
    void emit_back(const CutRecord& cut);

    const CutRecords& cuts_;
    std::optional<int> sync_off_;
    std::function<void(const Move&)> out_;
    std::size_t next_cut_ = 0;
    std::uint64_t index_ = 0;
};

//! Pass 3: the speed along every cut, the trajectory's pieces streamed once, each cut measured
//! from its first piece on the cut line to the first motion piece off it. A cut's measurement
//! is done once that piece has come (or the trajectory has ended).
class CutMeter {
public:
    CutMeter(const CutRecords& cuts, const NotchOptions& options);
    ~CutMeter();
    CutMeter(const CutMeter&) = delete;
    CutMeter& operator=(const CutMeter&) = delete;
    void add(const TrajectoryPiece& piece);
    void finish();
    [[nodiscard]] bool done(std::size_t cut) const { return state_[cut] == State::done; }
    //! The finished measurement of `cut` (once).
    [[nodiscard]] CutSpeed take(std::size_t cut);

private:
    enum class State : std::uint8_t { waiting, active, done };
    struct Active;
    const CutRecords& cuts_;
    const NotchOptions& options_;
    SweepIndex index_;
    double margin_mm_ = 0;
    std::vector<State> state_;
    std::vector<Active> active_;
    std::unordered_map<std::size_t, CutSpeed> finished_;
};

}  // namespace nckit::notch_detail
