// The modes in force at power-up: a lathe G-code system starts with feed per revolution (Fanuc's
// parameter FPM = 0), then the machine file's `startup_gcodes` run as a block of their own before
// the program, as LinuxCNC's RS274NGC_STARTUP_CODE and a Fanuc control's parameters set them.
#include <fmt/format.h>

#include "executor.hpp"
#include "nckit/gcode/parser.hpp"

namespace nckit::interp {

std::optional<Diagnostic> Executor::start() {
    if (machine_.gcode_system != GCodeSystem::none) modal_.feed_mode = FeedMode::per_revolution;
    if (machine_.startup_gcodes.empty()) return std::nullopt;
    Block block;
    block.location = machine_.startup_gcodes_at;
    if (auto e = parse_block(machine_.startup_gcodes, block)) {
        e->location = machine_.startup_gcodes_at;
        e->message = "startup_gcodes: " + e->message;
        return e;
    }
    // Columns point into the machine file: the string starts one past its opening quote.
    for (Word& word : block.words) word.column += machine_.startup_gcodes_at.column;
    for (const Word& word : block.words) {
        if (word.letter != 'G' || word.expr >= 0) {
            return error_at(block.at_column(word.column), "config-value",
                            fmt::format("startup_gcodes holds G codes only, not {}", word.letter));
        }
    }
    if (block.statement.kind != StatementKind::none) {
        return error_at(block.location, "config-value", "startup_gcodes holds G codes only");
    }
    block_ = &block;
    if (auto e = collect_words(block, words_, machine_.gcode_system, machine_.dialect)) return e;
    if (words_.group(ModalGroup::non_modal) >= 0 || words_.group(ModalGroup::exact_stop) >= 0) {
        return error(words_.group_column(ModalGroup::non_modal) + words_.group_column(ModalGroup::exact_stop),
                     "config-value", "startup_gcodes holds modal codes only");
    }
    std::vector<Move> events;  // a power-up sets modes; it makes no moves and no events
    bool program_end = false;
    auto e = run(block, events, program_end);
    block_ = nullptr;
    elapsed_s_ = 0;
    return e;
}

}  // namespace nckit::interp
