#pragma once
// Runs one parsed block against the modal state and appends the moves it makes.
#include <functional>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "block_words.hpp"
#include "corner_round.hpp"
#include "macro/variables.hpp"
#include "modal_state.hpp"
#include "program_transform.hpp"
#include "nckit/core/machine.hpp"
#include "nckit/interp/cutter_comp.hpp"
#include "nckit/interp/interpreter.hpp"
#include "nckit/interp/modal_view.hpp"

namespace nckit::interp {

//! #2001-#2999: the tool offsets (executor_tools.cpp).
inline constexpr std::int64_t first_tool_variable = 2001;
inline constexpr std::int64_t last_tool_variable = 2999;
//! #1000-#1099: inputs (read-only, the machine file's [inputs]); #1100-#1199: outputs.
inline constexpr std::int64_t first_macro_input = 1000;
inline constexpr std::int64_t first_macro_output = 1100;
inline constexpr std::int64_t last_macro_input = 1199;

//! Reads the blocks N p through N q of the running program for the lathe cycles G70-G73, their
//! expressions evaluated; the error names what was not found. Set by the program runner.
using SequenceReader =
    std::function<std::optional<Diagnostic>(std::int64_t p, std::int64_t q, std::vector<Block>& out)>;

class Executor {
public:
    Executor(const MachineConfig& machine, const InterpreterOptions& options);

    //! Sets the power-up modes (executor_startup.cpp): feed per revolution on a lathe G-code
    //! system, then the machine's `startup_gcodes`. An error points into the machine file.
    [[nodiscard]] std::optional<Diagnostic> start();

    void set_sequence_reader(SequenceReader reader) { sequence_reader_ = std::move(reader); }
    //! True once after a G71/G72/G73 block: the program goes on after its N q block, which the
    //! cycle has used (the runner seeks there).
    [[nodiscard]] bool take_skip_past_sequence() { return std::exchange(skip_past_sequence_, false); }

    //! Runs `block`: every check first, then its actions in RS-274 order. On an error nothing of
    //! the block has happened and `out` is unchanged. Sets `program_end` on M2/M30.
    [[nodiscard]] std::optional<Diagnostic> run(const Block& block, std::vector<Move>& out, bool& program_end);

    // Macro B system variables that describe the machine state (executor_system_variables.cpp):
    // modal codes #4001-, modal values #4107-, positions #5001-, work offsets #5221-, part counts.
    [[nodiscard]] std::optional<MacroValue> read_system(std::int64_t number) const;
    [[nodiscard]] std::optional<SystemVariables::WriteError> write_system(std::int64_t number, double value);

    //! The end of the program (M2/M30 or the end of its text): compensated moves still held go out.
    [[nodiscard]] std::optional<Diagnostic> end_program(std::vector<Move>& out);

    //! The machine stands elsewhere now (moved by hand, or by LinuxCNC outside the program):
    //! the next move starts at `machine` (machine coordinates, mm / deg).
    void set_position(const AxisVector& machine) {
        position_ = machine;
        programmed_ = machine;
    }

    //! The active group-1 code. The LinuxCNC dialect runs its splines as G2/G3 blocks and then
    //! puts back the motion mode of before, which LinuxCNC's G5/G5.1 leave as it was.
    [[nodiscard]] GCode motion_mode() const { return modal_.motion; }
    void restore_motion_mode(GCode motion) { modal_.motion = motion; }

    [[nodiscard]] bool inch_units() const { return modal_.length_factor_mm != 1.0; }
    //! Units, offsets and modes after the last block run (executor_modal_view.cpp).
    [[nodiscard]] ModalView modal_view() const;
    //! Simulated time since the start, s: moves at programmed feed (rapids at the axis limits)
    //! and dwells. The macro timers #3001/#3002 run on it.
    [[nodiscard]] double elapsed_s() const { return elapsed_s_; }

private:
    // Checks (executor_checks.cpp): nothing changes state.
    std::optional<Diagnostic> check_words();
    //! Fanuc dialect: one warning per G code a later code of its group overrode in this block.
    void warn_overridden_codes() const;
    std::optional<Diagnostic> check_axis_letter(const Word& word) const;

    // Cutter radius compensation (executor_cutter_comp.cpp).
    std::optional<Diagnostic> check_cutter_comp();
    std::optional<Diagnostic> compensate(std::vector<Move>& out, std::size_t first, bool program_end);
    [[nodiscard]] bool block_starts_comp() const;
    [[nodiscard]] bool changes_offset_in_offset_mode(GCode code) const;
    std::optional<Diagnostic> check_offset_change(GCode code, std::uint32_t code_column);
    std::optional<Diagnostic> read_comp_radius(int number, std::uint32_t column);
    [[nodiscard]] std::optional<double> tool_radius_mm(int d_number) const;

