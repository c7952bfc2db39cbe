#pragma once
// The crash-safe run journal (docs/restart.md#the-run-journal): while `nckit steps` or `servo`
// runs a program, one checksummed text record per completed block, with the block's number in
// the run, its line and N number, each axis's position at its end and the retained #500-#999
// it changed. Records are appended with one write each and synced every `fsync_interval_ms`,
// so a process killed at any instant leaves a journal whose complete records are all true; a
// torn or corrupt tail is detected by its checksum and ignored when the journal is read.
#include <chrono>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "nckit/core/result.hpp"
#include "nckit/interp/block_counter.hpp"
#include "nckit/interp/interpreter.hpp"

namespace nckit {

inline constexpr int journal_format_version = 1;

struct JournalOptions {
    //! The longest time between a record's write and its fsync, ms; 0: every record is synced
    //! before the next block is taken on. A power cut loses at most this much of the journal
    //! (the restart then begins a little earlier); a killed process loses nothing written.
    std::int64_t fsync_interval_ms = 250;
};

//! What the journal's first record holds: the run it belongs to.
struct JournalHeader {
    std::uint64_t program_bytes = 0;               //!< size of the main program file
    std::uint32_t program_crc = 0;                 //!< CRC-32 of its bytes
    std::string axes;                              //!< the machine's axis letters in order, e.g. "XYZ"
    std::vector<RetainedVariable> retained_start;  //!< #500-#999 when the run began
};

//! One completed block.
struct JournalBlock {
    std::int64_t block = 0;                       //!< ordinal among executed blocks, 1-based (restart --block)
    std::uint32_t line = 0;                       //!< source line
    std::int64_t sequence_number = -1;            //!< N number, -1 when none
    std::optional<std::vector<double>> position;  //!< per machine axis at its end; none before the first motion
    //! Retained variables the block changed: value, or none when it made one vacant.
    std::vector<std::pair<int, std::optional<double>>> retained_changes;
};

//! CRC-32 (IEEE 802.3, the zlib polynomial) of `bytes`, continuing from `crc`.
[[nodiscard]] std::uint32_t crc32(std::string_view bytes, std::uint32_t crc = 0);
//! CRC-32 and size of a file's bytes; an error naming the file when it cannot be read.
[[nodiscard]] Result<std::pair<std::uint64_t, std::uint32_t>> file_crc32(const std::filesystem::path& path);

//! One record line with its checksum: `PAYLOAD *CRC\n`.
[[nodiscard]] std::string journal_header_line(const JournalHeader& header);
[[nodiscard]] std::string journal_block_line(const JournalBlock& block, const std::string& axes);

//! Writes the journal of one run. Feed it every move (on_move, right after the interpreter
//! returned it) and, once the machine has taken a piece of motion, the source location of the
//! block it came from (on_reached: a trajectory piece's, or a move a LinuxCNC plug-in has
//! executed): a block is complete when a later block has been reached, or at finish().
class RunJournal {
public:
    //! Creates (truncates) `path` and writes the header; an error when it cannot.
    [[nodiscard]] static Result<RunJournal> create(const std::filesystem::path& path, const Interpreter& interpreter,
                                                   const std::filesystem::path& program, JournalOptions options);
    RunJournal(RunJournal&&) noexcept;
    RunJournal& operator=(RunJournal&&) noexcept;
    ~RunJournal();

    void on_move(const Interpreter& interpreter, const Move& move);
    void on_reached(const SourceLocation& where);
    //! The run ended clean: every block is complete; the journal is synced and closed.
    void finish();
    //! The first write or sync that failed, if any (the journal stops there).
    [[nodiscard]] const std::optional<Diagnostic>& error() const { return error_; }
    [[nodiscard]] std::int64_t blocks_written() const { return written_; }

private:
    RunJournal() = default;
    struct Pending {
        JournalBlock record;
        const std::string* file = nullptr;
    };
    void complete(std::size_t count);
    void write(const std::string& text, bool sync_now);

    int fd_ = -1;
    std::string path_;
    std::string axes_;
    std::vector<Axis> axis_order_;
    JournalOptions options_;
    BlockCounter blocks_;
    std::deque<Pending> pending_;  // blocks whose pieces may still be ahead, oldest first
    std::optional<std::vector<double>> position_;
    std::uint64_t retained_writes_ = 0;
    std::vector<RetainedVariable> retained_;
    std::chrono::steady_clock::time_point last_sync_;
    std::int64_t written_ = 0;
    std::optional<Diagnostic> error_;
};

//! A journal as read back: the header and the complete records before the first bad one.
struct JournalContents {
    JournalHeader header;
    std::optional<JournalBlock> last;                //!< the last complete block; none if no block completed
    std::vector<RetainedVariable> retained_at_last;  //!< #500-#999 after it (the start values folded with every change)
    std::int64_t records = 0;                        //!< complete block records
    std::uint64_t ignored_bytes = 0;                 //!< the torn or corrupt tail, not trusted
};

//! Reads a journal with the torn-tail rule: records are trusted up to the first one that is
//! incomplete (no newline), fails its checksum, does not parse, or does not number its block
//! one more than the record before; that one and everything after it are ignored. An error
//! (`journal-unreadable`) only when the file cannot be read or has no complete header.
[[nodiscard]] Result<JournalContents> read_journal(const std::filesystem::path& path);

}  // namespace nckit
