#include "nckit_interp.hpp"

#include <cstdlib>
#include <cstring>
#include <exception>

#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "guarded.hpp"
#include "nckit/core/tool_table.hpp"

namespace nckit::lcnc {

namespace {

char* copy_out(const std::string& text, char* buf, size_t buflen) {
    if (buf == nullptr || buflen == 0) return buf;
    std::size_t n = std::min(text.size(), buflen - 1);
    std::memcpy(buf, text.data(), n);
    buf[n] = '\0';
    return buf;
}

//! LinuxCNC's tool table as nckit's: in inches on an inch machine, else mm (a .toml file as TOML).
Result<ToolTable> load_linuxcnc_tool_table(const std::filesystem::path& path, bool inch) {
    if (!inch || path.extension() == ".toml") return load_tool_table(path);
    std::ifstream in(path, std::ios::binary);
    if (!in) return load_tool_table(path);  // says why it cannot be read
    std::ostringstream text;
    text << in.rdbuf();
    return parse_tool_tbl(text.str(), path.string(), true);
}

}  // namespace

int NckitInterp::fail(std::string message) {
    error_ = std::move(message);
    return INTERP_ERROR;
}

int NckitInterp::fail_with(const Diagnostic& d) {
    line_ = static_cast<int>(d.location.line);
    return fail(format_diagnostic(d));
}

// ---- set-up ----------------------------------------------------------------------------------

int NckitInterp::ini_load(const char* inifile) {
    ini_path_ = inifile != nullptr ? inifile : "";
    return INTERP_OK;
}

int NckitInterp::init() {
    return guarded(error_, [&] {
        // The task names the INI through ini_load(); standalone rs274 -i puts it in INI_FILE_NAME.
        if (ini_path_.empty()) {
            if (const char* env = std::getenv("INI_FILE_NAME")) ini_path_ = env;
        }
        settings_ = PluginSettings{};
        setup_error_.reset();
        close();
        mdi_.reset();
        running_ = nullptr;
        machine_.reset();
        if (!ini_path_.empty()) {
            if (auto error = read_plugin_settings(ini_path_, settings_)) {
                setup_error_ = *error;
                return fail(*error);
            }
        }
        if (settings_.machine_file.empty()) {
            machine_ = default_mill();
        } else {
            auto machine = load_machine_config(settings_.machine_file);
            if (!machine) {
                setup_error_ = format_diagnostic(machine.diagnostics().front());
                return fail(*setup_error_);
            }
            machine_ = std::move(machine).value();
        }
        return load_tools();
    });
}

int NckitInterp::load_tools() {
    if (settings_.tool_table_file.empty()) return INTERP_OK;
    auto tools = load_linuxcnc_tool_table(settings_.tool_table_file, settings_.tool_table_inch);
    if (!tools) return fail(format_diagnostic(tools.diagnostics().front()));
    machine_->tools = std::move(tools).value();
    machine_->tools_file = settings_.tool_table_file.string();
    return INTERP_OK;
}

int NckitInterp::open(const char* filename) {
    return guarded(error_, [&] {
        close();
        if (!machine_ && !setup_error_) init();
        if (setup_error_) return fail(*setup_error_);
        if (filename == nullptr || filename[0] == '\0') return fail("nckit interpreter: no program file given");
        // MDI after this run starts afresh: the run may change #500-#999 the MDI session holds.
        mdi_.reset();
        // The tool table again: offsets set on the machine since (G10 L1, the table editor) count.
        if (int status = load_tools(); status != INTERP_OK) return status;
        // Opened once here so that a missing file is reported at open, as LinuxCNC's own does.
        auto source = ProgramSource::open(filename);
        if (!source) return fail_with(source.diagnostics().front());
        program_path_ = filename;
        return static_cast<int>(INTERP_OK);
    });
}

InterpreterOptions NckitInterp::run_options() {
    InterpreterOptions options;
    options.block_delete = GET_BLOCK_DELETE();
    options.library_dir = settings_.library_dir;
    options.retained_file = settings_.retained_file;
    options.max_blocks = settings_.max_blocks;
    // A message comes before the next move the interpreter makes (LinuxCNC's own order).
    options.on_message = [this](const SourceLocation&, const std::string& text) {
        messages_.push_back(Message{running_ != nullptr ? running_->moves_made() : 0, text});
    };
    return options;
}

int NckitInterp::start_run() {
    auto source = ProgramSource::open(program_path_);
    if (!source) {
        program_error_ = source.diagnostics().front();
        return fail_with(*program_error_);
    }
    interpreter_.emplace(*machine_, std::move(source).value(), run_options());
    if (!settings_.journal_file.empty()) {
        auto journal = RunJournal::create(settings_.journal_file, *interpreter_, program_path_,
                                          JournalOptions{settings_.journal_fsync_ms});
        if (!journal) {
            program_error_ = journal.diagnostics().front();
            return fail_with(*program_error_);
        }
        journal_ = std::move(journal).value();
    }
    canon_.emplace(*machine_, settings_.g64_tolerance_mm, settings_.exact_path, settings_.line_comments);
    running_ = &*interpreter_;
    moves_taken_ = 0;
    messages_.clear();
    reset_start_line();
    skipped_.emplace(*machine_, interpreter_->modal_view());
    return INTERP_OK;
}

int NckitInterp::close() {
    if (canon_) {
        if (auto offset = canon_->offset_mm()) sent_offset_mm_ = offset;
    }
    if (running_ == &*interpreter_ || !interpreter_) running_ = nullptr;
    interpreter_.reset();
    canon_.reset();
    journal_.reset();  // an unfinished run keeps the blocks it completed; the last is not among them
    pending_.reset();
    pending_end_ = false;
    ended_ = false;
    program_error_.reset();
    program_path_.clear();
    line_ = 0;
    sequence_ = 0;
    call_level_ = 0;
    move_file_.clear();
    messages_.clear();
    reset_start_line();
    return INTERP_OK;
}

int NckitInterp::exit() {
    return close();
}

int NckitInterp::reset() {
    pending_.reset();
    pending_end_ = false;
    return INTERP_OK;
}

int NckitInterp::on_abort(int, const char*) {
    // An aborted run starts from its first block next time, as after a reset on a Fanuc control.
    std::string path = program_path_;
    close();
    program_path_ = path;
    return INTERP_OK;
}

void NckitInterp::note_move(const Move& move, const Interpreter& interpreter) {
    line_ = static_cast<int>(move.where.line);
    move_file_ = move.where.file ? *move.where.file : program_path_;
    call_level_ = interpreter.call_depth();
    if (move.sequence_number >= 0) sequence_ = static_cast<int>(move.sequence_number);
}

// ---- running ---------------------------------------------------------------------------------

int NckitInterp::read() {
    return guarded(error_, [&] {
        if (program_path_.empty()) return static_cast<int>(INTERP_FILE_NOT_OPEN);
        if (program_error_) return fail_with(*program_error_);
        if (ended_) return static_cast<int>(INTERP_ENDFILE);
        // The synch asked for never came: task dropped it with the block's calls (run from line).
        if (synch_owed_) {
            synch_owed_ = false;
            run_mode_ = RunMode::skipping;
        }
        if (probe_read_ || pending_ || pending_end_) return static_cast<int>(INTERP_OK);  // read twice: same block
        if (!interpreter_) {
            if (int status = start_run(); status != INTERP_OK) return status;
            if (hosted_by_task()) {
                // The probe: a block of line 0 that makes no call but asks task to synch after it.
                probe_read_ = true;
                run_mode_ = RunMode::probing;
                line_ = 0;
                call_level_ = 0;
                return static_cast<int>(INTERP_OK);
            }
        }
        running_ = &*interpreter_;
        if (!held_) {
            InterpResult result = interpreter_->next();
            if (auto* move = std::get_if<Move>(&result)) {
                // LinuxCNC's spindle-synchronised motion always starts at the index pulse: a
                // thread start past it (Q, a multi-start thread) would be cut on top of the first.
                if (const auto* sync = std::get_if<SyncMove>(&move->what);
                    sync != nullptr && sync->start_angle_deg != 0) {
                    program_error_ =
                        error_at(move->where, "sync-start-angle",
                                 fmt::format("a thread starting {} deg past the spindle index (Q): LinuxCNC "
                                             "starts every synchronised move at the index; shift the start "
                                             "along Z by a fraction of the lead instead",
                                             sync->start_angle_deg));
                    return fail_with(*program_error_);
                }
                held_view_ = interpreter_->modal_view();
                held_depth_ = interpreter_->call_depth();
                held_main_line_ = main_line_of(*move);
                held_ = std::move(*move);
            } else if (std::holds_alternative<ProgramEnd>(result)) {
                view_ = interpreter_->modal_view();
                if (run_mode_ == RunMode::skipping) {
                    program_error_ =
                        error_at(make_location(std::make_shared<const std::string>(program_path_), main_line_, 1),
                                 "start-line-not-reached",
                                 "run from line: the program ended before task reached the start line in the main "
                                 "program; start at a line of the main program that the run passes (not in a called "
                                 "program, a subroutine definition or after the program end)");
                    return fail_with(*program_error_);
                }
                pending_end_ = true;
                return static_cast<int>(INTERP_OK);
            } else {
                view_ = interpreter_->modal_view();
                program_error_ = std::get<Diagnostic>(result);
                return fail_with(*program_error_);
            }
        }
        if (!step_line()) deliver_held();
        return static_cast<int>(INTERP_OK);
    });
}

int NckitInterp::execute() {
    return guarded(error_, [&] {
        if (probe_read_) {
            probe_read_ = false;
            synch_owed_ = true;
            return static_cast<int>(INTERP_EXECUTE_FINISH);
        }
        if (pending_) {
            if (skip_pending()) return static_cast<int>(INTERP_OK);
            if (run_mode_ == RunMode::finishing_line) {
                run_mode_ = RunMode::normal;
                if (auto refused = restore_before(*pending_)) {
                    program_error_ = std::move(*refused);
                    pending_.reset();
                    return fail_with(*program_error_);
                }
            }
            issue_messages(pending_ordinal_);
            if (journal_) journal_->on_reached(pending_->where);
            AfterMove after = canon_->emit(*pending_, view_);
            pending_.reset();
            if (after == AfterMove::wait_for_motion) {
                synch_owed_ = hosted_by_task();
                return static_cast<int>(INTERP_EXECUTE_FINISH);
            }
            return static_cast<int>(INTERP_OK);
        }
        if (pending_end_) {
            issue_messages(std::nullopt);
            canon_->emit_program_end();
            if (journal_) {
                journal_->finish();
                if (journal_->error()) return fail_with(*journal_->error());
            }
            pending_end_ = false;
            ended_ = true;
            return static_cast<int>(INTERP_EXIT);
        }
        return static_cast<int>(INTERP_OK);
    });
}

void NckitInterp::issue_messages(std::optional<std::uint64_t> before) {
    std::size_t issued = 0;
    for (const Message& m : messages_) {
        // A move made before the message (an earlier block's, held by cutter compensation) first.
        if (before && m.before_move > *before) break;
        canon_->message(m.text);
        ++issued;
    }
    messages_.erase(messages_.begin(), messages_.begin() + static_cast<std::ptrdiff_t>(issued));
}

// ---- what LinuxCNC shows ---------------------------------------------------------------------

char* NckitInterp::error_text(int errcode, char* buf, size_t buflen) {
    return copy_out(errcode > INTERP_MIN_ERROR ? error_ : std::string{}, buf, buflen);
}

char* NckitInterp::line_text(char* buf, size_t buflen) {
    // The block's sequence number: rs274 prints it beside each canonical call, as for its own.
    return copy_out(sequence_ > 0 ? fmt::format("N{}", sequence_) : std::string{}, buf, buflen);
}

char* NckitInterp::command(char* buf, size_t buflen) {
    return line_text(buf, buflen);
}

size_t NckitInterp::line_length() {
    char buf[32];
    return std::strlen(line_text(buf, sizeof buf));
}

// The file of the block last read, as LinuxCNC's own interpreter names it: a called program's
// inside a call (line() is a line of this file), else the opened program.
char* NckitInterp::file_name(char* buf, size_t buflen) {
    return copy_out(move_file_.empty() ? program_path_ : move_file_, buf, buflen);
}
char* NckitInterp::file(char* buf, size_t buflen) {
    return file_name(buf, buflen);
}

// The call stack as far as the plug-in sees it: the file of the move last read at index 0, the
// main program at the index of the call level when that is above 0 (the files of levels
// between are not handed out).
char* NckitInterp::stack_name(int index, char* buf, size_t buflen) {
    std::string name;
    if (index == 0) name = move_file_;
    if (index > 0 && index == call_level_) name = program_path_;
    return copy_out(name, buf, buflen);
}

int NckitInterp::sequence_number() {
    return sequence_;
}
int NckitInterp::line() {
    return line_;
}
// Called programs in progress at the move last read (G65, M98, M-/G-code calls, O-word calls):
// 0 in the main program. LinuxCNC's status shows it as the subroutine level.
int NckitInterp::call_level() {
    return call_level_;
}

}  // namespace nckit::lcnc

extern "C" __attribute__((visibility("default"))) InterpBase* makeInterp() {
    return new (std::nothrow) nckit::lcnc::NckitInterp;
}
