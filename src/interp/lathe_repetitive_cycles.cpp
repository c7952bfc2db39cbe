// The multiple repetitive cycles of a Fanuc lathe that follow a finishing shape, the blocks
// N p .. N q (G70 finishing, G73 pattern repeating; G71/G72 roughing in lathe_rough_cycles.cpp).
// The shape is found by running those blocks on a copy of the executor from the cycle's start
// point: the moves it makes are the shape, in machine coordinates, with every mode in force.
//   G70 P Q: the shape as programmed (its F S T count), then a rapid back to the start point.
//   G73 U(relief X) W(relief Z) R(passes); G73 P Q U W F: the shape moved by the relief, then
//   by less each pass, the last pass by the finishing allowance alone; a rapid back each time.
#include <cmath>

#include <fmt/format.h>

#include "executor.hpp"
#include "nckit/interp/arc_geometry.hpp"
#include "lathe_codes.hpp"
#include "lathe_contour.hpp"

namespace nckit::interp {

namespace {
constexpr int max_pattern_passes = 9999;
}  // namespace

std::optional<Diagnostic> Executor::lathe_repetitive_cycle(std::vector<Move>& out) {
    const GCode cycle = words_.group(ModalGroup::non_modal);
    const std::uint32_t column = words_.group_column(ModalGroup::non_modal);
    const std::string name = lathe_code_name(machine_.gcode_system, cycle);
    if (!sequence_reader_) {
        return error(column, "bad-cycle", fmt::format("{} inside the P-Q blocks of another cycle", name));
    }
    if (cycle == lathe_thread_repeat) return thread_cycle(out);
    if (cycle == lathe_face_grooving || cycle == lathe_od_grooving) return groove_cycle(out);
    const bool shape_block = words_.has('P') || words_.has('Q');
    if (shape_block && !(words_.has('P') && words_.has('Q'))) {
        return error(column, "missing-word",
                     fmt::format("{} needs both P and Q (first and last block of the shape)", name));
    }
    if (cycle == lathe_finish) {
        if (!shape_block) return error(column, "missing-word", fmt::format("{} needs P and Q", name));
        return finish_cycle(out);
    }
    if (cycle == lathe_rough_turning || cycle == lathe_rough_facing || cycle == lathe_pattern_repeat) {
        if (!shape_block) return lathe_cycle_settings();
        return cycle == lathe_pattern_repeat ? pattern_cycle(out) : rough_cycle(out);
    }
    return error(column, "unsupported-gcode", fmt::format("{} is not supported", name));
}

std::optional<Diagnostic> Executor::lathe_cycle_settings() {
    const GCode cycle = words_.group(ModalGroup::non_modal);
    const std::string name = lathe_code_name(machine_.gcode_system, cycle);
    LatheCycleSettings& settings = modal_.lathe.settings;
    // D I K belong to the one-block forms (G71 P Q U W D, G73 P Q I K U W D), which name P and Q.
    for (const char c : {'D', 'I', 'K'}) {
        if (const Word* stray = words_.word(c)) {
            return error(stray->column, "unused-word",
                         fmt::format("{}'s first block takes no {} (the one-block form names P and Q)", name, c));
        }
    }
    auto positive = [&](const Word* word, double& into, const char* what) -> std::optional<Diagnostic> {
        if (word == nullptr) return std::nullopt;
        const double value = offset_value(*word);
        if (value <= 0) {
            return error(word->column, "bad-value",
                         fmt::format("{} {} ({}) must be positive", name, word->letter, what));
        }
        into = value;
        return std::nullopt;
    };
    if (cycle == lathe_pattern_repeat) {
        if (const Word* u = cycle_word('U')) settings.relief_x_mm = offset_value(*u);
        if (const Word* w = cycle_word('W')) settings.relief_z_mm = offset_value(*w);
        if (const Word* r = words_.word('R')) {
            if (r->value < 1 || r->value > max_pattern_passes || r->value != std::floor(r->value)) {
                return error(
                    r->column, "bad-value",
                    fmt::format("{} R (passes) must be a whole number from 1 to {}", name, max_pattern_passes));
            }
            settings.divisions = static_cast<int>(r->value);
        }
        return std::nullopt;
    }
    const char depth_letter = cycle == lathe_rough_turning ? 'U' : 'W';
    const char other = cycle == lathe_rough_turning ? 'W' : 'U';
    if (const Word* stray = cycle_word(other)) {
        return error(stray->column, "unused-word", fmt::format("{}'s first block takes no {}", name, other));
    }
    if (auto e = positive(cycle_word(depth_letter), settings.rough_depth_mm, "depth of cut")) return e;
    if (const Word* r = words_.word('R')) {
        if (r->value < 0) return error(r->column, "bad-value", fmt::format("{} R (escape) must not be negative", name));
        settings.retract_mm = offset_value(*r);
    }
    return std::nullopt;
}

std::optional<Diagnostic> Executor::run_pq_blocks(PqShape& shape) {
    const Word* p_word = words_.word('P');
    const Word* q_word = words_.word('Q');
    for (const Word* word : {p_word, q_word}) {
        if (word->value < 1 || word->value > 99999 || word->value != std::floor(word->value)) {
            return error(word->column, "bad-value",
                         fmt::format("{} must be a sequence number 1 to 99999", word->letter));
        }
    }
    std::vector<Block> blocks;
    if (auto e = sequence_reader_(static_cast<std::int64_t>(p_word->value), static_cast<std::int64_t>(q_word->value),
                                  blocks)) {
        if (e->location.file == nullptr) {
            // Fanuc alarm PS0063: the block P or Q names is not in the program.
            const Word* missing = e->message.find("after") != std::string::npos ? q_word : p_word;
            return error(missing->column, e->code, e->message);
        }
        return e;
    }
    Executor runner(*this);
    runner.sequence_reader_ = nullptr;  // a cycle inside the shape is an error there
    runner.modal_.lathe.single = LatheSingleCycle{};
    shape = PqShape{};
    if (!blocks.empty()) {
        for (const Word& word : blocks.front().words) shape.p_letters.push_back(word.letter);
    }
    for (std::size_t i = 0; i < blocks.size(); ++i) {
        bool program_end = false;
        if (auto e = runner.run(blocks[i], shape.moves, program_end)) return e;
        if (program_end) return error_at(blocks[i].location, "bad-cycle", "M2/M30 inside a cycle's P-Q blocks");
    }
    if (auto e = runner.end_program(shape.moves)) return e;
    // The P block's moves lead; counted by their block, since nose radius compensation holds a
    // block's move back until the next block settles its corner.
    if (!blocks.empty()) {
        const SourceLocation& p_block = blocks.front().location;
        while (shape.approach_moves < shape.moves.size() &&
               shape.moves[shape.approach_moves].where.line == p_block.line &&
               shape.moves[shape.approach_moves].where.file_name() == p_block.file_name()) {
            ++shape.approach_moves;
        }
    }
    return std::nullopt;
}

std::optional<Diagnostic> Executor::feed_arc(Arc arc, std::vector<Move>& out) {
    arc.feed = current_feed();
    arc.path = modal_.path;
    AxisBox box = arc_bounds(arc);
    if (auto e = check_travel(box.low, box.high)) return e;
    push(out, arc);
    position_ = arc.to;
    return std::nullopt;
}

std::optional<Diagnostic> Executor::finish_cycle(std::vector<Move>& out) {
    const AxisVector start = position_;
    PqShape shape;
    if (auto e = run_pq_blocks(shape)) return e;
    for (Move& move : shape.moves) {
        if (auto end = move_end(move)) position_ = *end;
        if (const auto* sync = std::get_if<SyncMove>(&move.what)) position_ = sync->to;
        out.push_back(std::move(move));
    }
    return straight(g(0), start, out);
}

std::optional<Diagnostic> Executor::pattern_cycle(std::vector<Move>& out) {
    const std::string name = lathe_code_name(machine_.gcode_system, lathe_pattern_repeat);
    LatheCycleSettings settings = modal_.lathe.settings;
    if (const Word* r = words_.word('R')) {
        return error(
            r->column, "unused-word",
            fmt::format("{} P Q takes no R: the number of passes is R of the block {} U W R, or D here", name, name));
    }
    // The one-block form of Fanuc's Series 15 and of Haas: G73 P Q I(relief X, radius) K(relief Z)
    // U W D(passes). Its words hold for this cycle alone; the block G73 U W R is not changed.
    const Word* relief_x = words_.word('I');
    const Word* relief_z = words_.word('K');
    if (const Word* d = words_.word('D')) {
        if (d->value < 1 || d->value > max_pattern_passes || d->value != std::floor(d->value)) {
            return error(d->column, "bad-value",
                         fmt::format("{} D (passes) must be a whole number from 1 to {}", name, max_pattern_passes));
        }
        settings.divisions = static_cast<int>(d->value);
        settings.relief_x_mm = relief_x != nullptr ? offset_value(*relief_x) : 0.0;
        settings.relief_z_mm = relief_z != nullptr ? offset_value(*relief_z) : 0.0;
    } else if (relief_x != nullptr || relief_z != nullptr) {
        return error((relief_x != nullptr ? relief_x : relief_z)->column, "missing-word",
                     fmt::format("{} P Q with I K (relief) needs D, the number of passes", name));
    }
    if (settings.divisions < 1) {
        return error(
            words_.group_column(ModalGroup::non_modal), "missing-word",
            fmt::format("{} needs its number of passes first: a block {} U W R (or D in this block)", name, name));
    }
    const AxisVector start = position_;
    AxisVector allowance;
    if (const Word* u = cycle_word('U')) allowance[Axis::X] = axis_value(Axis::X, *u);
    if (const Word* w = cycle_word('W')) allowance[Axis::Z] = axis_value(Axis::Z, *w);
    PqShape pq;
    if (auto e = run_pq_blocks(pq)) return e;
    const std::vector<Move>& shape = pq.moves;
    const std::size_t approach = pq.approach_moves;
    const Line* in = nullptr;  // the P block's move, its S T M events aside
    for (std::size_t i = 0; i < approach; ++i) {
        if (const auto* line = std::get_if<Line>(&shape[i].what)) in = line;
    }
    if (in == nullptr || approach >= shape.size()) {
        return error(column_of('P'), "bad-cycle", fmt::format("{}: the P block must move to the shape's start", name));
    }
    const std::optional<AxisVector> first = in->to;
    const bool rapid_in = in->rapid;
    const int passes = settings.divisions;
    for (int pass = 1; pass <= passes; ++pass) {
        // Relief shrinks evenly: the full relief on pass 1, none on the last one.
        const double left = passes == 1 ? 0.0 : static_cast<double>(passes - pass) / (passes - 1);
        AxisVector shift = allowance;
        shift[Axis::X] += settings.relief_x_mm * left;
        shift[Axis::Z] += settings.relief_z_mm * left;
        if (auto e = straight(rapid_in ? g(0) : g(1), *first + shift, out)) return e;
        for (std::size_t i = approach; i < shape.size(); ++i) {
            Move moved = shifted(shape[i], shift);
            if (auto* line = std::get_if<Line>(&moved.what)) {
                if (auto e = straight(line->rapid ? g(0) : g(1), line->to, out)) return e;
            } else if (auto* arc = std::get_if<Arc>(&moved.what)) {
                if (auto e = feed_arc(*arc, out)) return e;
            }
        }
        if (auto e = straight(g(0), start, out)) return e;
    }
    skip_past_sequence_ = true;
    return std::nullopt;
}

}  // namespace nckit::interp
