// The notch job in passes over the program (see run_notch_job), and the same job on a move list
// held in memory.
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

//! Pass 3: both trajectories side by side, each cut handed out once measured on both. Each
//! stream is pulled only as far as the next cut in order needs, so measurements wait in memory
//! only for the few cuts one stream is ahead of the other.
NotchRunStatus measure_cuts(CutRecords& cuts, PieceStream& before, PieceStream& after, const NotchStreams& streams,
                            const NotchOptions& options) {
    notch_detail::CutMeter before_meter(cuts, options);
    notch_detail::CutMeter after_meter(cuts, options);
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
    for (std::size_t c = 0; c < cuts.size(); ++c) {
        while (!before_meter.done(c)) {
            if (!pull(before, before_meter, before_ended)) return {before.diagnostics()};
        }
        while (!after_meter.done(c)) {
            if (!pull(after, after_meter, after_ended)) return {after.diagnostics()};
        }
        NotchCut cut = std::move(cuts[c].info);
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
    // Pass 1: the cuts, and whether the planner takes the program (its errors must come before
    // any output, and pass 3 hands out cuts as it goes).
    std::optional<MoveReader> reader = streams.original();
    if (!reader) return {{}, true};
    notch_detail::CutFinder finder(machine, options);
    Planner check_planner(machine);
    TrajectoryPiece discard;
    Diagnostics failed = each_move(*reader, [&](const Move& move) {
        finder.add(move);
        if (!check_planner.diagnostics().empty()) return;
        check_planner.push(move);
        while (check_planner.pop(discard)) {
        }
    });
    if (!failed.empty()) return {failed};
    check_planner.finish();
    while (check_planner.pop(discard)) {
    }
    const Diagnostics plan_errors = check_planner.diagnostics();
    CutRecords cuts = finder.take();

    // Pass 2: crossings, and the rewritten program (a plain program: absolute machine
    // coordinates, one move per block, rather than the original text with blocks changed:
    // shortening an approach or inserting moves in a program with incremental moves, macros or
    // calls would shift everything after it). The writer's exact decimals keep run-up and overrun
    // points on the cut line (rounded ones would bend it, and the planner would blend the bend).
    reader = streams.original();
    if (!reader) return {{}, true};
    notch_detail::ClearanceCheck clearance(cuts, options);
    GcodeWriter writer(machine);
    std::string text;
    writer.append_header(text, source_name);
    notch_detail::NotchEmitter emitter(cuts, machine, [&](const Move& move) {
        writer.append(text, move);
        if (text.size() >= (1U << 16)) {
            streams.write_rewritten(text);
            text.clear();
        }
    });
    failed = each_move(*reader, [&](const Move& move) {
        clearance.add(move);
        emitter.add(move);
    });
    if (!failed.empty()) return {failed};
    reader.reset();
    Diagnostics errors = notch_detail::cut_errors(cuts);
    if (!errors.empty()) return {errors};
    if (!plan_errors.empty()) return {plan_errors};
    writer.append_footer(text);
    streams.write_rewritten(text);
    text = std::string();

    // Pass 3: "after" is measured on the program as written, read back like any program.
    std::optional<MoveReader> rewritten = streams.rewritten();
    if (!rewritten) return {{}, true};
    reader = streams.original();
    if (!reader) return {{}, true};
    if (streams.on_checked && !streams.on_checked(cuts.size())) return {{}, true};
    PieceStream before(std::move(*reader), machine);
    PieceStream after(std::move(*rewritten), machine);
    return measure_cuts(cuts, before, after, streams, options);
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
    notch_detail::CutFinder finder(machine, options);
    for (const Move& move : moves) finder.add(move);
    CutRecords cuts = finder.take();
    NotchRewrite out;
    notch_detail::ClearanceCheck clearance(cuts, options);
    notch_detail::NotchEmitter emitter(cuts, machine, [&out](const Move& move) { out.moves.push_back(move); });
    for (const Move& move : moves) {
        clearance.add(move);
        emitter.add(move);
    }
    Diagnostics errors = notch_detail::cut_errors(cuts);
    if (!errors.empty()) return errors;
    for (CutRecord& cut : cuts) out.cuts.push_back(std::move(cut.info));
    return out;
}

}  // namespace nckit
