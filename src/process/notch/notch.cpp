// The notch job in passes over the program (see run_notch_job), and the same job on a move list
// held in memory.
#include <algorithm>
#include <iterator>
#include <variant>

#include "nckit/gcode/program_source.hpp"
#include "nckit/interp/interpreter.hpp"
#include "nckit/interp/move_gcode.hpp"
#include "nckit/plan/planner.hpp"
#include "nckit/process/notch/notch.hpp"
#include "notch_passes.hpp"

namespace nckit {

namespace {

using notch_detail::CutRecord;
using notch_detail::CutRecords;

//! Runs `reader` to its end, handing each move to `on_move`; the diagnostic that stopped it.
Diagnostics each_move(MoveReader& reader, const std::function<void(const Move&)>& on_move) {
    for (;;) {
        InterpResult result = reader();
        if (std::holds_alternative<ProgramEnd>(result)) return {};
        if (auto* diagnostic = std::get_if<Diagnostic>(&result)) return {std::move(*diagnostic)};
        on_move(std::get<Move>(result));
    }
}

//! A program's trajectory piece by piece: its moves pulled through a planner as needed.
class PieceStream {
public:
    PieceStream(MoveReader reader, const MachineConfig& machine) : reader_(std::move(reader)), planner_(machine) {}

    //! The next piece; false at the end or on an error (then diagnostics is not empty).
    bool next(TrajectoryPiece& piece) {
        for (;;) {
            if (planner_.pop(piece)) return true;
            if (ended_ || !diagnostics_.empty()) return false;
            InterpResult result = reader_();
            if (std::holds_alternative<ProgramEnd>(result)) {
                planner_.finish();
                ended_ = true;
            } else if (auto* diagnostic = std::get_if<Diagnostic>(&result)) {
                diagnostics_.push_back(std::move(*diagnostic));
            } else {
                planner_.push(std::get<Move>(result));
                if (!planner_.diagnostics().empty()) diagnostics_ = planner_.diagnostics();
            }
        }
    }
    [[nodiscard]] const Diagnostics& diagnostics() const { return diagnostics_; }

private:
    MoveReader reader_;
    Planner planner_;
    bool ended_ = false;
    Diagnostics diagnostics_;
};

//! Pass 3's source of cut records after the first window: a further run of the original
//! program through a CutFinder, pulled as far as the next record needs.
class CutSource {
public:
    CutSource(MoveReader reader, const MachineConfig& machine, const NotchOptions& options)
        : reader_(std::move(reader)),
          finder_(machine, options, [this](CutRecord&& cut) { ready_.push_back(std::move(cut)); }) {}

