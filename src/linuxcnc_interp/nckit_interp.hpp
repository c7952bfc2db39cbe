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

    std::string ini_path_;
    PluginSettings settings_;
    std::optional<MachineConfig> machine_;
    std::optional<std::string> setup_error_;  // INI or machine file at fault: every open says so

    std::string program_path_;                // the opened program; empty: none
    std::optional<Interpreter> interpreter_;  // made at the first read (block delete is known then)
    std::optional<CanonOutput> canon_;
    std::optional<Move> pending_;  // read, not yet executed
    bool pending_end_ = false;     // read the program end, not yet executed
    bool ended_ = false;           // the end was executed: read() says so again
    std::optional<Diagnostic> program_error_;
    ModalView view_;  // the modes of the pending move's block

    std::string error_;  // error_text's message
    int line_ = 0;
    int sequence_ = 0;
    std::string move_file_;  // the file of the move last read (a called program's)

    //! Operator messages the interpreter gave, waiting for the first move of their block or
    //! after it: messages come while a block is read, which may be before moves still queued
    //! from earlier blocks (cutter compensation looks ahead) are executed.
    struct Message {
        std::string file;
        std::uint32_t line = 0;
        std::string text;
    };
    std::vector<Message> messages_;
    void issue_messages(const Move* before);  //!< the messages due before `before` (all: null)
};

}  // namespace nckit::lcnc
