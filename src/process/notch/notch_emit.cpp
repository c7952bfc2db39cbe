// Pass 2b of the notch job: the rewritten moves, written as the original moves go by. Each cut
// becomes: (a step back to the run-up point, unless the approach ends there,) the laser-on
// code, the run-up, the cut at speed, the laser-off code that switches at speed, the overrun
// to rest, (the programmed laser-off,) and a rapid back to the programmed end.
#include "notch_geometry.hpp"
#include "notch_passes.hpp"

namespace nckit::notch_detail {

NotchEmitter::NotchEmitter(const CutRecords& cuts, const MachineConfig& machine, std::function<void(const Move&)> out,
                           std::uint64_t from_move, std::optional<std::uint64_t> until_move)
    : cuts_(cuts),
      sync_off_(sync_off_mcode(machine)),
      out_(std::move(out)),
      from_move_(from_move),
      until_move_(until_move) {}

void NotchEmitter::add(const Move& move) {
    const std::uint64_t k = index_++;
    if (k < from_move_ || (until_move_ && k >= *until_move_)) return;
    const CutRecord* cut = next_cut_ < cuts_.size() ? &cuts_[next_cut_] : nullptr;
    if (cut == nullptr || k < cut->laser_on) {
        // A plain move; the approach of a cut whose run-up lies on it ends at the run-up point.
        if (cut != nullptr && cut->info.approach_shortened && cut->approach == k) {
            Move shortened = move;
            std::get<Line>(shortened.what).to = cut->run_up_point;
            out_(shortened);
            return;
        }
        out_(move);
        return;
    }
    const Move where{Io{}, cut->info.where, cut->info.sequence_number};
    auto placed = [&](const Line& line) { return Move{line, where.where, where.sequence_number}; };
    if (k == cut->laser_on) {
        if (!cut->info.approach_shortened) {
            // The head goes back from the notch start to the run-up point.
            Line back;
            back.from = cut->info.start;
            back.to = cut->run_up_point;
            back.rapid = true;
            out_(placed(back));
        }
        out_(move);
        return;
    }
    if (k == cut->line) {
        const Line& line = std::get<Line>(move.what);
        Line run_up = line;
        run_up.from = cut->run_up_point;
        run_up.to = line.from;
        run_up.path = PathControl{};
        out_(placed(run_up));
        Line stroke = line;
        stroke.path = PathControl{};  // passes the programmed end at speed
        out_(placed(stroke));
        out_(Move{Io{IoKind::mcode, *sync_off_, 0}, where.where, where.sequence_number});
        Line overrun = line;
        overrun.from = line.to;
        overrun.to = cut->overrun_point;
        overrun.path = PathControl{true, 0};  // comes to rest at the overrun's end
        out_(placed(overrun));
        if (!cut->programmed_off) emit_back(*cut);
        return;
    }
    // The programmed laser-off right after the cut: at rest, the beam already off.
    out_(move);
    emit_back(*cut);
}

void NotchEmitter::emit_back(const CutRecord& cut) {
    ++next_cut_;
    Line back;
    back.from = cut.overrun_point;
    back.to = cut.info.end;
    back.rapid = true;
    // No motion before the next cut's laser-on code: when its run-up lies on its approach (this
    // cut's line), this return is the approach the rewrite shortens.
    if (next_cut_ < cuts_.size()) {
        const CutRecord& next = cuts_[next_cut_];
        if (next.info.approach_shortened && next.approach == cut.line) back.to = next.run_up_point;
    }
    out_(Move{back, cut.info.where, cut.info.sequence_number});
}

}  // namespace nckit::notch_detail
