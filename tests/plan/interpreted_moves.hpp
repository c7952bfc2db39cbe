#pragma once
// The moves of a whole program text, as the planner receives them; a diagnostic fails the test.
#include <gtest/gtest.h>

#include <string>
#include <variant>
#include <vector>

#include "nckit/interp/interpreter.hpp"

namespace nckit::plan_test {

inline std::vector<Move> interpreted_moves(const std::string& program, const MachineConfig& machine,
                                           const std::string& file_name = "program.nc") {
    std::vector<Move> moves;
    Interpreter interpreter(machine, ProgramSource::from_string(program, file_name));
    for (;;) {
        InterpResult result = interpreter.next();
        if (const auto* d = std::get_if<Diagnostic>(&result)) {
            ADD_FAILURE() << d->message;
            break;
        }
        if (std::holds_alternative<ProgramEnd>(result)) break;
        moves.push_back(std::get<Move>(std::move(result)));
    }
    return moves;
}

}  // namespace nckit::plan_test
