#pragma once
// Runs a program's blocks in the order Custom Macro B gives them: statements (assignments, IF,
// GOTO, WHILE/DO/END), calls (G65, G66/G67, M98, M99) and the NC blocks, which it hands to the
// Executor after evaluating their expressions.
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <unordered_map>
#include <vector>

#include "executor.hpp"
#include "sequence_index.hpp"
#include "macro/evaluate.hpp"
#include "macro/program_library.hpp"
#include "macro/variables.hpp"
#include "nckit/interp/interpreter.hpp"

namespace nckit::interp {

//! An active WHILE/DO range.
struct LoopEntry {
    int number = 0;            //!< m of DOm
    std::uint64_t offset = 0;  //!< the DO block's line, where ENDm goes back to
    std::uint32_t line = 0;
    std::uint32_t column = 0;  //!< where its WHILE / DO statement starts, for alarms
};

//! One level of the call stack: the main program, a subprogram (M98) or a macro (G65/G66).
struct Frame {
    ProgramLocation program;
    std::int64_t program_number = 0;  //!< #4115; 0 when the program has no O number
    std::uint64_t return_offset = 0;  //!< the caller's next line
    std::uint32_t return_line = 0;
    int repeats_left = 1;      //!< L count still to run, this run included
    bool own_locals = false;   //!< G65/G66: a fresh set of #1-#33
    bool modal_call = false;   //!< started by G66 after a move
    bool started = false;      //!< a block of it has been read (its O line is its header)
    bool jumped_back = false;  //!< blocks now count against the runaway budget
    std::vector<LoopEntry> loops;
};

class ProgramRunner final : public SystemVariables {
public:
    ProgramRunner(const MachineConfig& machine, ProgramSource main, const InterpreterOptions& options);

    //! Runs blocks until moves are queued in `pending`, the program ends, or an error stops it.
    [[nodiscard]] std::optional<InterpResult> fill(std::vector<Move>& pending);

    //! Writes #500-#999 back when the program changed them and a file is configured.
    [[nodiscard]] std::optional<Diagnostic> save_retained() const;
    //! The error fill() last returned was in a block of the main program and the run can go on
    //! with the next block (see InterpreterOptions::keep_going_after_errors).
    [[nodiscard]] bool error_is_recoverable() const { return error_is_recoverable_; }
    [[nodiscard]] std::uint64_t main_program_offset() const { return sources_.empty() ? 0 : sources_[0].next_offset(); }

    [[nodiscard]] ModalView modal_view() const { return executor_.modal_view(); }
    //! Called programs in progress: 0 in the main program.
    [[nodiscard]] int call_depth() const { return static_cast<int>(frames_.size()) - 1; }
    //! The file of the program running now (a called one's when in a call).
    [[nodiscard]] const std::string& current_file() const { return *sources_[frames_.size() - 1].file(); }
    void append_main(std::string_view text) { sources_[0].append(text); }
    //! Inside a call: the line of the main program's block that made the outermost call; 0 else.
    [[nodiscard]] std::uint32_t calling_line() const {
        return frames_.size() > 1 && frames_[1].return_line > 0 ? frames_[1].return_line - 1 : 0;
    }
    void set_position(const AxisVector& machine) { executor_.set_position(machine); }
    [[nodiscard]] std::uint64_t retained_writes() const { return variables_.retained_writes(); }
    [[nodiscard]] std::vector<RetainedVariable> retained_values() const;

    [[nodiscard]] std::optional<MacroValue> read_system(std::int64_t number) const override;
    [[nodiscard]] std::optional<SystemVariables::WriteError> write_system(std::int64_t number, double value) override;

private:
    // program_runner.cpp: reading and running blocks.
    std::optional<InterpResult> run_block(const Block& block, std::vector<Move>& pending);
    std::optional<Diagnostic> resolve_words(const Block& block, Block& resolved);
    [[nodiscard]] ProgramSource& source() { return sources_[frames_.size() - 1]; }
    [[nodiscard]] Frame& frame() { return frames_.back(); }
    [[nodiscard]] Diagnostic alarm_at(const Block& block, std::uint32_t column, int alarm, std::string message) const;

