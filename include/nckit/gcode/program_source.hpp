#pragma once
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "nckit/core/result.hpp"

namespace nckit {

//! Reads a program one line at a time from a file or a string, so that a program of any length
//! runs in bounded memory. It can seek back to a line it has passed (loops, GOTO, subprograms).
class ProgramSource {
public:
    //! One line of the program, without its line end.
    struct Line {
        std::string_view text;     //!< valid until the next call to next() or seek()
        std::uint32_t number = 0;  //!< 1-based
        std::uint64_t offset = 0;  //!< byte offset of the line's first character
    };

    //! A block longer than this is an error, never a silent truncation.
    static constexpr std::size_t max_line_bytes = 64 * 1024;

    [[nodiscard]] static Result<ProgramSource> open(const std::filesystem::path& path);
    [[nodiscard]] static ProgramSource from_string(std::string text, std::string name);

    ProgramSource(ProgramSource&&) noexcept;
    ProgramSource& operator=(ProgramSource&&) noexcept;
    ~ProgramSource();

    //! The next line, nothing at the end of input, or an error (line too long, read failure).
    [[nodiscard]] Result<std::optional<Line>> next();

    //! Where the next line starts, to come back to with seek().
    [[nodiscard]] std::uint64_t next_offset() const { return buffer_offset_ + begin_; }
    [[nodiscard]] std::uint32_t next_line_number() const { return line_number_ + 1; }

    //! More lines at the end of a program made from a string (MDI: each command a further line
    //! of one growing program); a line end is added when `text` has none. Not for files.
    void append(std::string_view text);

    //! Continue reading at a line returned earlier.
    void seek(std::uint64_t offset, std::uint32_t line_number);

    //! A second, independent reader of the same program from its start (for subprograms in the
    //! same file). A program read from a pipe cannot be read twice: that is an error.
    [[nodiscard]] Result<ProgramSource> reopen() const;

    [[nodiscard]] const std::shared_ptr<const std::string>& file() const { return name_; }
    //! Lines passed can be read again after seek(): false for standard input and other pipes.
    [[nodiscard]] bool rereadable() const { return rereadable_; }

private:
    ProgramSource() = default;
    bool refill();

    std::shared_ptr<const std::string> name_;
    std::FILE* file_ = nullptr;        // null when reading from text_
    std::string text_;                 // whole program (string input) or the read buffer (file input)
    std::size_t begin_ = 0;            // next unread byte in text_
    std::size_t end_ = 0;              // end of valid bytes in text_
    std::uint64_t buffer_offset_ = 0;  // file offset of text_[0]
    std::uint32_t line_number_ = 0;
    bool eof_ = false;
    bool rereadable_ = true;
    std::string line_;  // a line that straddles two buffer fills
};

}  // namespace nckit
