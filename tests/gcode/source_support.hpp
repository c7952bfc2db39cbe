#pragma once
// Helpers for the ProgramSource tests: lines as comparable values, temporary files, programs
// built to straddle the read buffer.
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "nckit/gcode/program_source.hpp"

namespace nckit::test {

namespace fs = std::filesystem;

// The read buffer of a file source (program_source.cpp); the straddle tests are built around it.
inline constexpr std::size_t buffer_bytes = std::size_t{1} << 20;

//! A line as the tests compare it: text, number and offset in one value.
struct Got {
    std::string text;
    std::uint32_t number = 0;
    std::uint64_t offset = 0;
    friend bool operator==(const Got&, const Got&) = default;
};

inline std::ostream& operator<<(std::ostream& os, const Got& g) {
    return os << "{\"" << (g.text.size() > 40 ? g.text.substr(0, 40) + "..." : g.text) << "\" (" << g.text.size()
              << " bytes), line " << g.number << ", offset " << g.offset << "}";
}

//! The next line, or nothing at the end of input; fails the test on an error.
inline std::optional<Got> read(ProgramSource& source) {
    auto line = source.next();
    if (!line.ok()) {
        ADD_FAILURE() << format_diagnostic(line.diagnostics().front());
        return std::nullopt;
    }
    if (!line.value()) return std::nullopt;
    return Got{std::string((*line)->text), (*line)->number, (*line)->offset};
}

//! The next line, which must be there.
inline Got next_line(ProgramSource& source) {
    std::optional<Got> line = read(source);
    if (!line) ADD_FAILURE() << "unexpected end of input";
    return line.value_or(Got{});
}

inline bool at_end(ProgramSource& source) {
    auto line = source.next();
    return line.ok() && !line.value();
}

//! Every line until the end of input.
inline std::vector<Got> all_lines(ProgramSource& source) {
    std::vector<Got> lines;
    while (std::optional<Got> line = read(source)) lines.push_back(*line);
    return lines;
}

//! A folder of its own for one test, removed afterwards.
class TempDir {
public:
    TempDir() {
        static int counter = 0;
        path_ = fs::temp_directory_path() /
                ("nckit_source_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
        fs::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    fs::path write(const std::string& name, const std::string& content) const {
        fs::path file = path_ / name;
        std::ofstream(file, std::ios::binary) << content;
        return file;
    }
    [[nodiscard]] const fs::path& path() const { return path_; }

private:
    fs::path path_;
};

inline ProgramSource open_file(const fs::path& path) {
    auto source = ProgramSource::open(path);
    if (!source.ok()) {
        ADD_FAILURE() << format_diagnostic(source.diagnostics().front());
        return ProgramSource::from_string("", "failed");
    }
    return std::move(source).value();
}

//! The lines `text` splits into at '\n' with their 1-based numbers and offsets: what a source
//! must return for it (for text without '\r').
inline std::vector<Got> expected_lines(const std::string& text) {
    std::vector<Got> lines;
    std::size_t start = 0;
    std::uint32_t number = 1;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        lines.push_back(Got{text.substr(start, end - start), number++, start});
        start = end + 1;
    }
    return lines;
}

//! A program of G1 lines of varying length, at least `bytes` long, with lines that are not
//! aligned to anything.
inline std::string long_program(std::size_t bytes) {
    std::string text;
    for (int i = 0; text.size() < bytes; ++i) {
        text += "N" + std::to_string(i) + " G1 X" + std::to_string(i % 997) + "." +
                std::string(static_cast<std::size_t>(i % 13), '5') + " Y" + std::to_string(i % 31) + "\n";
    }
    return text;
}

//! Exactly `bytes` of short comment lines ("(AAA...)"), each ending in '\n'.
inline std::string filler(std::size_t bytes) {
    std::string text;
    while (text.size() < bytes) {
        std::size_t left = bytes - text.size();
        std::size_t line = left >= 200 ? 100 : left;  // never leave a remainder too short for "()\n"
        if (line < 3) {
            text += std::string(line - 1, ' ') + "\n";
            continue;
        }
        text += "(" + std::string(line - 3, 'A') + ")\n";
    }
    return text;
}

}  // namespace nckit::test
