// The blocks a lathe cycle names by P and Q (G70-G73): found by their N numbers anywhere in the
// running program, so a G70 may stand far from its G71, and read with their expressions
// evaluated. The reader comes back to where it was; after a roughing cycle the program goes
// on after the N q block.
#include <fmt/format.h>

#include "nckit/gcode/parser.hpp"
#include "program_runner.hpp"

namespace nckit::interp {

namespace {
// A finishing shape longer than this is a missing Q rather than a contour (Fanuc: 100 blocks
// on a 0i; kept generous for CAM output).
constexpr std::size_t max_sequence_blocks = 10000;

bool starts_with_sequence(const Block& block, std::int64_t number) {
    return !block.words.empty() && block.words.front().letter == 'N' &&
           static_cast<std::int64_t>(block.words.front().value) == number;
}
}  // namespace

std::optional<Diagnostic> ProgramRunner::read_sequence(std::int64_t p, std::int64_t q, std::vector<Block>& out) {
    ProgramSource& src = source();
    const std::uint64_t here = src.next_offset();
    const std::uint32_t here_line = src.next_line_number();
    auto back = [&](std::optional<Diagnostic> result) {
        src.seek(here, here_line);
        return result;
    };
    const Frame& f = frame();
    src.seek(f.program.offset, f.program.line);
    bool found = false;
    bool started = false;
    Block parsed;
    for (;;) {
        auto line = src.next();
        if (!line) return back(line.diagnostics().front());
        if (!line.value()) break;
        const ProgramSource::Line& text = **line;
        parsed.clear();
        parsed.location = make_location(src.file(), text.number, 1);
        if (auto error = parse_block(text.text, parsed)) {
            if (found) return back(std::move(*error));
            continue;
        }
        if (parsed.tape_mark) {
            if (started) break;
            continue;
        }
        if (!parsed.words.empty() && parsed.words.front().letter == 'O') {
            if (started) break;  // the next program: this one has no such N
            started = true;
            continue;
        }
        started = started || !parsed.words.empty();
        if (!found && !starts_with_sequence(parsed, p)) continue;
        found = true;
        if (out.size() >= max_sequence_blocks) break;
        if (parsed.statement.kind != StatementKind::none) {
            return back(error_at(parsed.location, "bad-cycle",
                                 "a macro statement inside a cycle's P-Q blocks is not supported"));
        }
        Block resolved;
        if (auto error = resolve_words(parsed, resolved)) return back(std::move(*error));
        out.push_back(std::move(resolved));
        if (starts_with_sequence(parsed, q)) {
            sequence_end_ = {src.next_offset(), src.next_line_number()};
            return back(std::nullopt);
        }
    }
    // Fanuc alarm PS0063: the block of P (or Q) is not in the program.
    return back(error_at(SourceLocation{}, "missing-sequence",
                         found ? fmt::format("no block N{} after N{}", q, p) : fmt::format("no block N{}", p)));
}

}  // namespace nckit::interp
