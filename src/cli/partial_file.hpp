#pragma once
// An output file that appears under its name only when complete: it is written as NAME.partial,
// renamed by commit(), and removed if never committed, so a bad program leaves no output.
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>

namespace nckit::cli {

class PartialFile {
public:
    //! Opens NAME.partial; prints `NAME:0:0: error: cannot write` and gives nothing if it cannot.
    [[nodiscard]] static std::optional<PartialFile> create(const std::string& name);

    PartialFile(PartialFile&& other) noexcept;
    PartialFile& operator=(PartialFile&& other) noexcept;
    PartialFile(const PartialFile&) = delete;
    ~PartialFile();

    [[nodiscard]] std::FILE* get() const { return file_; }
    void write(std::string_view bytes) { std::fwrite(bytes.data(), 1, bytes.size(), file_); }

    //! Closes and renames; false (error printed, nothing left behind) when writing failed.
    [[nodiscard]] bool commit();

private:
    PartialFile(std::string name, std::FILE* file) : name_(std::move(name)), file_(file) {}
    void discard();  //!< close and remove an uncommitted file
    std::string name_;
    std::FILE* file_ = nullptr;  // null once committed or moved from
};

}  // namespace nckit::cli