    // Values of words, converted to mm / deg / s (executor.cpp).
    [[nodiscard]] double axis_value(Axis axis, const Word& word) const;
    [[nodiscard]] double offset_value(const Word& word) const;  // I J K R: length, no diameter
    [[nodiscard]] bool axis_is_linear(Axis axis) const;

    // Actions before motion (executor.cpp).
    std::optional<Diagnostic> set_modes();
    std::optional<Diagnostic> set_feed_and_spindle(std::vector<Move>& out);
    std::optional<Diagnostic> emit_mcodes(std::vector<Move>& out, bool stopping);
    std::optional<Diagnostic> dwell(std::vector<Move>& out);
    std::optional<Diagnostic> set_coordinates();

    // Programmable mirror, scaling and rotation (executor_transform.cpp): the block's G51 G51.1
    // G50.1 G68 G69 (G50 alone), and the block's motion mapped through them.
    std::optional<Diagnostic> set_transform();
    std::optional<Diagnostic> transformed_move(std::vector<Move>& out);

    // Motion (executor_motion.cpp).
    std::optional<Diagnostic> move(std::vector<Move>& out);
    std::optional<Diagnostic> home(std::vector<Move>& out);
    std::optional<Diagnostic> probe(std::vector<Move>& out);  //!< G31 (executor_probe.cpp)
    std::optional<Diagnostic> straight(GCode motion, const AxisVector& target, std::vector<Move>& out);
    std::optional<Diagnostic> arc(GCode motion, const AxisVector& target, std::vector<Move>& out);
    std::optional<Diagnostic> sync(const AxisVector& target, std::vector<Move>& out);
    std::optional<Diagnostic> check_travel(const AxisVector& low, const AxisVector& high) const;
    std::optional<Diagnostic> check_line_travel(const AxisVector& target) const;
    [[nodiscard]] AxisVector target_from_words(bool machine_coordinates) const;
    [[nodiscard]] bool block_has_axis_words() const;
    [[nodiscard]] Feed current_feed() const;
    [[nodiscard]] double spindle_rpm_at(double work_x_radius_mm) const;
    [[nodiscard]] double work_x() const;  //!< X of the current position in work coordinates, mm

    [[nodiscard]] Diagnostic error(std::uint32_t column, std::string code, std::string message) const;
    //! The same diagnostic as a warning, handed to options_.on_warning (if one is set).
    void warn(std::uint32_t column, std::string code, std::string message) const;
    [[nodiscard]] std::uint32_t column_of(char letter) const;
    [[nodiscard]] std::uint32_t motion_column() const;
    void push(std::vector<Move>& out, decltype(Move::what) what) const;
    [[nodiscard]] double duration_s(const Move& move) const;  //!< for the simulated clock

    // Tools (executor_tools.cpp).
    [[nodiscard]] AxisVector program_offset() const;                     //!< work + G92 + G52 + tool length, mm
    std::optional<Diagnostic> number_word(char letter, int& out) const;  //!< H, D: whole numbers
    std::optional<Diagnostic> set_tool_length();
    std::optional<Diagnostic> change_tool(std::vector<Move>& out);
    [[nodiscard]] std::optional<Diagnostic> check_tool_table_write() const;
    void write_tool_table();
    [[nodiscard]] std::optional<MacroValue> read_tool_variable(std::int64_t number) const;
    [[nodiscard]] std::optional<SystemVariables::WriteError> write_tool_variable(std::int64_t number, double value);

    // A lathe's offsets (lathe_tool_offsets.cpp): T xxyy, G10 P, #2001-#2999 as a 0i-T.
    std::optional<Diagnostic> select_lathe_tool(const Word& t);
    [[nodiscard]] bool is_lathe_offset_write() const;
    [[nodiscard]] std::optional<Diagnostic> check_lathe_offset_write() const;
    void write_lathe_offset();
    [[nodiscard]] std::optional<MacroValue> read_lathe_offset_variable(std::int64_t number) const;
    [[nodiscard]] std::optional<SystemVariables::WriteError> write_lathe_offset_variable(std::int64_t number,
                                                                                         double value);
    // Corner rounding and chamfers, `,R` / `,C` (executor_corner.cpp): the line is held until the
    // next block's move shows where the corner goes.
    std::optional<Diagnostic> check_corner();
    std::optional<Diagnostic> apply_corner(std::vector<Move>& out, std::size_t first, bool program_end);

    // Drilling cycles (executor_cycles.cpp).
    std::optional<Diagnostic> check_cycle_words() const;
    //! Warns (once) of an arc too small to be meant in mm: a program in inches without G20.
    void warn_if_implausibly_small(const Arc& arc);
    std::optional<Diagnostic> drill(std::vector<Move>& out);
    std::optional<Diagnostic> drill_hole(const struct HolePlan& hole, std::vector<Move>& out);

