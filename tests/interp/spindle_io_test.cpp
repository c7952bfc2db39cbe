// Spindle, tools, coolant and other M codes; feed per revolution and constant surface speed;
// dwell; threading; the order of events within a block.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "interp_support.hpp"

namespace nckit::test {
namespace {

//! An Io event as a test names it: "M3 rpm=1000", "S rpm=500", "T2", "M6 waits".
std::string describe(const Io& io) {
    std::string out;
    switch (io.kind) {
        case IoKind::mcode:
            out = "M" + std::to_string(io.number);
            break;
        case IoKind::spindle_speed:
            out = "S";
            break;
        case IoKind::tool_select:
            out = "T" + std::to_string(io.number);
            break;
    }
    if (io.kind == IoKind::spindle_speed || (io.kind == IoKind::mcode && (io.number == 3 || io.number == 4))) {
        out += io.constant_surface_speed ? " css=" : " rpm=";
        out += std::to_string(static_cast<long>(std::lround(io.value)));
    }
    if (io.rpm_clamp > 0) out += " clamp=" + std::to_string(static_cast<long>(io.rpm_clamp));
    if (io.waits) out += " waits";
    return out;
}

//! Every move of a program in one line each: Io by describe(), the rest in text form.
Texts events(std::string_view program, const MachineConfig& machine = default_mill()) {
    Texts out;
    for (const Move& move : moves_of(program, machine)) {
        if (const Io* io = std::get_if<Io>(&move.what)) {
            out.push_back(describe(*io));
        } else {
            std::string line;
            append_move_text(line, move, machine);
            out.push_back(line);
        }
    }
    return out;
}

// ---- spindle, tool, coolant, M codes ------------------------------------------------------------

TEST(Spindle, SpeedAndDirection) {
    EXPECT_EQ(events("S1000 M3\nM4\nM5\nS200\n"),
              (Texts{"S rpm=1000", "M3 rpm=1000", "M4 rpm=1000", "M5", "S rpm=200"}));
}

TEST(Spindle, SpeedUpToTheMachineMaximum) {
    EXPECT_EQ(events("S6000\n"), (Texts{"S rpm=6000"}));
}

TEST(Spindle, SpeedIsModalForLaterM3) {
    EXPECT_EQ(events("S750\nM3\n"), (Texts{"S rpm=750", "M3 rpm=750"}));
}

TEST(Spindle, M3WithoutSpeedCarriesZero) {
    EXPECT_EQ(events("M3\n"), (Texts{"M3 rpm=0"}));
}

TEST(Tool, SelectAndChange) {
    std::vector<Move> moves = moves_of("T2 M6\n");
    ASSERT_EQ(moves.size(), 2U);
    const Io& t = std::get<Io>(moves[0].what);
    EXPECT_EQ(t.kind, IoKind::tool_select);
    EXPECT_EQ(t.number, 2);
    EXPECT_FALSE(t.waits);
    EXPECT_EQ(describe(std::get<Io>(moves[1].what)), "M6 waits");
}

TEST(Coolant, MistFloodAndOff) {
    EXPECT_EQ(events("M7 M8\nM9\n"), (Texts{"M7", "M8", "M9"}));
}

TEST(MCodes, StopsWaitAndComeAfterMotion) {
    EXPECT_EQ(events("G0 X1 M0\nM1\nM60\n"),
              (Texts{"G0 X1.0000 Y0.0000 Z0.0000", "M0 waits", "M1 waits", "M60 waits"}));
}

TEST(MCodes, OtherCodesAreIoEvents) {
    std::vector<Move> moves = moves_of("M100\nM24 M101\n");
    ASSERT_EQ(moves.size(), 3U);
    const Io& io = std::get<Io>(moves[0].what);
    EXPECT_EQ(io.kind, IoKind::mcode);
    EXPECT_EQ(io.number, 100);
    EXPECT_FALSE(io.waits);
    EXPECT_EQ(describe(std::get<Io>(moves[1].what)), "M24");
}

TEST(MCodes, ExactStopCodesOfTheMachineWait) {
    MachineConfig m = default_mill();
    m.exact_stop_mcodes = {24, 64};
    EXPECT_EQ(events("M24 M101\nM64\nM65\n", m), (Texts{"M24 waits", "M101", "M64 waits", "M65"}));
}

TEST(MCodes, LeadingZerosAreTheSameCode) {
    EXPECT_EQ(events("M03 S100\nM08\n"), (Texts{"S rpm=100", "M3 rpm=100", "M8"}));
}

TEST(Order, SpeedToolSpindleCoolantBeforeMotionAndStopAfter) {
    EXPECT_EQ(events("G1 X10 F100 M8 S500 T2 M3 M30\n"),
              (Texts{"S rpm=500", "T2", "M3 rpm=500", "M8", "G1 X10.0000 Y0.0000 Z0.0000 F100.0000", "M30 waits"}));
}

TEST(Order, DwellComesAfterSpeedAndMCodes) {
    EXPECT_EQ(events("G4 P250 M8 S100\n"), (Texts{"S rpm=100", "M8", "G4 P0.2500"}));
}

TEST(Order, EveryMoveOfABlockHasItsLocation) {
    std::vector<std::uint32_t> lines;
    std::vector<std::int64_t> numbers;
    for (const Move& move : moves_of("G0 X1\nN7 S100 M3 G1 X2 F10 M30\n")) {
        lines.push_back(move.where.line);
        numbers.push_back(move.sequence_number);
    }
    EXPECT_EQ(lines, (std::vector<std::uint32_t>{1, 2, 2, 2, 2}));
    EXPECT_EQ(numbers, (std::vector<std::int64_t>{-1, 7, 7, 7, 7}));
}

// ---- dwell --------------------------------------------------------------------------------

TEST(Dwell, PIsMilliseconds) {
    EXPECT_DOUBLE_EQ(the<Dwell>("G4 P1500\n").seconds, 1.5);
}

TEST(Dwell, XIsSeconds) {
    EXPECT_DOUBLE_EQ(the<Dwell>("G4 X2\n").seconds, 2.0);
    EXPECT_DOUBLE_EQ(the<Dwell>("G4 X0.25\n").seconds, 0.25);
}

TEST(Dwell, ZeroIsAllowed) {
    EXPECT_DOUBLE_EQ(the<Dwell>("G4 P0\n").seconds, 0.0);
}

TEST(Dwell, DoesNotMoveOrChangeTheMotionMode) {
    EXPECT_EQ(events("G1 X1 F100\nG4 X1\nX2\n"),
              (Texts{"G1 X1.0000 Y0.0000 Z0.0000 F100.0000", "G4 P1.0000", "G1 X2.0000 Y0.0000 Z0.0000 F100.0000"}));
}

// ---- feed per revolution, constant surface speed -------------------------------------------------

TEST(FeedMode, G95FeedIsPerRevolutionTimesTheSpeed) {
    Line line = the<Line>("G95 S1000 M3\nG1 Z-10 F0.2\n", lathe());
    EXPECT_EQ(line.feed.mode, FeedMode::per_revolution);
    EXPECT_DOUBLE_EQ(line.feed.mm_per_rev, 0.2);
    EXPECT_DOUBLE_EQ(line.feed.mm_per_min, 200.0);
}

TEST(FeedMode, G95WithoutSpindleSpeedHasNoFeedPerMinute) {
    Line line = the<Line>("G95 G1 Z-10 F0.2\n", lathe());
    EXPECT_DOUBLE_EQ(line.feed.mm_per_rev, 0.2);
    EXPECT_DOUBLE_EQ(line.feed.mm_per_min, 0.0);
}

TEST(FeedMode, G95InInchIsInchesPerRevolution) {
    EXPECT_DOUBLE_EQ(the<Line>("G20\nG95 S100 G1 Z-1 F0.01\n", lathe()).feed.mm_per_rev, 0.254);
}

TEST(FeedMode, G94SwitchesBack) {
    std::vector<Line> lines = only<Line>(moves_of("S500 G95 G1 Z-1 F0.1\nG94 Z-2 F80\n", lathe()));
    ASSERT_EQ(lines.size(), 2U);
    EXPECT_EQ(lines[1].feed.mode, FeedMode::per_minute);
    EXPECT_DOUBLE_EQ(lines[1].feed.mm_per_min, 80.0);
    EXPECT_DOUBLE_EQ(lines[1].feed.mm_per_rev, 0.0);
}

TEST(FeedMode, PerRevolutionArc) {
    Arc arc = the<Arc>("G18 S400 G95\nG0 X40\nG2 X40 Z-20 R10 F0.25\n", lathe());
    EXPECT_EQ(arc.feed.mode, FeedMode::per_revolution);
    EXPECT_DOUBLE_EQ(arc.feed.mm_per_min, 100.0);
}

TEST(SurfaceSpeed, RpmFollowsTheXRadius) {
    // 200 m/min at diameter 100 (radius 50 mm): 200 / (2π · 0.05) rpm.
    std::vector<Move> moves = moves_of("G96 S200 M3\nG0 X100\nG95 G1 Z-10 F0.2\n", lathe());
    ASSERT_EQ(moves.size(), 4U);
    EXPECT_EQ(describe(std::get<Io>(moves[0].what)), "S css=200");
    EXPECT_EQ(describe(std::get<Io>(moves[1].what)), "M3 css=200");
    const double rpm = 200.0 / (2 * std::numbers::pi * 0.05);
    EXPECT_DOUBLE_EQ(std::get<Line>(moves[3].what).feed.mm_per_min, 0.2 * rpm);
}

TEST(SurfaceSpeed, ClampedByG50S) {
    std::vector<Move> moves = moves_of("G50 S500\nG96 S200 M3\nG0 X100\nG95 G1 Z-10 F0.2\n", lathe());
    ASSERT_EQ(moves.size(), 4U);
    EXPECT_EQ(describe(std::get<Io>(moves[1].what)), "M3 css=200 clamp=500");
    EXPECT_DOUBLE_EQ(std::get<Line>(moves[3].what).feed.mm_per_min, 100.0);
}

TEST(SurfaceSpeed, ClampedByTheMachineMaximum) {
    // Radius 1 mm would need 31831 rpm; the lathe turns 4000.
    EXPECT_DOUBLE_EQ(only<Line>(moves_of("G96 S200\nG0 X2\nG95 G1 Z-10 F0.1\n", lathe())).back().feed.mm_per_min,
                     400.0);
    EXPECT_DOUBLE_EQ(the<Line>("G96 S200\nG95 G1 Z-10 F0.1\n", lathe()).feed.mm_per_min, 400.0) << "at X0";
}

TEST(SurfaceSpeed, RadiusIsInWorkCoordinates) {
    // Machine radius 60, but G50 makes it diameter 100 (radius 50).
    const double rpm = 200.0 / (2 * std::numbers::pi * 0.05);
    Line cut = only<Line>(moves_of("G0 X120\nG50 X100\nG96 S200 G95 G1 Z-10 F0.2\n", lathe())).back();
    EXPECT_DOUBLE_EQ(cut.feed.mm_per_min, 0.2 * rpm);
}

TEST(SurfaceSpeed, InchSpeedIsFeetPerMinute) {
    Io s = only<Io>(moves_of("G20 G96 S100\n", lathe())).front();
    EXPECT_TRUE(s.constant_surface_speed);
    EXPECT_DOUBLE_EQ(s.value, 30.48);
}

TEST(SurfaceSpeed, G97ReturnsToRpm) {
    std::vector<Move> moves = moves_of("G96 S200\nG97 S1000\nG0 X100\nG95 G1 Z-10 F0.2\n", lathe());
    EXPECT_EQ(describe(std::get<Io>(moves[1].what)), "S rpm=1000");
    EXPECT_DOUBLE_EQ(std::get<Line>(moves.back().what).feed.mm_per_min, 200.0);
}

TEST(SurfaceSpeed, SpeedIsNotLimitedByMaxRpm) {
    EXPECT_EQ(events("G96 S5000\n", lathe()), (Texts{"S css=5000"}));
}

TEST(SurfaceSpeed, G50SAloneIsNotAnEvent) {
    EXPECT_TRUE(moves_of("G50 S2000\n", lathe()).empty());
}

TEST(SurfaceSpeed, ModeChangeWithoutSIsAnEvent) {
    // Later stages know the spindle only from events: G96 / G97 alone must still say so.
    std::vector<Move> moves = moves_of("G97 S800 M3\nG96\nG97\n", lathe());
    ASSERT_EQ(moves.size(), 4U);
    const Io& css = std::get<Io>(moves[2].what);
    EXPECT_EQ(css.kind, IoKind::spindle_speed);
    EXPECT_TRUE(css.constant_surface_speed);
    const Io& rpm = std::get<Io>(moves[3].what);
    EXPECT_FALSE(rpm.constant_surface_speed);
    EXPECT_DOUBLE_EQ(rpm.value, 800.0);
}

TEST(SurfaceSpeed, ClampChangeUnderG96IsAnEvent) {
    std::vector<Move> moves = moves_of("G96 S200 M3\nG50 S1000\nG96 D900\n", lathe());
    ASSERT_EQ(moves.size(), 4U);
    EXPECT_DOUBLE_EQ(std::get<Io>(moves[2].what).rpm_clamp, 1000.0);
    EXPECT_DOUBLE_EQ(std::get<Io>(moves[2].what).value, 200.0);
    EXPECT_DOUBLE_EQ(std::get<Io>(moves[3].what).rpm_clamp, 900.0);
}

// ---- threading ----------------------------------------------------------------------------

TEST(Thread, G33WithKLead) {
    SyncMove s = the<SyncMove>("S500 M3\nG0 X20 Z5\nG33 Z-20 K1.5\n", lathe());
    EXPECT_DOUBLE_EQ(s.from[Axis::Z], 5.0);
    EXPECT_DOUBLE_EQ(s.to[Axis::Z], -20.0);
    EXPECT_DOUBLE_EQ(s.to[Axis::X], 10.0);
    EXPECT_EQ(s.feed.mode, FeedMode::per_revolution);
    EXPECT_DOUBLE_EQ(s.feed.mm_per_rev, 1.5);
    EXPECT_DOUBLE_EQ(s.feed.mm_per_min, 750.0);
}

TEST(Thread, G32WithFLeadAndEWithE) {
    EXPECT_DOUBLE_EQ(the<SyncMove>("G32 Z-20 F1.25\n", lathe()).feed.mm_per_rev, 1.25);
    EXPECT_DOUBLE_EQ(the<SyncMove>("G32 Z-20 E2\n", lathe()).feed.mm_per_rev, 2.0);
    EXPECT_DOUBLE_EQ(the<SyncMove>("G33 Z-20 K1 F5\n", lathe()).feed.mm_per_rev, 1.0) << "K before F";
}

TEST(Thread, Text) {
    EXPECT_EQ(events("G33 Z-20 K1.5\n"), (Texts{"G33 X0.0000 Y0.0000 Z-20.0000 FR1.5000"}));
}

TEST(Thread, FLeadDoesNotChangeTheFeed) {
    EXPECT_EQ(events("G1 X1 F100\nG33 Z-5 F1.5\nG1 X2\n"),
              (Texts{"G1 X1.0000 Y0.0000 Z0.0000 F100.0000", "G33 X1.0000 Y0.0000 Z-5.0000 FR1.5000",
                     "G1 X2.0000 Y0.0000 Z-5.0000 F100.0000"}));
}

TEST(Thread, InchLead) {
    EXPECT_DOUBLE_EQ(the<SyncMove>("G20 G33 Z-1 K0.1\n").feed.mm_per_rev, 2.54);
}

TEST(Thread, TaperThreadMovesBothAxes) {
    SyncMove s = the<SyncMove>("G0 X20\nG33 X30 Z-20 K2\n", lathe());
    EXPECT_DOUBLE_EQ(s.from[Axis::X], 10.0);
    EXPECT_DOUBLE_EQ(s.to[Axis::X], 15.0);
}

TEST(Thread, UnderSurfaceSpeedUsesTheRpmAtTheStart) {
    // 100 m/min at radius 10 mm: 1591.5 rpm.
    SyncMove s = the<SyncMove>("G0 X20 Z5\nG96 S100 M3\nG33 Z-20 K1.5\n", lathe());
    EXPECT_DOUBLE_EQ(s.feed.mm_per_min, 1.5 * 100.0 / (2 * std::numbers::pi * 0.01));
}

}  // namespace
}  // namespace nckit::test
