// Fanuc's label skip: after power-on or reset the control reads nothing up to the first end of
// block, and a file read in from an I/O device skips its leader so. nckit reads a file's first
// line as such a leader when it is no block and the tape start '%' follows it.
#include <string_view>

#include "nckit/gcode/parser.hpp"
#include "program_runner.hpp"

namespace nckit::interp {

bool ProgramRunner::is_leader(const ProgramSource::Line& first) {
    // `PAWN 30` before `%` and `O0002` is a leader. A first line that reads as a block stays a
    // block: `G0 X1` before '%' is a program the '%' ends. The reader is left after line 1 for
    // a leader, on line 1 again otherwise.
    auto tape_mark = [](std::string_view text) {
        const std::size_t i = text.find_first_not_of(" \t");
        return i != std::string_view::npos && text[i] == '%';
    };
    scan_.location = make_location(source().file(), first.number, 1);
    if (tape_mark(first.text) || !parse_block(first.text, scan_)) {
        source().seek(first.offset, 1);
        return false;
    }
    const std::uint64_t first_offset = first.offset;
    const std::uint64_t second_offset = source().next_offset();
    auto second = source().next();
    const bool leader = second && second.value() && tape_mark((*second)->text);
    if (leader) {
        source().seek(second_offset, 2);
        if (options_.on_warning) {
            Diagnostic note = error_at(make_location(source().file(), 1, 1), "tape-leader",
                                       "line 1 is no block and the tape start '%' follows: it is the tape's leader "
                                       "(a title), skipped as Fanuc's label skip does");
            note.severity = Severity::warning;
            options_.on_warning(note);
        }
    } else {
        source().seek(first_offset, 1);
    }
    return leader;
}

}  // namespace nckit::interp
