#pragma once
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <optional>
#include <variant>
#include <vector>

#include "nckit/core/diagnostic.hpp"
#include "nckit/core/machine.hpp"
#include "nckit/gcode/program_source.hpp"
#include "nckit/interp/modal_view.hpp"
#include "nckit/interp/move.hpp"

namespace nckit {

//! One retained macro variable (#500-#999) that holds a number.
struct RetainedVariable {
    int number = 0;
    double value = 0;
    bool operator==(const RetainedVariable&) const = default;
};

struct InterpreterOptions {
    //! The operator's block delete switch: when on, blocks that start with '/' are skipped.
    //! Off by default, as on a Fanuc control at power-on and in LinuxCNC's rs274.
    bool block_delete = false;
    //! An I/J/K arc whose end radius differs from its start radius by more than this and by
    //! more than 0.1 %, or by more than 100 times this, is an error: LinuxCNC 2.9's rule and
    //! value (0.02·√2 mm; under G20 its inch value 0.002·√2 in, 2.54 times this).
    double arc_radius_tolerance_mm = 0.028284271247461905;
    //! An R arc whose radius falls short of half its chord by up to this is a half circle; by
    //! more it is an error (LinuxCNC: 0.00005 in = 0.00127 mm in either unit).
    double r_arc_tolerance_mm = 0.00127;
    //! Where M98/G65 find programs that are not in the program's own file: one file per program,
    //! named by its number (`O1234.nc`, `1234.ngc`, `O1234`), as in a control's memory.
    std::filesystem::path library_dir;
    //! LinuxCNC dialect: further folders where `o<name> call` finds NAME.ngc (after library_dir,
    //! before the main program's own folder); the machine file's `subroutine_path`.
    std::vector<std::filesystem::path> subroutine_path;
    //! Blocks a program may execute inside loops, after a jump back or in called programs before
    //! it is stopped as a runaway (alarm 100). A program without jumps is bounded by its length.
    std::int64_t max_blocks = 10'000'000;
    //! File that keeps #500-#999 between runs; empty: they start vacant and are not kept. In the
    //! LinuxCNC dialect: its parameter file (`NUMBER<tab>VALUE` lines, like LinuxCNC's .var).
    std::filesystem::path retained_file;
    //! When set, #500-#999 start with these values (the others vacant) instead of the file's,
    //! and nothing is written back: a restart resumes with the values its run journal kept. In
    //! the LinuxCNC dialect: the persistent parameters, read as if from its parameter file.
    std::optional<std::vector<RetainedVariable>> retained_start;
    //! Write changed #500-#999 back at the end of the run (a check reads them but keeps none).
    bool save_retained = true;
    //! After an error in a block of the main program (a syntax error, a bad word, a move off the
    //! travel), report it and go on with the next block instead of stopping, as a compiler does
    //! (`nckit check`). Errors that leave no sensible place to go on (a runaway, an unreadable
    //! line, an error inside a called program) still stop the run.
    bool keep_going_after_errors = false;
    //! Called with each warning (a block that runs but likely not as meant, e.g. `G4 P1.5`);
    //! none: warnings are dropped.
    std::function<void(const Diagnostic&)> on_warning;
    //! Called with each operator message and the block that gives it: the text of a
    //! `(MSG, text)` comment, and #3006's comment when it stops the program. None: not shown
    //! (the LinuxCNC plug-in shows them as LinuxCNC's MESSAGE).
    std::function<void(const SourceLocation&, const std::string&)> on_message;
};

//! The program ended: M2, M30, a closing '%', or the end of the file.
struct ProgramEnd {};

//! One answer from the interpreter: a move, the end of the program, or the error that stops it.
using InterpResult = std::variant<Move, ProgramEnd, Diagnostic>;

//! Runs a program block by block and streams its moves: memory stays bounded whatever the
//! program's length. After an error or the end, every further call repeats that answer (unless
//! `keep_going_after_errors` lets it go on after a block's error).
class Interpreter {
public:
    Interpreter(MachineConfig machine, ProgramSource source, InterpreterOptions options = {});
    Interpreter(Interpreter&&) noexcept;
    Interpreter& operator=(Interpreter&&) noexcept;
    ~Interpreter();

    [[nodiscard]] InterpResult next();

    [[nodiscard]] const MachineConfig& machine() const;
    //! Bytes of the main program read so far (for progress: this over the file's size).
    [[nodiscard]] std::uint64_t main_program_offset() const;

    //! Units, work offsets and modes in force for the moves next() returns now: those of the
    //! block that made them (a block's moves come out together, after its modes are set).
    [[nodiscard]] ModalView modal_view() const;

    //! Counts the times the interpreter ran blocks to refill its output: moves returned since
    //! the last change of this number came from one run of the blocks (a block run again in a
    //! loop shows up under a new number, though its source line is the same).
    [[nodiscard]] std::uint64_t output_batch() const;

    //! Moves made so far: those next() returned and those made in the refill running now. An
    //! on_message callback reads it to know which move its message comes before.
    [[nodiscard]] std::uint64_t moves_made() const;

    //! Called programs in progress when the last move was made (0: the main program), and the
    //! file of the program running then.
    [[nodiscard]] int call_depth() const;
    [[nodiscard]] const std::string& current_file() const;
    //! Inside a called program: the line of the main program's block that made the outermost
    //! call in progress (where a run from a main-program line places the called program's
    //! moves); 0 in the main program.
    [[nodiscard]] std::uint32_t calling_line() const;

    //! MDI: `text` becomes further lines of a program made from a string, and a run that ended
    //! (at the end of its text, M2 or M30) goes on with them, in the modes and with the variables
    //! it left. False when the run stopped at an error: it cannot go on.
    [[nodiscard]] bool append_input(std::string_view text);

    //! The machine stands at `machine` (machine coordinates, mm / deg) now, moved outside the
    //! program: the next move starts there.
    void set_position(const AxisVector& machine);
    //! Counts the writes to #500-#999 so far (Fanuc dialect), or the changes of the parameters
    //! LinuxCNC keeps in its parameter file (LinuxCNC dialect: #5161-#5390 and those the file
    //! had): a run journal reads retained_values() only when it moves.
    [[nodiscard]] std::uint64_t retained_writes() const;
    //! The retained variables that hold a number now, by number (LinuxCNC dialect: the
    //! persistent parameters, as their file would have them).
    [[nodiscard]] std::vector<RetainedVariable> retained_values() const;

private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace nckit
