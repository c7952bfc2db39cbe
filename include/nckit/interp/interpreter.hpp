#pragma once
#include <memory>
#include <variant>

#include "nckit/core/diagnostic.hpp"
#include "nckit/core/machine.hpp"
#include "nckit/gcode/program_source.hpp"
#include "nckit/interp/move.hpp"

namespace nckit {

struct InterpreterOptions {
    //! The operator's block delete switch: when on, blocks that start with '/' are skipped.
    //! Off by default, as on a Fanuc control at power-on and in LinuxCNC's rs274.
    bool block_delete = false;
    //! An arc whose end lies off its circle by more than this (and by more than 0.1 % of the
    //! radius) is an error, as in LinuxCNC.
    double arc_radius_tolerance_mm = 0.01;
};

//! The program ended: M2, M30, a closing '%', or the end of the file.
struct ProgramEnd {};

//! One answer from the interpreter: a move, the end of the program, or the error that stops it.
using InterpResult = std::variant<Move, ProgramEnd, Diagnostic>;

//! Runs a program block by block and streams its moves: memory stays bounded whatever the
//! program's length. After an error or the end, every further call repeats that answer.
class Interpreter {
public:
    Interpreter(MachineConfig machine, ProgramSource source, InterpreterOptions options = {});
    Interpreter(Interpreter&&) noexcept;
    Interpreter& operator=(Interpreter&&) noexcept;
    ~Interpreter();

    [[nodiscard]] InterpResult next();

    [[nodiscard]] const MachineConfig& machine() const;

private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace nckit
