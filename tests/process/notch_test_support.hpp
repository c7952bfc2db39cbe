#pragma once
// What the notch tests share: the example notcher and programs interpreted into moves (a program
// that does not interpret is a test failure, not an empty move list).
#include <gtest/gtest.h>

#include <string>
#include <variant>
#include <vector>

#include "nckit/gcode/program_source.hpp"
#include "nckit/interp/interpreter.hpp"

namespace nckit::notch_test {

inline MachineConfig notcher() {
    Result<MachineConfig> machine =
        load_machine_config(std::string(NCKIT_SOURCE_DIR) + "/examples/machines/notcher.toml");
    EXPECT_TRUE(machine.ok());
    return *machine;
}

inline std::vector<Move> interpret(ProgramSource source, const MachineConfig& machine) {
    Interpreter interpreter(machine, std::move(source));
    std::vector<Move> moves;
    for (;;) {
        InterpResult result = interpreter.next();
        if (std::holds_alternative<ProgramEnd>(result)) break;
        if (const auto* d = std::get_if<Diagnostic>(&result)) {
            ADD_FAILURE() << format_diagnostic(*d);
            break;
        }
        moves.push_back(std::get<Move>(result));
    }
    return moves;
}

//! A program given as text (file name t.nc in its diagnostics).
inline std::vector<Move> program(const std::string& text, const MachineConfig& machine) {
    return interpret(ProgramSource::from_string(text, "t.nc"), machine);
}

//! A program file, relative to the source folder.
inline std::vector<Move> file(const std::string& path, const MachineConfig& machine) {
    Result<ProgramSource> source = ProgramSource::open(std::string(NCKIT_SOURCE_DIR) + "/" + path);
    EXPECT_TRUE(source.ok()) << path;
    return interpret(std::move(*source), machine);
}

}  // namespace nckit::notch_test