    // Lathe cycles (lathe_cycle_words.cpp, lathe_single_cycles.cpp, lathe_repetitive_cycles.cpp).
    [[nodiscard]] GCode lathe_cycle_of_block() const;          //!< the block's lathe cycle, or -1
    [[nodiscard]] const Word* cycle_word(char written) const;  //!< the word as written (U, not X)
    [[nodiscard]] std::optional<Diagnostic> check_lathe_cycle_words(GCode cycle) const;
    std::optional<Diagnostic> lathe_single_cycle(std::vector<Move>& out);
    std::optional<Diagnostic> lathe_repetitive_cycle(std::vector<Move>& out);
    std::optional<Diagnostic> lathe_cycle_settings();  //!< the first blocks of G71/G72/G73
    //! Runs the blocks N p .. N q of the block's P and Q words from the current position on a
    //! copy of this executor: their moves, and the letters of the P block's words.
    std::optional<Diagnostic> run_pq_blocks(struct PqShape& shape);
    //! G71/G72 type II: the roughing levels that follow pockets (lathe_rough_pockets.cpp).
    std::optional<Diagnostic> rough_pocket_levels(const struct RoughLevels& plan, const std::vector<Move>& moved,
                                                  std::vector<Move>& out);
    std::optional<Diagnostic> finish_cycle(std::vector<Move>& out);
    std::optional<Diagnostic> rough_cycle(std::vector<Move>& out);
    std::optional<Diagnostic> pattern_cycle(std::vector<Move>& out);
    std::optional<Diagnostic> thread_cycle(std::vector<Move>& out);  //!< G76 (lathe_thread_cycle.cpp)
    std::optional<Diagnostic> groove_cycle(std::vector<Move>& out);  //!< G74/G75 (lathe_groove_cycles.cpp)
    std::optional<Diagnostic> sync_to(const AxisVector& target, double lead_mm, double start_angle_deg,
                                      std::vector<Move>& out);
    //! Q of a threading block: the start angle past the index, deg (thread_start_angle.cpp).
    std::optional<Diagnostic> thread_start_angle(const Word& q, double& angle_deg) const;
    std::optional<Diagnostic> feed_arc(Arc arc, std::vector<Move>& out);

    // System variable helpers (executor_system_variables.cpp).
    [[nodiscard]] std::optional<MacroValue> modal_code(int group) const;
    [[nodiscard]] std::optional<MacroValue> read_macro_input(std::int64_t number) const;
    [[nodiscard]] const AxisConfig* axis_by_number(std::int64_t one_based) const;
    [[nodiscard]] double to_program_units(Axis axis, double mm) const;
    [[nodiscard]] double from_program_units(Axis axis, double value) const;

    const MachineConfig& machine_;
    InterpreterOptions options_;
    AxisSet configured_;
    std::array<bool, axis_count> rotary_{};

    ModalState modal_;
    Offsets offsets_;
    ToolTable tools_;      //!< the machine's table; G10 and #2001- change it during the run
    AxisVector position_;  //!< machine coordinates, mm / deg
    ProgramTransform transform_;
    AxisVector programmed_;  //!< position_ before the transform (while one is active)

    const Block* block_ = nullptr;  //!< the block being run
    BlockWords words_;
    GCode motion_ = g(80);  //!< motion code for this block (explicit or modal)

    CutterCompensator comp_;
    CompSide comp_side_ = CompSide::left;  //!< from check_cutter_comp() for this block's G41/G42
    double comp_radius_mm_ = 0;            //!< likewise, mm
    AxisVector comp_tip_shift_;            //!< a lathe tool's imaginary tip less its nose centre (G41/G42), mm
    bool comp_change_ = false;             //!< this block changes the offset in offset mode (check_offset_change())

    SequenceReader sequence_reader_;
    bool skip_past_sequence_ = false;

    //! A G1 line or G2/G3 arc with a corner word, and what its block made after it, waiting for the next move.
    struct HeldCorner {
        Word word;                //!< the ,R or ,C word (its column) ...
        SourceLocation location;  //!< ... in this block
        CornerKind kind = CornerKind::round;
        double size_mm = 0;
        Plane plane = Plane::xy;
        std::vector<Move> moves;  //!< the line or arc first
    };
    std::optional<HeldCorner> corner_;

    AxisVector skip_position_;                 //!< machine coordinates where G31 last skipped (#5061-)
    std::array<double, 100> macro_outputs_{};  //!< #1100-#1199 as the program wrote them
    std::array<bool, 100> macro_output_set_{};

    double elapsed_s_ = 0;  //!< simulated time, s
    //! Where a gcode-overridden warning was given (file, line, column): a block that runs again
    //! in a loop or a called program warns once, not on every pass.
    mutable std::set<std::tuple<std::string, std::uint32_t, std::uint32_t>> overrides_warned_;
    int last_mcode_ = 0;             //!< #4113
    double parts_done_ = 0;          //!< #3901, counted at M2/M30
    double parts_required_ = 0;      //!< #3902
    bool warned_small_arc_ = false;  //!< the implausible-size warning is given once a run
};

}  // namespace nckit::interp
