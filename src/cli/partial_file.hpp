#pragma once
// A command-line output (-o, --trace, --svg, ...) through nckit::OutputFile: "-" is standard
// output, devices, pipes and sockets are written through, symlinks are followed, and a regular
// file appears under its name only when complete (NAME.partial, fsync, rename), so a bad program
// leaves the old file as it was. Errors print `NAME: cannot write: REASON (DETAIL)`.
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>

#include "nckit/core/output_file.hpp"

namespace nckit::cli {

class PartialFile {
public:
    //! Opens the output; prints why and gives nothing if it cannot.
    [[nodiscard]] static std::optional<PartialFile> create(const std::string& name);

    [[nodiscard]] std::FILE* get() const { return file_.get(); }
    void write(std::string_view bytes) { file_.write(bytes); }
    [[nodiscard]] bool is_stdout() const { return file_.kind() == OutputFile::Kind::standard_output; }

    //! Completes the output; false (error printed, the original left as it was) when it failed.
    [[nodiscard]] bool commit();

private:
    explicit PartialFile(OutputFile file) : file_(std::move(file)) {}
    OutputFile file_;
};

//! Prints an output error as `NAME: cannot write: REASON (DETAIL)`.
void print_output_error(const OutputError& error);

}  // namespace nckit::cli
