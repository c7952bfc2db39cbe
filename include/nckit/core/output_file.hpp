#pragma once
// Where an output goes, chosen so that writing it never destroys what the name points at:
//   "-"                      standard output;
//   a device, pipe or socket written through (opened for writing, never replaced or removed);
//   a symlink                followed to the file it names, and that file is handled as below;
//   a regular file, or none  written as NAME.partial, then fsync'd and renamed over NAME, and
//                            the folder fsync'd, so a crash leaves the old or the new file.
// An unfinished NAME.partial is removed when the output is dropped and when the process is
// killed by SIGINT, SIGTERM, SIGHUP or SIGPIPE; a stale one from a crash is truncated, never read.
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

namespace nckit {

//! Why an output cannot be written: `NAME: cannot write: REASON (DETAIL)`.
struct OutputError {
    std::string name;    //!< as the user gave it
    std::string reason;  //!< strerror's text, e.g. "No such file or directory"
    std::string detail;  //!< what nckit found, e.g. "folder 'x' does not exist"; may be empty
    [[nodiscard]] std::string message() const;
};

class OutputFile {
public:
    enum class Kind { standard_output, write_through, atomic_replace };

    //! Opens the output named `name` (see above); nothing is created when it fails.
    [[nodiscard]] static std::variant<OutputFile, OutputError> open(const std::string& name);

    OutputFile(OutputFile&& other) noexcept;
    OutputFile& operator=(OutputFile&& other) noexcept;
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;
    ~OutputFile();  //!< an uncommitted atomic output is removed; the original stays as it was

    [[nodiscard]] std::FILE* get() const { return stream_; }
    [[nodiscard]] Kind kind() const { return kind_; }
    [[nodiscard]] const std::string& name() const { return name_; }
    //! The regular file that will be replaced (symlinks resolved); empty unless atomic_replace.
    [[nodiscard]] const std::filesystem::path& target() const { return target_; }
    void write(std::string_view bytes) { std::fwrite(bytes.data(), 1, bytes.size(), stream_); }

    //! Finishes the output: flushes; for an atomic output fsyncs, renames and fsyncs the folder.
    //! An error leaves the original file as it was and removes NAME.partial.
    [[nodiscard]] std::optional<OutputError> commit();

private:
    OutputFile() = default;
    void discard();
    std::string name_;
    std::filesystem::path target_;   // atomic_replace: the file renamed over
    std::filesystem::path partial_;  // atomic_replace: TARGET.partial
    std::FILE* stream_ = nullptr;    // null once committed, discarded or moved from
    Kind kind_ = Kind::standard_output;
    int registry_slot_ = -1;  // where the signal handler finds partial_
};

//! Replaces `path` (symlinks followed) by `bytes` through OutputFile: the atomic replace that
//! every file nckit keeps (retained variables) shares with the command line's outputs.
[[nodiscard]] std::optional<OutputError> write_file_atomically(const std::filesystem::path& path,
                                                               std::string_view bytes);

}  // namespace nckit
