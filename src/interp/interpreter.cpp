#include "nckit/interp/interpreter.hpp"

#include "linuxcnc/ngc_runner.hpp"
#include "program_runner.hpp"

namespace nckit {

struct Interpreter::State {
    State(MachineConfig m, ProgramSource s, InterpreterOptions o) : machine(std::move(m)), options(std::move(o)) {
        if (machine.dialect == Dialect::linuxcnc) {
            ngc.emplace(machine, std::move(s), options);
        } else {
            runner.emplace(machine, std::move(s), options);
        }
    }

    MachineConfig machine;
    InterpreterOptions options;
    std::optional<interp::ProgramRunner> runner;  // Fanuc with Macro B
    std::optional<interp::ngc::NgcRunner> ngc;    // LinuxCNC's RS-274/NGC

    std::optional<InterpResult> fill(std::vector<Move>& out) { return ngc ? ngc->fill(out) : runner->fill(out); }
    [[nodiscard]] bool recoverable() const {
        return ngc ? ngc->error_is_recoverable() : runner->error_is_recoverable();
    }
    std::vector<Move> pending;
    std::uint64_t batches = 0;
    std::uint64_t returned = 0;  // moves next() has returned
    std::size_t next_pending = 0;
    std::optional<InterpResult> finished;  // ProgramEnd or Diagnostic, repeated once reached

    //! The run is over: keep #500-#999, as a control does whatever stopped the program.
    void finish(InterpResult result) {
        if (auto error = ngc ? ngc->save_parameters() : runner->save_retained();
            error && std::holds_alternative<ProgramEnd>(result)) {
            result = std::move(*error);
        }
        finished = std::move(result);
    }
};

Interpreter::Interpreter(MachineConfig machine, ProgramSource source, InterpreterOptions options)
    : state_(std::make_unique<State>(std::move(machine), std::move(source), std::move(options))) {}
Interpreter::Interpreter(Interpreter&&) noexcept = default;
Interpreter& Interpreter::operator=(Interpreter&&) noexcept = default;
Interpreter::~Interpreter() = default;

const MachineConfig& Interpreter::machine() const {
    return state_->machine;
}

ModalView Interpreter::modal_view() const {
    return state_->ngc ? state_->ngc->modal_view() : state_->runner->modal_view();
}
std::uint64_t Interpreter::main_program_offset() const {
    return state_->ngc ? state_->ngc->main_program_offset() : state_->runner->main_program_offset();
}

std::uint64_t Interpreter::output_batch() const {
    return state_->batches;
}

std::uint64_t Interpreter::moves_made() const {
    const State& s = *state_;
    return s.returned + (s.pending.size() - s.next_pending);
}

int Interpreter::call_depth() const {
    return state_->ngc ? state_->ngc->call_depth() : state_->runner->call_depth();
}

const std::string& Interpreter::current_file() const {
    return state_->ngc ? state_->ngc->current_file() : state_->runner->current_file();
}

std::uint32_t Interpreter::calling_line() const {
    return state_->ngc ? state_->ngc->calling_line() : state_->runner->calling_line();
}

bool Interpreter::append_input(std::string_view text) {
    State& s = *state_;
    if (s.finished && !std::holds_alternative<ProgramEnd>(*s.finished)) return false;
    s.finished.reset();
    if (s.ngc) {
        s.ngc->append_main(text);
    } else {
        s.runner->append_main(text);
    }
    return true;
}

void Interpreter::set_position(const AxisVector& machine) {
    if (state_->ngc) {
        state_->ngc->set_position(machine);
    } else {
        state_->runner->set_position(machine);
    }
}

std::uint64_t Interpreter::retained_writes() const {
    return state_->runner ? state_->runner->retained_writes() : state_->ngc->persistent_changes();
}

std::vector<RetainedVariable> Interpreter::retained_values() const {
    return state_->runner ? state_->runner->retained_values() : state_->ngc->persistent_values();
}

InterpResult Interpreter::next() {
    State& s = *state_;
    while (s.next_pending == s.pending.size()) {
        if (s.finished) return *s.finished;
        s.pending.clear();
        s.next_pending = 0;
        ++s.batches;
        // The moves of the block that ended the program still go out before the end.
        if (auto stop = s.fill(s.pending)) {
            if (s.options.keep_going_after_errors && s.recoverable() && std::holds_alternative<Diagnostic>(*stop)) {
                s.pending.clear();  // the block in error moves nothing
                return std::move(*stop);
            }
            s.finish(std::move(*stop));
        }
    }
    ++s.returned;
    return std::move(s.pending[s.next_pending++]);
}

}  // namespace nckit
