#pragma once
// Helpers for the Custom Macro B tests: read a macro value back through the moves, state an
// alarm in one comparison, and make scratch folders for program libraries and retained files.
#include <atomic>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <unistd.h>

#include "interp_support.hpp"

namespace nckit::test {

//! The default mill with a travel of +-1e6 mm, so that any value fits in an X word.
inline MachineConfig wide_mill() {
    MachineConfig m = default_mill();
    for (AxisConfig& axis : m.axes) {
        axis.min = -1e6;
        axis.max = 1e6;
    }
    return m;
}

//! The X end point of every line and arc, in order (mm, machine coordinates).
inline std::vector<double> xs(std::string_view program, InterpreterOptions options = {},
                              const MachineConfig& machine = wide_mill()) {
    std::vector<double> out;
    for (const Move& move : moves_of(program, machine, std::move(options))) {
        if (const auto* line = std::get_if<Line>(&move.what)) out.push_back(line->to[Axis::X]);
        if (const auto* arc = std::get_if<Arc>(&move.what)) out.push_back(arc->to[Axis::X]);
    }
    return out;
}

//! The exact value `#1` holds after `setup`, or nothing when it is vacant. It is read back as
//! the G64 P tolerance of a marked move (N99998): P is neither rounded nor scaled in mm. It must
//! not be negative (x_of in the expression tests reads negatives, to 0.001).
inline std::optional<double> value_after(std::string_view setup) {
    constexpr std::int64_t mark = 99998;
    std::string program = std::string(setup) + "\nG21\nIF [#1 EQ #0] GOTO 99999\nG64 P#1\nN99998 G1 X0 F100\nN99999\n";
    std::optional<double> out;
    for (const Move& move : moves_of(program, wide_mill())) {
        const auto* line = std::get_if<Line>(&move.what);
        if (line != nullptr && move.sequence_number == mark) out = line->path.tolerance_mm;
    }
    return out;
}

//! The exact value of `expression` (not negative), through `#1 = expression`.
inline std::optional<double> value_of(std::string_view expression) {
    return value_after("#1=" + std::string(expression));
}

//! `ALARM LINE:COL` of the error that stops `program`: a macro alarm in one comparison.
inline std::string alarm_of(std::string_view program, InterpreterOptions options = {},
                            const MachineConfig& machine = wide_mill()) {
    Diagnostic d = error_of(program, machine, std::move(options));
    return std::to_string(d.alarm) + " " + std::to_string(d.location.line) + ":" + std::to_string(d.location.column);
}

//! A fresh empty folder under the system's temporary folder, removed with the object.
class ScratchDir {
public:
    ScratchDir() {
        static std::atomic<int> counter{0};
        path_ = std::filesystem::temp_directory_path() /
                ("nckit-macro-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;
    ~ScratchDir() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }

    [[nodiscard]] const std::filesystem::path& path() const { return path_; }

    //! Writes `text` to `name` in the folder and returns its path.
    std::filesystem::path write(const std::string& name, std::string_view text) const {
        std::filesystem::path file = path_ / name;
        std::ofstream(file, std::ios::binary) << text;
        return file;
    }

    [[nodiscard]] std::string read(const std::string& name) const {
        std::ifstream in(path_ / name, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }

private:
    std::filesystem::path path_;
};

}  // namespace nckit::test
