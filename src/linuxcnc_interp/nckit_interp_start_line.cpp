// Run from line: LinuxCNC's task reads and executes the blocks before the start line, drops their
// canonical calls and synchs; the plug-in skips them itself and, before the first move from the
// start line, issues the state they left (nckit's restart model, docs/linuxcnc-plugin.md).
#include <dlfcn.h>

#include <algorithm>
#include <cmath>

#include "nckit_interp.hpp"

namespace nckit::lcnc {

namespace {

//! The moves of a restart's approach are made only when the machine is not at the point yet.
constexpr double at_point_mm = 1e-6;

}  // namespace

bool NckitInterp::hosted_by_task() {
    // milltask exports its functions (the plug-in's canonical calls resolve against them);
    // emcTaskPlanSynch (emctask.cc) is the one that calls synch(). rs274 has no such function.
    static const bool task = dlsym(RTLD_DEFAULT, "_Z16emcTaskPlanSynchv") != nullptr;
    return task;
}

void NckitInterp::reset_start_line() {
    run_mode_ = RunMode::normal;
    probe_read_ = false;
    synch_owed_ = false;
    main_line_ = 0;
    call_line_open_ = false;
    held_.reset();
    held_depth_ = 0;
    held_main_line_ = 0;
    pending_main_line_ = 0;
    skipped_line_ = 0;
    skipped_.reset();
}

std::uint32_t NckitInterp::main_line_of(const Move& move) const {
    if (interpreter_->call_depth() == 0) return move.where.line;
    return interpreter_->calling_line();
}

// Task finds the start line by line(): it synchs after the block whose line() is the one before
// the start line, at call level 0. LinuxCNC's own interpreter reads every line; nckit's hands out
// only blocks that move, so the lines between them (and the line of a call, whose moves come at
// a deeper level) are handed out as steps that issue nothing.
bool NckitInterp::step_line() {
    const bool same_call = held_depth_ > 0 && held_main_line_ == main_line_;
    if (call_line_open_ && !same_call) {
        call_line_open_ = false;
    } else if (held_main_line_ > main_line_ + 1) {
        ++main_line_;
    } else {
        return false;
    }
    line_ = static_cast<int>(main_line_);
    call_level_ = 0;
    move_file_ = program_path_;
    return true;
}

void NckitInterp::deliver_held() {
    if (held_main_line_ > 0) main_line_ = held_main_line_;
    call_line_open_ = held_depth_ > 0;
    pending_main_line_ = held_main_line_;
    view_ = held_view_;
    note_move(*held_, *interpreter_);
    if (journal_) journal_->on_move(*interpreter_, *held_);
    call_level_ = held_depth_;
    pending_ordinal_ = moves_taken_++;
    pending_ = std::move(held_);
    held_.reset();
}

bool NckitInterp::skip_pending() {
    const bool skip =
        run_mode_ == RunMode::skipping || (run_mode_ == RunMode::finishing_line && pending_main_line_ == skipped_line_);
    if (!skip) return false;
    skipped_->note(*pending_, view_);
    // Task drops the messages of the blocks it skips as well.
    std::erase_if(messages_, [&](const Message& m) { return m.before_move <= pending_ordinal_; });
    pending_.reset();
    return true;
}

std::optional<Diagnostic> NckitInterp::restore_before(const Move& target) {
    if (auto refused = skipped_->refuse(target, view_)) return refused;
    // LinuxCNC got none of the skipped blocks' calls: a fresh output sends every mode again
    // (units, offsets, plane, feed mode and rate, path mode) with the first call.
    canon_.emplace(*machine_, settings_.g64_tolerance_mm, settings_.exact_path, settings_.line_comments);
    const RestartIo& io = skipped_->io();
    auto issue = [&](IoKind kind, int number, double value = 0) {
        Move event;
        event.where = target.where;
        event.what = Io{kind, number, value, io.constant_surface_speed, io.rpm_clamp};
        return canon_->emit(event, view_);
    };
    if (io.tool_in_spindle > 0 && GET_EXTERNAL_TOOL_TABLE(0).toolno != io.tool_in_spindle) {
        issue(IoKind::tool_select, io.tool_in_spindle);
        issue(IoKind::mcode, 6);
    }
    if (io.tool_selected > 0 && io.tool_selected != io.tool_in_spindle) issue(IoKind::tool_select, io.tool_selected);
    if (io.speed_set) issue(IoKind::spindle_speed, 0, io.speed);
    if (io.spindle_mcode == 3 || io.spindle_mcode == 4) {
        issue(IoKind::mcode, io.spindle_mcode, io.speed_set ? io.speed : io.spindle_rpm);
    }
    if (io.mist) issue(IoKind::mcode, 7);
    if (io.flood) issue(IoKind::mcode, 8);
    for (int m : io.laser_on) issue(IoKind::mcode, m);
    // Back onto the path where the target starts: retract, rapid over, feed down.
    const RestartApproach approach = skipped_->approach(target);
    if (approach.moves && synched_position_) {
        double off_mm = 0;
        for (const AxisConfig& axis : machine_->axes) {
            off_mm = std::max(off_mm, std::abs((*synched_position_)[axis.axis] - approach.point[axis.axis]));
        }
        if (off_mm > at_point_mm) {
            for (const ApproachStep& step : approach_steps(approach, *machine_, *synched_position_)) {
                Move move;
                move.where = target.where;
                move.what = step.line;
                canon_->emit(move, view_);
            }
        }
    }
    return std::nullopt;
}

}  // namespace nckit::lcnc
