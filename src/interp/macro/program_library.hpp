#pragma once
// Where programs are: the O-numbered programs of the main file, and a library folder with one
// file per program number, standing in for a control's program memory. Indexed lazily, on the
// first call, so a plain program pays nothing.
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>

#include "nckit/core/result.hpp"
#include "nckit/gcode/program_source.hpp"

namespace nckit::interp {

struct ProgramLocation {
    std::string file;           //!< path (or the name of a program given as text)
    bool in_main_file = false;  //!< read with a second reader of the main program
    std::uint64_t offset = 0;   //!< the O line, or 0 for a library file
    std::uint32_t line = 1;
};

//! The program number an `O` line starts, if the line is one (`O1234`, `O1234 (NAME)`).
[[nodiscard]] std::optional<std::int64_t> program_number_of(std::string_view line);

//! The sequence number a line starts with (`N120 ...`, `/N120 ...`), if any.
[[nodiscard]] std::optional<std::int64_t> sequence_number_of(std::string_view line);

class ProgramLibrary {
public:
    explicit ProgramLibrary(std::filesystem::path library_dir);

    //! Where program `number` starts, nothing when it exists nowhere, or a read error. `main` is
    //! the reader of the main program (its file is searched first).
    [[nodiscard]] Result<std::optional<ProgramLocation>> find(std::int64_t number, const ProgramSource& main);

private:
    std::optional<Diagnostic> index_main_file(const ProgramSource& main);
    void index_library();

    std::filesystem::path library_dir_;
    bool main_indexed_ = false;
    bool library_indexed_ = false;
    std::map<std::int64_t, ProgramLocation> main_programs_;
    std::map<std::int64_t, std::filesystem::path> library_programs_;
};

}  // namespace nckit::interp
