// 01: from program text to moves.
//
// The interpreter reads a program one block at a time and hands out Moves: lines, arcs, dwells
// and I/O events in absolute machine coordinates (mm, deg), each with the block that made it.
// A bad block is not an exception but a Diagnostic value with its file, line and column.
#include <cstdio>
#include <string>
#include <variant>

#include "nckit/core/machine.hpp"
#include "nckit/gcode/program_source.hpp"
#include "nckit/interp/interpreter.hpp"
#include "nckit/interp/move_format.hpp"

// A 15 × 10 mm pocket outline with one rounded corner, on the built-in mill.
constexpr const char* program = R"nc(%
O0001 (outline with a rounded corner)
G21 G90 G17 G94
G0 X0 Y0 Z5
G1 Z-1 F300
G1 X10 F600
G3 X15 Y5 R5
G1 Y10
G1 X0
G1 Y0
G0 Z5
M30
%
)nc";

// The same start, but the arc's radius is too small to reach its end point.
constexpr const char* bad_program = R"nc(G21 G90 G17
G0 X0 Y0
G2 X20 Y0 R5 F600
M30
)nc";

// Runs one program to its end and prints every move the way `nckit moves` does. Returns false
// after printing the diagnostic of the block that stopped it.
bool print_moves(const std::string& text, const std::string& file_name) {
    const nckit::MachineConfig machine = nckit::default_mill();
    nckit::Interpreter interpreter(machine, nckit::ProgramSource::from_string(text, file_name));
    std::string line;
    for (;;) {
        // next() answers with a Move, the program's end, or the Diagnostic that stops it.
        nckit::InterpResult result = interpreter.next();
        if (std::holds_alternative<nckit::ProgramEnd>(result)) return true;
        if (const auto* error = std::get_if<nckit::Diagnostic>(&result)) {
            std::printf("%s\n", nckit::format_diagnostic(*error).c_str());
            return false;
        }
        const nckit::Move& move = std::get<nckit::Move>(result);
        line.clear();
        nckit::append_move_text(line, move, machine);  // e.g. `G1 X10.0000 Y0.0000 Z-1.0000 F600.0000`
        std::printf("%s\n", line.c_str());
    }
}

int main() {
    if (!print_moves(program, "outline.nc")) return 1;
    // The error is a value: the caller decides what to do with it (here: print and go on).
    std::printf("--\n");
    if (print_moves(bad_program, "bad.nc")) return 1;  // it must not run to the end
    return 0;
}
