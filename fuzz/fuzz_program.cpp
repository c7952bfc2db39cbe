// Program text through the interpreter, Custom Macro B included, with a small runaway budget so
// that every input ends quickly. Every run must end in a move stream that stops with ProgramEnd
// or one diagnostic, never a crash, hang or undefined behaviour; every move's numbers finite.
#include <cmath>
#include <string>
#include <variant>

#include "fuzz_support.hpp"
#include "nckit/interp/interpreter.hpp"

extern "C" int LLVMFuzzerTestOneInput(const unsigned char* data, std::size_t size) {
    using namespace nckit;
    if (size > 64 * 1024) return 0;
    // The first byte picks the machine's dialect; the rest is the program.
    MachineConfig machine = default_mill();
    if (size > 0 && (data[0] & 1)) machine.decimal_point_input = DecimalPointInput::least_increment;
    if (size > 0 && (data[0] & 2)) machine.diameter_mode = true;
    std::string text(fuzz::text_of(data, size).substr(size > 0 ? 1 : 0));
    InterpreterOptions options;
    options.max_blocks = 20000;
    Interpreter interpreter(machine, ProgramSource::from_string(std::move(text), "fuzz.nc"), options);
    for (int results = 0; results < 200000; ++results) {
        InterpResult result = interpreter.next();
        if (!std::holds_alternative<Move>(result)) return 0;
        const Move& move = std::get<Move>(result);
        if (const auto* line = std::get_if<Line>(&move.what)) {
            for (std::size_t i = 0; i < axis_count; ++i) {
                fuzz::require(std::isfinite(line->to[i]), "a line ends at a non-finite position");
            }
        }
    }
    fuzz::finding("more than 200000 results from a program under a 20000-block budget");
}
