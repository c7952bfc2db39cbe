// MDI and synch(): commands LinuxCNC's task hands over one at a time in MDI mode, run against the
// state the commands before them left, from where LinuxCNC says the machine stands.
#include "guarded.hpp"
#include "nckit_interp.hpp"

namespace nckit::lcnc {

namespace {

bool blank(const char* line) {
    if (line == nullptr) return true;
    for (const char* p = line; *p != '\0'; ++p) {
        if (*p != ' ' && *p != '\t' && *p != '\r' && *p != '\n') return false;
    }
    return true;
}

}  // namespace

// MDI: LinuxCNC's task hands each command to execute(command); read(command) is the same here
// (LinuxCNC's own reads and runs an MDI block in one go too).
int NckitInterp::read(const char* line) {
    return execute(line);
}

int NckitInterp::execute(const char* line) {
    if (line == nullptr) return execute();
    if (blank(line)) return INTERP_OK;
    return guarded(error_, [&] { return run_mdi(line); });
}

int NckitInterp::execute(const char* line, int) {
    return execute(line);
}

int NckitInterp::run_mdi(const char* command) {
    if (!machine_ && !setup_error_) init();
    if (setup_error_) return fail(*setup_error_);
    if (!canon_) canon_.emplace(*machine_, settings_.g64_tolerance_mm, settings_.exact_path, settings_.line_comments);
    if (!mdi_ || !mdi_->append_input(command)) {
        if (int status = load_tools(); status != INTERP_OK) return status;
        mdi_.emplace(*machine_, ProgramSource::from_string("", "MDI"), run_options());
        if (synched_position_) mdi_->set_position(*synched_position_);
        if (!mdi_->append_input(command)) return fail("nckit interpreter: MDI cannot start");
    }
    running_ = &*mdi_;
    moves_taken_ = 0;
    messages_.clear();
    bool wait = false;
    // Bounded: the interpreter stops loops and calls after MAX_BLOCKS blocks (alarm 100).
    for (;;) {
        InterpResult result = mdi_->next();
        view_ = mdi_->modal_view();
        if (auto* move = std::get_if<Move>(&result)) {
            note_move(*move, *mdi_);
            issue_messages(moves_taken_++);
            if (canon_->emit(*move, view_) == AfterMove::wait_for_motion) wait = true;
            continue;
        }
        issue_messages(std::nullopt);
        if (auto* error = std::get_if<Diagnostic>(&result)) {
            Diagnostic d = *error;
            mdi_.reset();  // the next command starts a fresh session, as after a reset
            running_ = nullptr;
            return fail_with(d);
        }
        break;  // the end of the command's text (or M2/M30): the session waits for the next
    }
    call_level_ = 0;
    return wait ? INTERP_EXECUTE_FINISH : INTERP_OK;
}

// LinuxCNC says where the machine stands (after a mode change, a tool change, jogging): MDI
// commands go on from there. A program run keeps its own path: LinuxCNC synchs mid-run after a
// tool change, where the machine stands where the program left it, and at the start line of a
// run from line, where the approach starts (nckit_interp_start_line.cpp).
int NckitInterp::synch() {
    return guarded(error_, [&] {
        if (!machine_) return static_cast<int>(INTERP_OK);
        const CANON_UNITS units = GET_EXTERNAL_LENGTH_UNIT_TYPE();
        const double factor = units == CANON_UNITS_INCHES ? 25.4 : units == CANON_UNITS_CM ? 10.0 : 1.0;
        const double external[axis_count] = {
            GET_EXTERNAL_POSITION_X(), GET_EXTERNAL_POSITION_Y(), GET_EXTERNAL_POSITION_Z(),
            GET_EXTERNAL_POSITION_A(), GET_EXTERNAL_POSITION_B(), GET_EXTERNAL_POSITION_C(),
            GET_EXTERNAL_POSITION_U(), GET_EXTERNAL_POSITION_V(), GET_EXTERNAL_POSITION_W()};
        std::optional<AxisVector> offset = canon_ ? canon_->offset_mm() : std::nullopt;
        if (!offset) offset = sent_offset_mm_;
        AxisVector machine;
        for (std::size_t i = 0; i < axis_count; ++i) {
            const double program = is_rotary(static_cast<Axis>(i)) ? external[i] : external[i] * factor;
            machine.value[i] = program + (offset ? (*offset)[i] : 0.0);
        }
        synched_position_ = machine;
        if (mdi_) mdi_->set_position(machine);
        if (synch_owed_) {
            // The synch asked for after a block (the probe, a tool change): the calls went out.
            synch_owed_ = false;
            if (run_mode_ == RunMode::probing) run_mode_ = RunMode::normal;
        } else if (run_mode_ == RunMode::skipping) {
            // Task's start-line synch: the line handed out last is the one before the start line.
            run_mode_ = RunMode::finishing_line;
            skipped_line_ = main_line_;
        }
        return static_cast<int>(INTERP_OK);
    });
}

}  // namespace nckit::lcnc
