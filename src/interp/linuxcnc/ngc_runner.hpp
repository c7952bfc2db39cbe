#pragma once
// Runs a LinuxCNC RS-274/NGC program: reads its lines, follows O-word subroutines and control
// flow the way LinuxCNC's interpreter does (labels found by name as the file is read, skipping
// forward to a label, seeking back to a recorded one), keeps its parameters, and hands each
// ordinary line, with its values known, to the Executor that nckit's Fanuc reader uses too.
#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "../executor.hpp"
#include "ngc_g7x_profile.hpp"
#include "ngc_line.hpp"
#include "ngc_nurbs.hpp"
#include "ngc_parameters.hpp"
#include "nckit/interp/interpreter.hpp"

namespace nckit::interp::ngc {

// A G70-G72 shape while its subroutine's lines are read, not run. At namespace scope: clang
// cannot default-construct a nested class with member initialisers inside std::optional.
struct ProfileReading {
    std::vector<ProfileSegment> segments;
    ZX at;  //!< where the shape has got to: #<_x> and #<_z> while it is read
    int motion = 0;
    bool incremental = false;
    bool ijk_incremental = true;
};

class NgcRunner {
public:
    NgcRunner(const MachineConfig& machine, ProgramSource main, const InterpreterOptions& options);

    //! Runs lines until moves are queued in `pending`, the program ends, or an error stops it.
    [[nodiscard]] std::optional<InterpResult> fill(std::vector<Move>& pending);
    //! Writes the parameter file back when one is configured and saving is asked for.
    [[nodiscard]] std::optional<Diagnostic> save_parameters() const;
    [[nodiscard]] bool error_is_recoverable() const { return error_is_recoverable_; }
    [[nodiscard]] std::uint64_t main_program_offset() const { return main_offset_; }
    [[nodiscard]] ModalView modal_view() const { return executor_.modal_view(); }
    //! O-word and M98 calls in progress: 0 in the main program.
    [[nodiscard]] int call_depth() const { return static_cast<int>(frames_.size()) - 1; }
    [[nodiscard]] const std::string& current_file() const { return *current_->file(); }
    //! Inside a call: the line of the main program's block that made the outermost call; 0 else.
    [[nodiscard]] std::uint32_t calling_line() const {
        return frames_.size() > 1 && frames_[1].return_line > 0 ? frames_[1].return_line - 1 : 0;
    }
    void append_main(std::string_view text) { files_.at(main_file_)->append(text); }
    void set_position(const AxisVector& machine) { executor_.set_position(machine); }
    //! The parameters LinuxCNC keeps in its file (#5161-#5390 and those the file had), now.
    [[nodiscard]] std::vector<RetainedVariable> persistent_values() const;
    //! Counts the changes of persistent_values() seen so far (a run journal records them).
    [[nodiscard]] std::uint64_t persistent_changes() const;

private:
    //! Where an O-word label was seen (LinuxCNC's offset table).
    struct Label {
        OKind kind = OKind::none;
        std::string file;
        std::uint64_t offset = 0;
        std::uint32_t line = 0;
        int repeat_count = -1;
    };
    //! One level of O-word calls; [0] is the main program.
    struct Frame {
        std::string sub;  //!< the called sub's label; empty for the main program
        std::string return_file;
        std::uint64_t return_offset = 0;
        std::uint32_t return_line = 0;
        bool fanuc = false;    //!< called by M98: ends with M99, shares the caller's parameters
        int repeats_left = 0;  //!< M98 L: runs still to come after this one
    };

    // ngc_runner.cpp: reading lines and running ordinary ones.
    std::optional<InterpResult> run_line(std::vector<Move>& pending);
    std::optional<InterpResult> run_ordinary(std::vector<Move>& pending);
    std::optional<Diagnostic> resolve_block();
    std::optional<Diagnostic> comments();

    // ngc_translate.cpp, ngc_polar.cpp: LinuxCNC's meanings of words, as blocks for the Executor.
    std::optional<Diagnostic> translate_block();
    [[nodiscard]] std::optional<Diagnostic> check_tool_numbers() const;
    void split_dwell(Word& p);
    void comp_from_loaded_tool();
    std::optional<Diagnostic> translate_polar(std::vector<Block>& repeats);
    void add_motion_to_here();

    // ngc_inverse_time.cpp: G93.
    std::optional<Diagnostic> read_inverse_time();
    void apply_inverse_time(std::vector<Move>& pending, std::size_t first_new) const;
    void follow_linuxcnc_tapping(std::vector<Move>& pending, std::size_t first_new);
    std::optional<Diagnostic> back_off_after_probe(std::vector<Move>& pending, std::size_t first_new);
    [[nodiscard]] Diagnostic fail(std::uint32_t column, std::string message) const;
    [[nodiscard]] ProgramSource& source() { return *current_; }
    std::optional<Diagnostic> switch_to(const std::string& file, std::uint64_t offset, std::uint32_t line);

    // ngc_control.cpp: O-words.
    std::optional<Diagnostic> run_oword();
    std::optional<Diagnostic> call_sub(const std::string& name);
    std::optional<Diagnostic> return_from_sub();
    std::optional<Diagnostic> back_to(const std::string& name);
    std::optional<Diagnostic> save_label(const std::string& name);
    std::optional<Diagnostic> check_label(const std::string& name, std::initializer_list<OKind> kinds, Label*& out);
    [[nodiscard]] std::string full_name() const;
    [[nodiscard]] std::optional<std::filesystem::path> find_sub_file(const std::string& name) const;
    std::optional<Diagnostic> condition(double& value);

