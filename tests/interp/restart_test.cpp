// nckit::write_restart: the preamble brings back the modal state of the target, the rest makes
// the original's moves, and targets that cannot be restarted are refused with their line.
#include "nckit/interp/restart.hpp"

#include <gtest/gtest.h>

#include "interp_support.hpp"

namespace nckit::test {
namespace {

Result<RestartReport> restart(std::string_view program, RestartTarget target, std::string& out) {
    Interpreter interpreter(default_mill(), ProgramSource::from_string(std::string(program), "test.ngc"));
    return write_restart(interpreter, target, "test.ngc", out);
}

//! The modal view in force at the first move of `program` from source line `line` on.
std::optional<ModalView> view_at_line(std::string_view program, std::uint32_t line) {
    Interpreter interpreter(default_mill(), ProgramSource::from_string(std::string(program), "r.ngc"));
    for (int guard = 0; guard < 100000; ++guard) {
        InterpResult next = interpreter.next();
        const Move* move = std::get_if<Move>(&next);
        if (move == nullptr) return std::nullopt;
        if (move->where.line >= line) return interpreter.modal_view();
    }
    return std::nullopt;
}

//! A move as `nckit moves --json` prints it, without its source line and N (which differ).
std::string motion_of(const Move& move) {
    std::string json;
    append_move_json(json, move, default_mill());
    return json.substr(json.find("\"kind\""));
}

constexpr std::string_view program = R"(G21 G90 G17 G94
T3 M6
S1500 M3
M8
G10 L2 P1 X5 Y-5 Z-20
G54 G64 P0.01
G0 X10 Y10 Z5
G1 Z-1 F200
G1 X20
G61
G2 X30 Y20 I10 J0 F[400/3]
G95 G1 Y30 F0.05
G64 G1 X0
M9
M5
M30
)";

TEST(Restart, PreambleRebuildsTheModalStateAtEveryBlock) {
    const std::vector<Move> original = moves_of(program);
    for (std::int64_t block = 1;; ++block) {
        std::string out;
        Result<RestartReport> report = restart(program, {RestartTarget::Kind::block, block, 1}, out);
        if (!report) {
            EXPECT_EQ(report.diagnostics().front().code, "restart-not-reached");
            EXPECT_GT(block, 5);
            break;
        }
        // The original's view at the target against the restart program's at its rest.
        Interpreter interpreter(default_mill(), ProgramSource::from_string(std::string(program), "test.ngc"));
        ModalView expected;
        for (std::int64_t i = 0; i <= report->first_record; ++i) {
            ASSERT_TRUE(std::holds_alternative<Move>(interpreter.next()));
            expected = interpreter.modal_view();
        }
        std::optional<ModalView> got = view_at_line(out, report->rest_line);
        ASSERT_TRUE(got) << out;
        SCOPED_TRACE(out);
        EXPECT_EQ(got->spindle_direction, expected.spindle_direction);
        EXPECT_EQ(got->spindle_rpm, expected.spindle_rpm);
        EXPECT_EQ(got->tool, expected.tool);
        EXPECT_EQ(got->tool_in_spindle, expected.tool_in_spindle);
        EXPECT_EQ(got->feed_mode, expected.feed_mode);
        EXPECT_EQ(got->feed, expected.feed);
        EXPECT_EQ(got->plane, expected.plane);
        EXPECT_EQ(got->path.exact_stop, expected.path.exact_stop);
        EXPECT_EQ(got->path.tolerance_mm, expected.path.tolerance_mm);
        // And the rest moves as the original did from the target on, bit for bit.
        std::vector<Move> again = moves_of(out);
        std::size_t skip = 0;
        while (skip < again.size() && again[skip].where.line < report->rest_line) ++skip;
        ASSERT_EQ(again.size() - skip, original.size() - static_cast<std::size_t>(report->first_record));
        for (std::size_t i = skip; i < again.size(); ++i) {
            const Move& o = original[static_cast<std::size_t>(report->first_record) + i - skip];
            EXPECT_EQ(motion_of(again[i]), motion_of(o)) << "record " << i;
        }
    }
}

TEST(Restart, SequenceNumbersCountTheirRunsInALoop) {
    constexpr std::string_view loop = "#1 = 0\nWHILE [#1 LT 3] DO1\nN40 G0 X[#1 * 10]\nN41 G1 Y5 F100\n#1 = #1 + 1\nEND1\nM30\n";
    std::string out;
    Result<RestartReport> report = restart(loop, {RestartTarget::Kind::sequence, 40, 3}, out);
    ASSERT_TRUE(report) << format_diagnostic(report.diagnostics().front());
    EXPECT_EQ(report->where.line, 3U);
    EXPECT_EQ(report->block, 5);
    EXPECT_EQ(report->first_record, 4);
    EXPECT_NE(out.find("G0 X20.0 Y0.0 Z0.0"), std::string::npos) << out;
    // Y last moved in +, X too: the approach turns 1 mm short of the point on the - side.
    EXPECT_EQ(report->approach.side[index(Axis::X)], 1);
    EXPECT_EQ(report->approach.side[index(Axis::Y)], 1);
    Result<RestartReport> missing = restart(loop, {RestartTarget::Kind::sequence, 40, 4}, out);
    ASSERT_FALSE(missing);
    EXPECT_EQ(missing.diagnostics().front().code, "restart-not-reached");
}

TEST(Restart, InsideCutterCompensationIsRefusedAtItsLine) {
    constexpr std::string_view comp =
        "G10 L12 P1 R2\nG0 X-10 Y-10\nG41 D1 G1 X0 Y0 F100\nG1 X20\nG1 Y20\nG40 G0 X30 Y30\nM30\n";
    std::string out;
    Result<RestartReport> inside = restart(comp, {RestartTarget::Kind::line, 5, 1}, out);
    ASSERT_FALSE(inside);
    EXPECT_EQ(inside.diagnostics().front().code, "restart-cutter-comp");
    EXPECT_EQ(inside.diagnostics().front().location.line, 5U);
    EXPECT_TRUE(restart(comp, {RestartTarget::Kind::line, 3, 1}, out)) << "the block that switches it on";
}

}  // namespace
}  // namespace nckit::test
