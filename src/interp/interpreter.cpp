#include "nckit/interp/interpreter.hpp"

#include "executor.hpp"
#include "nckit/gcode/parser.hpp"

namespace nckit {

namespace {
bool starts_with_block_delete(std::string_view line) {
    std::size_t i = line.find_first_not_of(" \t");
    return i != std::string_view::npos && line[i] == '/';
}
}  // namespace

struct Interpreter::State {
    State(MachineConfig m, ProgramSource s, InterpreterOptions o)
        : machine(std::move(m)), source(std::move(s)), options(o), executor(machine, options) {}

    //! Reads blocks until one makes moves, the program ends, or an error stops it.
    std::optional<InterpResult> fill();

    MachineConfig machine;
    ProgramSource source;
    InterpreterOptions options;
    interp::Executor executor;
    Block block;
    std::vector<Move> pending;
    std::size_t next_pending = 0;
    std::optional<InterpResult> finished;  // ProgramEnd or Diagnostic, repeated once reached
    bool seen_tape_mark = false;
    bool seen_block = false;
};

Interpreter::Interpreter(MachineConfig machine, ProgramSource source, InterpreterOptions options)
    : state_(std::make_unique<State>(std::move(machine), std::move(source), options)) {}
Interpreter::Interpreter(Interpreter&&) noexcept = default;
Interpreter& Interpreter::operator=(Interpreter&&) noexcept = default;
Interpreter::~Interpreter() = default;

const MachineConfig& Interpreter::machine() const { return state_->machine; }

InterpResult Interpreter::next() {
    State& s = *state_;
    while (s.next_pending == s.pending.size()) {
        if (s.finished) return *s.finished;
        s.pending.clear();
        s.next_pending = 0;
        if (auto stop = s.fill()) s.finished = std::move(stop);
    }
    return std::move(s.pending[s.next_pending++]);
}

std::optional<InterpResult> Interpreter::State::fill() {
    while (pending.empty()) {
        auto line = source.next();
        if (!line) return InterpResult(line.diagnostics().front());
        if (!line.value()) return InterpResult(ProgramEnd{});
        const ProgramSource::Line& text = **line;
        if (options.block_delete && starts_with_block_delete(text.text)) {
            seen_block = true;
            continue;  // skipped unread: a deleted block is not part of the program
        }
        block.location = make_location(source.file(), text.number, 1);
        if (auto error = parse_block(text.text, block)) return InterpResult(std::move(*error));
        if (block.tape_mark) {
            // A leading '%' opens the tape; any later one closes it and ends the program.
            if (seen_tape_mark || seen_block) return InterpResult(ProgramEnd{});
            seen_tape_mark = true;
            continue;
        }
        if (block.words.empty()) continue;
        seen_block = true;
        bool program_end = false;
        if (auto error = executor.run(block, pending, program_end)) return InterpResult(std::move(*error));
        if (program_end) {
            // The moves of the last block still go out before the end.
            finished = InterpResult(ProgramEnd{});
            return std::nullopt;
        }
    }
    return std::nullopt;
}

}  // namespace nckit