    // ngc_g7x.cpp: LinuxCNC's lathe cycles G70-G72, their shape read from a subroutine.
    [[nodiscard]] const Word* g7x_word() const;
    std::optional<InterpResult> run_g7x(std::vector<Move>& pending);
    std::optional<Diagnostic> collect_profile_line();
    [[nodiscard]] std::optional<Diagnostic> check_g7x_words(const G7xRequest& request, const Word& cycle_word) const;
    std::optional<Diagnostic> run_g7x_moves(const std::vector<ProfileMove>& moves, ZX from, const SourceLocation& where,
                                            std::vector<Move>& pending);

    // ngc_spline.cpp: G5, G5.1, G5.2/G5.3 as LinuxCNC's biarcs.
    //! The block is a spline's (names G5.x, or carries control point words while G5.2 gathers
    //! them, or axis words after G5.3). A block with another motion code ends that state.
    bool take_spline_block();
    std::optional<InterpResult> run_spline(std::vector<Move>& pending);
    std::optional<Diagnostic> run_spline_elements(const std::vector<SplineElement>& elements, Plane plane,
                                                  std::vector<Move>& pending, bool& program_end);

    // ngc_fanuc_subs.cpp: M98 and M99.
    std::optional<InterpResult> run_fanuc_sub_words(std::vector<Move>& pending);

    // ngc_state.cpp: parameters LinuxCNC keeps current, and its parameter file.
    void connect_live_parameters();
    [[nodiscard]] std::optional<double> live_numbered(std::int64_t n) const;
    //! G92.2 (offsets off, #5211-#5219 kept) and G92.3 (offsets back from them) as G92.1 / G92.
    std::optional<Diagnostic> translate_g92_kept();
    [[nodiscard]] std::optional<double> live_named(const std::string& name) const;
    std::optional<Diagnostic> load_parameter_file();
    std::optional<Diagnostic> apply_parameters(const std::map<std::int64_t, double>& values,
                                               const SourceLocation& where);
    [[nodiscard]] double to_program_units(double mm) const;
    //! `#123` and `#<name>` in a (print,...) or (debug,...) text replaced by their values.
    [[nodiscard]] std::string substitute_parameters(const std::string& text) const;
    [[nodiscard]] std::optional<double> axis_position(char letter) const;

    const MachineConfig& machine_;
    InterpreterOptions options_;
    Executor executor_;
    NgcParameters parameters_;
    std::map<std::string, std::unique_ptr<ProgramSource>> files_;
    ProgramSource* current_ = nullptr;
    std::string main_file_;
    std::unordered_map<std::string, Label> labels_;
    std::vector<Frame> frames_;
    std::optional<Diagnostic> startup_error_;

    NgcLine line_;
    Block block_;
    std::vector<Block> run_list_;  //!< what one line runs: block_, and a dwell before or repeats after it
    //! F of a recent G93 block, found again by its moves' source line.
    struct InverseFeed {
        const std::string* file = nullptr;
        std::uint32_t line = 0;
        double mm_per_min = 0;  //!< F x the programmed length, mm/min (deg/min for rotary alone)
    };
    std::vector<InverseFeed> inverse_feeds_;
    bool inverse_time_ = false;                       //!< G93 in force
    std::size_t repeats_from_ = 0;                    //!< index in run_list_ of the first repeat of a polar cycle
    static constexpr int max_polar_repeats = 100000;  //!< bounds L of a polar G91 cycle
    std::uint64_t line_offset_ = 0;
    std::uint64_t main_offset_ = 0;
    std::int64_t counted_lines_ = 0;
    std::set<std::int64_t> in_file_;                        //!< numbers the parameter file had: written back
    mutable std::vector<std::int64_t> persistent_numbers_;  //!< in_file_ and those LinuxCNC always writes
    mutable std::vector<RetainedVariable> persistent_seen_;
    mutable std::uint64_t persistent_changes_ = 0;
    bool repeating_ = false;        //!< a loop or call has run: lines count against the budget
    SourceLocation call_location_;  //!< the call a forward search for its sub started from

    // LinuxCNC's skipping state.
    std::string skipping_o_;        //!< skipping forward to this label; empty: not skipping
    bool skipping_to_sub_ = false;  //!< ... to its `sub` line, for a call
    bool fanuc_search_ = false;     //!< ... to its bare `O<n>` line, for M98
    bool defining_sub_ = false;     //!< passing over a sub's definition in the main program
    std::string sub_name_;          //!< the sub being defined
    bool executed_if_ = false;
    bool doing_break_ = false;
    bool doing_continue_ = false;
    bool seen_percent_ = false;
    bool seen_line_ = false;
    bool error_is_recoverable_ = false;
    //! Where the tool stands after a turned tapping feed: the next move starts there.
    std::optional<AxisVector> tool_at_;
    //! The running probe's start as the interpreter knows it (machine mm), for its back-off.
    std::optional<AxisVector> probe_start_;
    //! While a lathe cycle reads its shape: the shape so far.
    std::optional<ProfileReading> profile_;
    //! LinuxCNC's NURBS motion: 52 (G5.2, gathering points), 53 (after G5.3: no motion mode),
    //! 0 none (G5 and G5.1 are not modal).
    int spline_mode_ = 0;
    std::vector<NurbsControlPoint> nurbs_points_;
    unsigned nurbs_order_ = 3;
    //! I J of a G5 without them: -P -Q of the G5 before (the curve goes on smoothly).
    double spline_next_ij_[2]{};
    //! After G92.2: the G92 offsets #5211-#5219 kept for G92.3, program units (X Y Z A B C U V W).
    std::optional<std::array<double, 9>> g92_kept_;
};

}  // namespace nckit::interp::ngc
