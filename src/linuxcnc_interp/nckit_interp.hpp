#pragma once
// nckit's interpreter behind LinuxCNC's interpreter interface (interp_base.hh): LinuxCNC's task
// and its standalone rs274 call open, read, execute... and get canonical calls back.
//
// One read() takes the next answer from nckit's streaming interpreter: a move, the program end or
// an error. execute() issues the move's canonical calls. An error (a macro alarm among them)
// therefore comes from read(), before any call of its block: what LinuxCNC has queued from the
// blocks before it still runs, nothing of the block itself does.
#include <optional>
#include <cstdint>
#include <string>
#include <vector>

#include "canon_output.hpp"
#include "linuxcnc_headers.hpp"
#include "nckit/interp/interpreter.hpp"
#include "nckit/interp/run_journal.hpp"
#include "nckit/interp/restart_state.hpp"
#include "plugin_settings.hpp"

namespace nckit::lcnc {

class NckitInterp final : public InterpBase {
public:
    char* error_text(int errcode, char* buf, size_t buflen) override;
    char* line_text(char* buf, size_t buflen) override;
    char* file_name(char* buf, size_t buflen) override;
    char* stack_name(int index, char* buf, size_t buflen) override;
    size_t line_length() override;
    int sequence_number() override;
    int ini_load(const char* inifile) override;
    int init() override;
    int execute() override;
    int execute(const char* line) override;
    int execute(const char* line, int line_number) override;
    int synch() override;
    int exit() override;
    int open(const char* filename) override;
    int read() override;
    int read(const char* line) override;
    int close() override;
    int reset() override;
    int line() override;
    int call_level() override;
    char* command(char* buf, size_t buflen) override;
    char* file(char* buf, size_t buflen) override;
    int on_abort(int reason, const char* message) override;
    void active_g_codes(int active_gcodes[ACTIVE_G_CODES]) override;
    void active_m_codes(int active_mcodes[ACTIVE_M_CODES]) override;
    void active_settings(double active_settings[ACTIVE_SETTINGS]) override;
    int active_modes(int g_codes[ACTIVE_G_CODES], int m_codes[ACTIVE_M_CODES], double settings[ACTIVE_SETTINGS],
                     StateTag const& tag) override;
    int restore_from_tag(StateTag const& tag) override;
    void print_state_tag(StateTag const& tag) override;
    void set_loglevel(int level) override;
    void set_loop_on_main_m99(bool state) override;

private:
    int fail(std::string message);       //!< keeps the message for error_text: INTERP_ERROR
    int start_run();                     //!< the interpreter for the opened file
    int load_tools();                    //!< the tool table of the settings into machine_
    int fail_with(const Diagnostic& d);  //!< a program error: its FILE:LINE:COL text
    InterpreterOptions run_options();    //!< the options of a program run and of MDI
    int run_mdi(const char* command);    //!< one MDI block, all its calls issued
    //! The move just taken from `interpreter`: where it comes from (line, file, call level).
    void note_move(const Move& move, const Interpreter& interpreter);

    // ---- run from line (nckit_interp_start_line.cpp, docs/linuxcnc-plugin.md) ----------------
    // LinuxCNC's task runs a program from line L by reading and executing every block before L,
    // dropping the canonical calls they make (motion, spindle, coolant, tool, feed mode...), and
    // calling synch() after the block whose line() is L - 1 at call level 0. It tells the
    // interpreter nothing else. The plug-in finds out: the first read() of a run is a probe whose
    // execute() asks task to wait and synch; task drops that synch with the probe's calls when it
    // skips, so a read() before the synch means the run is skipping. The skipped moves are not
    // issued (task would run those of called programs) but folded into a RestartState; at the
    // start-line synch the rest of line L - 1 is skipped too, and before the first move after it
    // the state is issued again: tool, spindle, coolant, the approach, all modes.
    enum class RunMode {
        normal,          //!< calls go out
        probing,         //!< the probe asked for a synch; not yet answered
        skipping,        //!< task drops the calls: the blocks before the start line
        finishing_line,  //!< synched at the line before the start line: its last moves still skip
    };
    //! The next thing read() hands task: a step over a main-program line (task counts lines to
    //! find the start line; nckit hands out only blocks that move) or the move held.
    [[nodiscard]] bool step_line();
    //! The move taken last is handed out as the block read.
    void deliver_held();
    //! A move task would drop, or the rest of the line before the start line: folded, not issued.
    [[nodiscard]] bool skip_pending();
    //! The state the skipped blocks left, issued before `target`; an error when `target` cannot
    //! be a start. No INTERP_EXECUTE_FINISH for its tool change: task's synch would drop the
    //! motion canon still holds for merging (GET_EXTERNAL_POSITION drops unflushed segments); the
    //! tool load runs before the motions queued after it all the same.
    [[nodiscard]] std::optional<Diagnostic> restore_before(const Move& target);
    void reset_start_line();
    //! The line of the main program a move belongs to: its own at call level 0, the calling
    //! block's inside a called program.
    [[nodiscard]] std::uint32_t main_line_of(const Move& move) const;

