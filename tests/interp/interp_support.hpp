#pragma once
// Runs a program string through the Interpreter and hands back its moves or its error, in forms
// a test can compare in one line.
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <gtest/gtest.h>

#include "nckit/core/machine.hpp"
#include "nckit/interp/interpreter.hpp"
#include "nckit/interp/move_format.hpp"

namespace nckit::test {

struct RunResult {
    std::vector<Move> moves;          //!< every move streamed before the end or the error
    std::optional<Diagnostic> error;  //!< what stopped the program, if it did not end
};

inline RunResult run_program(std::string_view program, const MachineConfig& machine = default_mill(),
                             InterpreterOptions options = {}) {
    Interpreter interpreter(machine, ProgramSource::from_string(std::string(program), "test.ngc"), options);
    RunResult result;
    for (int guard = 0; guard < 10'000'000; ++guard) {
        InterpResult next = interpreter.next();
        if (auto* move = std::get_if<Move>(&next)) {
            result.moves.push_back(std::move(*move));
            continue;
        }
        if (auto* error = std::get_if<Diagnostic>(&next)) result.error = *error;
        return result;
    }
    ADD_FAILURE() << "program never ended";
    return result;
}

//! The moves of a program that must run without error.
inline std::vector<Move> moves_of(std::string_view program, const MachineConfig& machine = default_mill(),
                                  InterpreterOptions options = {}) {
    RunResult result = run_program(program, machine, options);
    if (result.error) ADD_FAILURE() << format_diagnostic(*result.error) << "\nin:\n" << program;
    return result.moves;
}

//! The error of a program that must fail.
inline Diagnostic error_of(std::string_view program, const MachineConfig& machine = default_mill(),
                           InterpreterOptions options = {}) {
    RunResult result = run_program(program, machine, options);
    if (!result.error) {
        ADD_FAILURE() << "no error in:\n" << program;
        return {};
    }
    EXPECT_EQ(result.error->location.file_name(), "test.ngc");
    EXPECT_EQ(result.error->severity, Severity::error);
    return *result.error;
}

//! `code LINE:COL`: what a test states about an error, in one comparison.
inline std::string where(const Diagnostic& d) {
    return d.code + " " + std::to_string(d.location.line) + ":" + std::to_string(d.location.column);
}

inline std::string error_where(std::string_view program, const MachineConfig& machine = default_mill()) {
    return where(error_of(program, machine));
}

//! The moves as `nckit moves` prints them (4 decimals, every axis of the machine).
inline std::vector<std::string> texts(std::string_view program, const MachineConfig& machine = default_mill(),
                                      InterpreterOptions options = {}) {
    std::vector<std::string> out;
    for (const Move& move : moves_of(program, machine, options)) {
        std::string line;
        append_move_text(line, move, machine);
        out.push_back(line);
    }
    return out;
}

using Texts = std::vector<std::string>;

//! The moves of one kind, in order.
template <class T>
std::vector<T> only(const std::vector<Move>& moves) {
    std::vector<T> out;
    for (const Move& move : moves) {
        if (const T* what = std::get_if<T>(&move.what)) out.push_back(*what);
    }
    return out;
}

//! The single move of one kind in a program.
template <class T>
T the(std::string_view program, const MachineConfig& machine = default_mill()) {
    std::vector<T> all = only<T>(moves_of(program, machine));
    if (all.size() != 1) {
        ADD_FAILURE() << "expected one move of that kind, got " << all.size() << " in:\n" << program;
        return T{};
    }
    return all.front();
}

inline AxisVector xyz(double x, double y, double z) {
    AxisVector v;
    v[Axis::X] = x;
    v[Axis::Y] = y;
    v[Axis::Z] = z;
    return v;
}

//! A lathe: X (diameter words, radius moves) and Z; travel X 0..200 mm radius, Z -300..10 mm.
inline MachineConfig lathe() {
    MachineConfig m = default_mill();
    m.name = "test-lathe";
    m.diameter_mode = true;
    m.axes = {m.axes[0], m.axes[2]};
    m.axes[0].min = -10.0;
    m.axes[0].max = 200.0;
    m.axes[1].min = -300.0;
    m.axes[1].max = 10.0;
    m.spindle.max_rpm = 4000.0;
    return m;
}

//! The default mill with a rotary A axis (-720..720 deg) after X Y Z.
inline MachineConfig mill_with_a() {
    MachineConfig m = default_mill();
    AxisConfig a = m.axes[0];
    a.axis = Axis::A;
    a.kind = AxisKind::rotary;
    a.min = -720.0;
    a.max = 720.0;
    m.axes.push_back(a);
    return m;
}

//! The default mill reading LinuxCNC's dialect (tests of the NGC interpreter).
inline MachineConfig linuxcnc_mill() {
    MachineConfig machine = default_mill();
    machine.dialect = Dialect::linuxcnc;
    return machine;
}

//! "LINE:COL message" of a diagnostic (without its code), as LinuxCNC's errors are compared.
inline std::string at(const Diagnostic& d) {
    return std::to_string(d.location.line) + ":" + std::to_string(d.location.column) + " " + d.message;
}

}  // namespace nckit::test