    // runner_flow.cpp: statements, jumps and loops.
    //! #3006's stop: an M0 event and the message as a warning.
    void program_stop(const Block& block, std::vector<Move>& pending);
    std::optional<Diagnostic> run_statement(const Block& block);
    std::optional<Diagnostic> assign(const Block& block);
    std::optional<Diagnostic> jump_to_sequence(const Block& block, std::uint32_t column, std::int64_t number);
    //! The index of the running program's sequence numbers, read on its first GOTO: once per
    //! program and run, so its cost is that of reading the program once and is not counted
    //! against the runaway budget (each jump is a block, counted after a jump back). Null when
    //! the program cannot be read twice or numbers too many lines: GOTO then searches line by
    //! line, and every line searched counts against the budget.
    const SequenceIndex* sequence_index();
    std::optional<Diagnostic> start_loop(const Block& block, bool condition_holds);
    std::optional<Diagnostic> end_loop(const Block& block);
    std::optional<Diagnostic> skip_past_end(const Block& block, int loop);
    [[nodiscard]] std::optional<Diagnostic> condition(const Block& block, bool& holds);
    [[nodiscard]] InterpResult end_of_main() const;
    //! end_of_main(), and on a clean end the moves cutter compensation still holds go out first.
    [[nodiscard]] InterpResult finish_main(std::vector<Move>& pending);

    // runner_sequences.cpp: the P-Q blocks of a lathe cycle.
    std::optional<Diagnostic> read_sequence(std::int64_t p, std::int64_t q, std::vector<Block>& out);
    struct SequenceEnd {
        std::uint64_t offset = 0;
        std::uint32_t line = 0;
    } sequence_end_;

    // runner_calls.cpp: G65, G66/G67, M98, M99.
    std::optional<InterpResult> run_nc_block(const Block& block, std::vector<Move>& pending);
    std::optional<Diagnostic> call(const Block& block, std::uint32_t column, std::int64_t program, int repeats,
                                   bool own_locals, const Variables::Locals* arguments, bool modal);
    std::optional<Diagnostic> return_from_call(const Block& block, std::int64_t sequence);
    std::optional<Diagnostic> arguments_of(const Block& block, Variables::Locals& arguments) const;

    const MachineConfig& machine_;
    InterpreterOptions options_;
    EvalSettings eval_settings_;
    Executor executor_;
    Variables variables_;
    ProgramLibrary library_;
    std::vector<ProgramSource> sources_;  // one reader per call depth; [0] reads the main program
    std::vector<Frame> frames_;
    std::optional<Diagnostic> startup_error_;

    struct ModalCall {
        std::int64_t program = -1;  //!< -1: no G66 active
        int repeats = 1;
        Variables::Locals arguments{};
    } modal_call_;

    //! Parsed blocks of loops and called programs, by file and offset: a loop body is parsed
    //! once, not once per pass.
    struct CacheKey {
        const std::string* file;  // the reader's file name; CachedBlock::file keeps it alive
        std::uint64_t offset;
        bool operator==(const CacheKey&) const = default;
    };
    struct CacheKeyHash {
        std::size_t operator()(const CacheKey& k) const {
            return std::hash<const void*>{}(k.file) ^ (std::hash<std::uint64_t>{}(k.offset) * 0x9E3779B97F4A7C15ULL);
        }
    };
    struct CachedBlock {
        std::shared_ptr<const std::string> file;
        Block block;
        std::uint64_t next_offset = 0;
        std::uint32_t next_line = 0;
    };
    static constexpr std::size_t max_cached_blocks = 16384;
    [[nodiscard]] bool repeating() const;  //!< blocks here may run again: cache and count them
    //! The first line of the main program is a leader when the tape start '%' follows it.
    [[nodiscard]] bool is_leader(const ProgramSource::Line& first);
    const Block* cached_block();
    const Block* remember(const Block& block);
    std::unordered_map<CacheKey, CachedBlock, CacheKeyHash> block_cache_;
    //! By file and the offset where the program starts; nullopt: too many numbered lines.
    std::map<std::pair<std::string, std::uint64_t>, std::optional<SequenceIndex>> sequence_indexes_;
    const Block* current_block_ = nullptr;  // the block being run (for #3000's message)

    Block block_;                    // the block being read
    Block resolved_;                 // its words with expressions evaluated
    Block scan_;                     // scratch for searches (GOTO, skipping a loop)
    std::uint64_t line_offset_ = 0;  // where the block being run starts in its file
    std::int64_t counted_blocks_ = 0;
    std::uint64_t moves_made_ = 0;          // moves and I/O events of the whole run
    std::uint64_t moves_at_main_pass_ = 0;  // moves_made_ when M99 last restarted the main program
    std::int64_t last_sequence_ = 0;        // #4114
    double timer_ms_base_s_ = 0;            // #3001 = (elapsed - base) in ms
    double timer_hours_base_s_ = 0;         // #3002
    bool stop_requested_ = false;           // #3006 = 1 (MESSAGE) in the statement just run
    bool seen_tape_mark_ = false;
    bool seen_block_ = false;
    bool leader_checked_ = false;  // the file's first line was looked at as a leader
    bool error_is_recoverable_ = false;
};

}  // namespace nckit::interp