    //! The next record; false at the end (or on an error: then diagnostics is not empty).
    bool next(CutRecord& out) {
        while (ready_.empty() && !ended_) {
            InterpResult result = reader_();
            if (std::holds_alternative<ProgramEnd>(result)) {
                finder_.finish();
                ended_ = true;
            } else if (auto* diagnostic = std::get_if<Diagnostic>(&result)) {
                diagnostics_.push_back(std::move(*diagnostic));
                ended_ = true;
            } else {
                finder_.add(std::get<Move>(result));
            }
        }
        if (ready_.empty()) return false;
        out = std::move(ready_.front());
        ready_.pop_front();
        return true;
    }
    [[nodiscard]] const Diagnostics& diagnostics() const { return diagnostics_; }

private:
    MoveReader reader_;
    CutRecords ready_;
    notch_detail::CutFinder finder_;
    bool ended_ = false;
    Diagnostics diagnostics_;
};

//! Pass 3: both trajectories side by side, each cut handed out once measured on both. Each
//! stream is pulled only as far as the next cut in order needs, so measurements wait in memory
//! only for the few cuts one stream is ahead of the other. The window holds two chunks of cuts
//! and moves on by one once the first is handed out; `source` fills it (nothing when the first
//! window holds every cut).
NotchRunStatus measure_cuts(notch_detail::CutWindow& window, std::size_t count, CutSource* source, PieceStream& before,
                            PieceStream& after, const NotchStreams& streams, const NotchOptions& options) {
    const std::size_t chunk = std::max<std::size_t>(options.cuts_per_chunk, 1);
    auto fill = [&]() {
        CutRecord record;
        while (source != nullptr && window.records.size() < 2 * chunk && source->next(record)) {
            window.records.push_back(std::move(record));
        }
        window.reindex();
        return source == nullptr || source->diagnostics().empty();
    };
    if (!fill()) return {source->diagnostics()};
    notch_detail::CutMeter before_meter(window, options);
    notch_detail::CutMeter after_meter(window, options);
    TrajectoryPiece piece;
    // Pulls one piece into `meter`; false when the stream failed.
    auto pull = [&piece](PieceStream& stream, notch_detail::CutMeter& meter, bool& ended) {
        if (stream.next(piece)) {
            meter.add(piece);
            return true;
        }
        if (!stream.diagnostics().empty()) return false;
        meter.finish();
        ended = true;
        return true;
    };
    bool before_ended = false;
    bool after_ended = false;
    for (std::size_t c = 0; c < count; ++c) {
        if (c == window.base + chunk) {
            // The first chunk is handed out (no meter looks at its cuts again): the next one in.
            window.records.erase(window.records.begin(), window.records.begin() + static_cast<std::ptrdiff_t>(chunk));
            window.base += chunk;
            if (!fill()) return {source->diagnostics()};
        }
        if (c >= window.base + window.records.size()) break;  // the program changed between passes
        while (!before_meter.done(c)) {
            if (!pull(before, before_meter, before_ended)) return {before.diagnostics()};
        }
        while (!after_meter.done(c)) {
            if (!pull(after, after_meter, after_ended)) return {after.diagnostics()};
        }
        NotchCut cut = window.at(c).info;
        cut.before = before_meter.take(c);
        cut.after = after_meter.take(c);
        if (streams.on_cut) streams.on_cut(std::move(cut));
    }
    // The rest of both programs: an error there still fails the job.
    while (!before_ended) {
        if (!pull(before, before_meter, before_ended)) return {before.diagnostics()};
    }
    while (!after_ended) {
        if (!pull(after, after_meter, after_ended)) return {after.diagnostics()};
    }
    return {};
}

}  // namespace

NotchRunStatus run_notch_job(const MachineConfig& machine, const std::string& source_name, const NotchStreams& streams,
                             const NotchOptions& options) {
    const std::size_t chunk = std::max<std::size_t>(options.cuts_per_chunk, 1);
    // Pass 1: the cuts (counted; the first chunk kept, with the cut after it), and whether the
    // planner takes the program (its errors must come before any output, and pass 3 hands out
    // cuts as it goes).
    std::optional<MoveReader> reader = streams.original();
    if (!reader) return {{}, true};
    std::size_t count = 0;
    CutRecords window;
    auto keep_from = [&](std::size_t first) {
        return [&, first](CutRecord&& cut) {
            if (count >= first && count <= first + chunk) window.push_back(std::move(cut));
            ++count;
        };
    };
    std::optional<notch_detail::CutFinder> finder(std::in_place, machine, options, keep_from(0));
    Planner check_planner(machine);
    TrajectoryPiece discard;
    Diagnostics failed = each_move(*reader, [&](const Move& move) {
        finder->add(move);
        if (!check_planner.diagnostics().empty()) return;
        check_planner.push(move);
        while (check_planner.pop(discard)) {
        }
    });
    if (!failed.empty()) return {failed};
    finder->finish();
    check_planner.finish();
    while (check_planner.pop(discard)) {
    }
    const Diagnostics plan_errors = check_planner.diagnostics();
    const std::size_t total = count;

    // Pass 2: crossings, and the rewritten program (a plain program: absolute machine
    // coordinates, one move per block, rather than the original text with blocks changed:
    // shortening an approach or inserting moves in a program with incremental moves, macros or
    // calls would shift everything after it). The writer's exact decimals keep run-up and overrun
    // points on the cut line (rounded ones would bend it, and the planner would blend the bend).
    // One run of the program per chunk of cuts: each checks its chunk against every move, writes
    // the moves from its first cut's laser-on code to the next chunk's, and keeps the next chunk.
    GcodeWriter writer(machine);
    std::string text;
    writer.append_header(text, source_name);
    Diagnostics errors;
    for (std::size_t base = 0;;) {
        const std::size_t checked = std::min(chunk, total - base);
        const bool last = base + checked >= total;
        reader = streams.original();
        if (!reader) return {{}, true};
        CutRecords next_window;
        std::swap(window, next_window);  // `window` now collects the next chunk
        count = 0;
        finder.emplace(machine, options, keep_from(base + checked));
        notch_detail::ClearanceCheck clearance(next_window, checked, options);
        const std::uint64_t from_move = base == 0 ? 0 : next_window.front().laser_on;
        std::optional<std::uint64_t> until_move;
        if (next_window.size() > checked) until_move = next_window[checked].laser_on;
        notch_detail::NotchEmitter emitter(
            next_window, machine,
            [&](const Move& move) {
                writer.append(text, move);
                if (text.size() >= (1U << 16)) {
                    streams.write_rewritten(text);
                    text.clear();
                }
            },
            from_move, until_move);
        failed = each_move(*reader, [&](const Move& move) {
            if (!last) finder->add(move);
            clearance.add(move);
            if (errors.empty()) emitter.add(move);  // a refused job's program is never read
        });
        if (!failed.empty()) return {failed};
        finder->finish();
        reader.reset();
        Diagnostics chunk_errors = notch_detail::cut_errors(next_window, checked);
        errors.insert(errors.end(), std::make_move_iterator(chunk_errors.begin()),
                      std::make_move_iterator(chunk_errors.end()));
        base += checked;
        if (last) {
            window = std::move(next_window);
            break;
        }
    }
    finder.reset();
    if (!errors.empty()) return {errors};
    if (!plan_errors.empty()) return {plan_errors};
    writer.append_footer(text);
    streams.write_rewritten(text);
    text = std::string();

    // Pass 3: "after" is measured on the program as written, read back like any program. When
    // the cuts fill more than a chunk, a further run of the original hands them to the window.
    std::optional<MoveReader> rewritten = streams.rewritten();
    if (!rewritten) return {{}, true};
    reader = streams.original();
    if (!reader) return {{}, true};
    std::optional<CutSource> source;
    notch_detail::CutWindow cut_window;
    if (total <= chunk) {
        cut_window.records = std::move(window);
    } else {
        std::optional<MoveReader> cuts_reader = streams.original();
        if (!cuts_reader) return {{}, true};
        source.emplace(std::move(*cuts_reader), machine, options);
    }
    if (streams.on_checked && !streams.on_checked(total)) return {{}, true};
    PieceStream before(std::move(*reader), machine);
    PieceStream after(std::move(*rewritten), machine);
    return measure_cuts(cut_window, total, source ? &*source : nullptr, before, after, streams, options);
}

namespace {

std::function<std::optional<MoveReader>()> reader_over(const std::vector<Move>& moves) {
    return [&moves]() -> std::optional<MoveReader> {
        return MoveReader([&moves, i = std::size_t{0}]() mutable -> InterpResult {
            if (i == moves.size()) return ProgramEnd{};
            return moves[i++];
        });
    };
}

}  // namespace

Result<NotchJob> notch_program(const std::vector<Move>& moves, const MachineConfig& machine,
                               const std::string& source_name, const NotchOptions& options) {
    NotchJob job;
    NotchStreams streams;
    streams.original = reader_over(moves);
    streams.write_rewritten = [&job](std::string_view text) { job.program += text; };
    std::shared_ptr<Interpreter> reread;
    streams.rewritten = [&]() -> std::optional<MoveReader> {
        reread =
            std::make_shared<Interpreter>(machine, ProgramSource::from_string(job.program, source_name + " (notched)"));
        return MoveReader([reread] { return reread->next(); });
    };
    streams.on_cut = [&job](NotchCut&& cut) { job.cuts.push_back(std::move(cut)); };
    NotchRunStatus status = run_notch_job(machine, source_name, streams, options);
    if (!status.ok()) return std::move(status.diagnostics);
    return job;
}

Result<NotchRewrite> rewrite_notches(const std::vector<Move>& moves, const MachineConfig& machine,
                                     const NotchOptions& options) {
    CutRecords cuts;
    notch_detail::CutFinder finder(machine, options, [&cuts](CutRecord&& cut) { cuts.push_back(std::move(cut)); });
    for (const Move& move : moves) finder.add(move);
    finder.finish();
    NotchRewrite out;
    notch_detail::ClearanceCheck clearance(cuts, cuts.size(), options);
    notch_detail::NotchEmitter emitter(cuts, machine, [&out](const Move& move) { out.moves.push_back(move); });
    for (const Move& move : moves) {
        clearance.add(move);
        emitter.add(move);
    }
    Diagnostics errors = notch_detail::cut_errors(cuts, cuts.size());
    if (!errors.empty()) return errors;
    for (CutRecord& cut : cuts) out.cuts.push_back(std::move(cut.info));
    return out;
}

}  // namespace nckit
