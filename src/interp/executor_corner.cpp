// Fanuc's corner words `,R` and `,C` on a G1, G2 or G3 block: the block's move is held back
// until the next block's move is known, then both are shortened and the rounding arc or chamfer line put
// between them (corner_round.cpp). The pieces go on to cutter compensation as programmed moves,
// so a compensated contour is offset with its rounded corners.
#include <fmt/format.h>

#include "executor.hpp"

namespace nckit::interp {

namespace {

bool is_motion(const Move& move) {
    return std::holds_alternative<Line>(move.what) || std::holds_alternative<Arc>(move.what) ||
           std::holds_alternative<SyncMove>(move.what);
}

}  // namespace

std::optional<Diagnostic> Executor::check_corner() {
    const Word& corner = block_->corner;
    if (corner.letter == 0) return std::nullopt;
    if (corner.value <= 0) {
        return error(corner.column, "bad-value", fmt::format(",{} must be positive", corner.letter));
    }
    const GCode non_modal = words_.group(ModalGroup::non_modal);
    const bool feeds = motion_ == g(1) || motion_ == g(2) || motion_ == g(3);
    if (!feeds || !block_has_axis_words() || non_modal >= 0) {
        return error(
            corner.column, "bad-corner",
            fmt::format(",{} needs a G1, G2 or G3 move in its block (the corner is at its end point)", corner.letter));
    }
    if (words_.has_m(2) || words_.has_m(30)) {
        return error(corner.column, "bad-corner",
                     fmt::format(",{} needs a move after it, not the end of the program", corner.letter));
    }
    return std::nullopt;
}

std::optional<Diagnostic> Executor::apply_corner(std::vector<Move>& out, std::size_t first, bool program_end) {
    if (corner_) {
        HeldCorner held = std::move(*corner_);
        corner_.reset();
        const auto held_error = [&](std::string message) {
            SourceLocation at = held.location;
            at.column = held.word.column;
            return error_at(at, "bad-corner", fmt::format(",{}{}: {}", held.word.letter, held.word.value, message));
        };
        std::size_t next = first;
        while (next < out.size() && !is_motion(out[next])) ++next;
        if (next == out.size()) return held_error("the next block must move in the plane (G1, G2 or G3)");
        const auto corner_move = [](const Move& move) -> std::optional<CornerMove> {
            if (const Line* line = std::get_if<Line>(&move.what)) return *line;
            if (const Arc* arc = std::get_if<Arc>(&move.what)) return *arc;
            return std::nullopt;
        };
        const std::optional<CornerMove> following = corner_move(out[next]);
        if (!following) return held_error("the next block must move in the plane (G1, G2 or G3)");
        const CornerKind kind = held.kind;
        auto made = make_corner(*corner_move(held.moves.front()), *following, kind, held.size_mm, held.plane);
        if (const std::string* why = std::get_if<std::string>(&made)) return held_error(*why);
        CornerResult& corner = std::get<CornerResult>(made);
        std::visit([&](auto& shortened) { out[next].what = shortened; }, corner.next);
        std::visit([&](auto& shortened) { held.moves.front().what = shortened; }, corner.first);
        Move piece{Line{}, held.moves.front().where, held.moves.front().sequence_number};
        std::visit([&](auto& made_piece) { piece.what = made_piece; }, corner.corner);
        held.moves.push_back(std::move(piece));
        out.insert(out.begin() + static_cast<std::ptrdiff_t>(first), std::make_move_iterator(held.moves.begin()),
                   std::make_move_iterator(held.moves.end()));
        first += held.moves.size();
    }
    const Word& word = block_->corner;
    if (word.letter != 0) {
        std::size_t last = out.size();
        while (last > first && !is_motion(out[last - 1])) --last;
        const Line* line = last > first ? std::get_if<Line>(&out[last - 1].what) : nullptr;
        const bool arc = last > first && std::holds_alternative<Arc>(out[last - 1].what);
        if (!arc && (line == nullptr || line->rapid)) {
            return error(word.column, "bad-corner",
                         fmt::format(",{} needs a G1 line or G2/G3 arc in its block", word.letter));
        }
        HeldCorner held{word,
                        block_->location,
                        word.letter == 'R' ? CornerKind::round : CornerKind::chamfer,
                        offset_value(word),
                        modal_.plane,
                        {}};
        held.moves.assign(std::make_move_iterator(out.begin() + static_cast<std::ptrdiff_t>(last - 1)),
                          std::make_move_iterator(out.end()));
        out.resize(last - 1);
        corner_ = std::move(held);
    }
    if (program_end && corner_) {
        return error(word.column, "bad-corner", ",R / ,C needs a move after it, not the end of the program");
    }
    return std::nullopt;
}

}  // namespace nckit::interp