    //! LinuxCNC's task hosts the plug-in (it synchs after INTERP_EXECUTE_FINISH and runs programs
    //! from a line); rs274 does neither: no probe there.
    [[nodiscard]] static bool hosted_by_task();

    RunMode run_mode_ = RunMode::normal;
    bool probe_read_ = false;      // the probe was read, not yet executed
    bool synch_owed_ = false;      // execute() asked task to wait and synch; no synch since
    std::uint32_t main_line_ = 0;  // the main-program line last handed out at call level 0
    bool call_line_open_ = false;  // moves of a call made on main_line_ were handed out at level > 0
    std::optional<Move> held_;     // taken from the interpreter, not yet handed out
    ModalView held_view_;          // its modes
    int held_depth_ = 0;           // its call depth
    std::uint32_t held_main_line_ = 0;
    std::uint32_t pending_main_line_ = 0;
    std::uint32_t skipped_line_ = 0;  // finishing_line: the line before the start line
    std::optional<RestartState> skipped_;

    std::string ini_path_;
    PluginSettings settings_;
    std::optional<MachineConfig> machine_;
    std::optional<std::string> setup_error_;  // INI or machine file at fault: every open says so

    std::string program_path_;                // the opened program; empty: none
    std::optional<Interpreter> interpreter_;  // made at the first read (block delete is known then)
    std::optional<CanonOutput> canon_;
    //! [NCKIT] JOURNAL: the run's journal; a block is recorded once a move of a later block has
    //! been executed (handed to LinuxCNC), or at the program end.
    std::optional<RunJournal> journal_;
    //! MDI: one program of all commands given since the last program run, so that modes and
    //! variables carry from one command to the next. Dropped by an error, init and a program run.
    std::optional<Interpreter> mdi_;
    //! Where LinuxCNC last said the machine stands (synch()), machine coordinates mm / deg.
    std::optional<AxisVector> synched_position_;
    //! LinuxCNC's offsets as the last CanonOutput gave them (kept when a run closes).
    std::optional<AxisVector> sent_offset_mm_;
    Interpreter* running_ = nullptr;  // the interpreter advanced now (messages ask it)
    std::uint64_t moves_taken_ = 0;   // moves taken from running_
    std::optional<Move> pending_;     // read, not yet executed
    bool pending_end_ = false;        // read the program end, not yet executed
    bool ended_ = false;              // the end was executed: read() says so again
    std::optional<Diagnostic> program_error_;
    ModalView view_;  // the modes of the pending move's block

    std::string error_;  // error_text's message
    int line_ = 0;
    int sequence_ = 0;
    int call_level_ = 0;     // called programs in progress at the move last read
    std::string move_file_;  // the file of the move last read (a called program's)

    //! Operator messages the interpreter gave, waiting for the first move of their block or
    //! after it: messages come while a block is read, which may be before moves still queued
    //! from earlier blocks (cutter compensation looks ahead) are executed.
    struct Message {
        std::uint64_t before_move = 0;  //!< the ordinal of the move made after it
        std::string text;
    };
    std::vector<Message> messages_;
    //! The messages due before the move of ordinal `before` (all: nothing).
    void issue_messages(std::optional<std::uint64_t> before);
    std::uint64_t pending_ordinal_ = 0;  // pending_'s ordinal among the moves taken
};

}  // namespace nckit::lcnc
