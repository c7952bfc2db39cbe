// Errors in values and motion: feed, speed, dwell, arcs, threads, G53. Each test states the
// error's code, line and column.
#include <gtest/gtest.h>

#include "interp_support.hpp"

namespace nckit::test {
namespace {

// ---- feed ---------------------------------------------------------------------------------

TEST(FeedErrors, CuttingMoveWithoutFeed) {
    Diagnostic d = error_of("G0 X1\nG1 X2\n");
    EXPECT_EQ(where(d), "no-feed 2:1");
    EXPECT_EQ(d.message, "cutting move with no feed rate (F)");
    EXPECT_EQ(error_where("X1 G1 Y1\n"), "no-feed 1:4") << "at the motion word";
    EXPECT_EQ(error_where("G1\nX1\n"), "no-feed 2:1") << "modal G1";
    EXPECT_EQ(error_where("G2 X10 I5\n"), "no-feed 1:1");
    EXPECT_EQ(error_where("G2 I5\n"), "no-feed 1:1") << "a full circle cuts too";
    EXPECT_EQ(error_where("G1 X1 F0\n"), "no-feed 1:1");
    EXPECT_EQ(error_where("F100\nF0\nG1 X1\n"), "no-feed 3:1");
}

TEST(FeedErrors, NoFeedNeededWithoutMotion) {
    EXPECT_TRUE(moves_of("G1\nG1 F0\nG0 X1\n").size() == 1U);
}

TEST(FeedErrors, NegativeFeed) {
    Diagnostic d = error_of("F-100\n");
    EXPECT_EQ(where(d), "bad-value 1:1");
    EXPECT_EQ(d.message, "feed rate F must not be negative");
    EXPECT_EQ(error_where("G1 X1 F-100\n"), "bad-value 1:7");
    EXPECT_EQ(error_where("G1 X1 F100\nX2 F-1\n"), "bad-value 2:4");
}

// ---- spindle, dwell, path tolerance ---------------------------------------------------------

TEST(ValueErrors, SpindleSpeedOverTheMachineMaximum) {
    Diagnostic d = error_of("S6001 M3\n");
    EXPECT_EQ(where(d), "spindle-limit 1:1");
    EXPECT_EQ(d.message, "S6001 exceeds the spindle's 6000 rpm");
    EXPECT_EQ(error_where("G0 X1\nM3 S4500\n", lathe()), "spindle-limit 2:4");
    EXPECT_EQ(error_where("G96 S100\nG97 S7000\n"), "spindle-limit 2:5");
}

TEST(ValueErrors, NegativeSpindleSpeed) {
    Diagnostic d = error_of("S-5\n");
    EXPECT_EQ(where(d), "bad-value 1:1");
    EXPECT_EQ(d.message, "spindle speed S must not be negative");
    EXPECT_EQ(error_where("G50 S-1\n"), "bad-value 1:5");
    EXPECT_EQ(error_where("G96 S-100\n"), "bad-value 1:5");
}

TEST(ValueErrors, DwellWithoutTime) {
    Diagnostic d = error_of("G4\n");
    EXPECT_EQ(where(d), "missing-word 1:1");
    EXPECT_EQ(d.message, "G4 needs P (ms) or X (s)");
    EXPECT_EQ(error_where("F10 G4\n"), "missing-word 1:5");
}

TEST(ValueErrors, NegativeDwell) {
    Diagnostic d = error_of("G4 P-100\n");
    EXPECT_EQ(where(d), "bad-value 1:4");
    EXPECT_EQ(d.message, "dwell time is negative");
    EXPECT_EQ(error_where("G4 X-1\n"), "bad-value 1:4");
}

TEST(ValueErrors, NegativePathTolerance) {
    Diagnostic d = error_of("G64 P-0.1\n");
    EXPECT_EQ(where(d), "bad-value 1:5");
    EXPECT_EQ(d.message, "G64 P tolerance must not be negative");
}

// ---- arcs ---------------------------------------------------------------------------------

TEST(ArcErrors, EndPointOffTheCircle) {
    Diagnostic d = error_of("G0 X10\nG2 X0 Y5 I-10 F100\n");
    EXPECT_EQ(where(d), "bad-arc 2:1");
    EXPECT_EQ(d.message, "end point is not on the arc: radius 10.0000 mm at the start, 5.0000 mm at the end");
    EXPECT_EQ(error_where("G2 X10 I5 F100\nX0 Y3 I-5\n"), "bad-arc 2:1") << "modal G2";
    EXPECT_EQ(error_where("G0 X10\nF100 G3 X0 Y10.03 I-10\n"), "bad-arc 2:6");
}

TEST(ArcErrors, RadiusTooSmall) {
    Diagnostic d = error_of("G2 X20 R9 F100\n");
    EXPECT_EQ(where(d), "bad-arc 1:8");
    EXPECT_EQ(d.message, "radius 9.0000 mm is too small to reach the end point (20.0000 mm away)");
    EXPECT_EQ(error_where("G3 X20 R-9.98 F100\n"), "bad-arc 1:8");
}

TEST(ArcErrors, RadiusFullCircle) {
    Diagnostic d = error_of("G0 X5\nG2 X5 Y0 R5 F100\n");
    EXPECT_EQ(where(d), "bad-arc 2:10");
    EXPECT_EQ(d.message, "an R arc cannot be a full circle: give I/J/K");
    EXPECT_EQ(error_where("G2 R5 F100\n"), "bad-arc 1:4");
    EXPECT_EQ(error_where("G2 Z-1 R5 F100\n"), "bad-arc 1:8") << "a helix with R ends above its start";
}

TEST(ArcErrors, ZeroRadius) {
    Diagnostic d = error_of("G2 X10 F100\n");
    EXPECT_EQ(where(d), "bad-arc 1:1");
    EXPECT_EQ(d.message, "arc has zero radius");
    EXPECT_EQ(error_where("G2 X10 I0 J0 F100\n"), "bad-arc 1:1");
    EXPECT_EQ(error_where("G3 F100\nY5 I0\n"), "bad-arc 2:1");
}

// ---- threads, G53 -------------------------------------------------------------------------

TEST(ThreadErrors, ThreadWithoutLead) {
    Diagnostic d = error_of("G33 Z-10\n");
    EXPECT_EQ(where(d), "missing-word 1:1");
    EXPECT_EQ(d.message, "thread needs its lead (F, E or K, mm per revolution)");
    EXPECT_EQ(error_where("G33 Z-1 K1\nZ-2\n"), "missing-word 2:1") << "the lead is not modal";
}

TEST(ThreadErrors, LeadMustBePositive) {
    Diagnostic d = error_of("G33 Z-10 K0\n");
    EXPECT_EQ(where(d), "bad-value 1:10");
    EXPECT_EQ(d.message, "thread lead must be positive");
    EXPECT_EQ(error_where("G32 Z-10 F-1\n"), "bad-value 1:10");
    EXPECT_EQ(error_where("G33 Z-10 E-2\n"), "bad-value 1:10");
}

TEST(G53Errors, OnlyWithG0OrG1) {
    Diagnostic d = error_of("G53 G2 X1 I1 F1\n");
    EXPECT_EQ(where(d), "bad-combination 1:1");
    EXPECT_EQ(d.message, "G53 moves only with G0 or G1");
    moves_of("G2 X10 I5 F100\nG53 X1\nG80\nX1 G53\n");  // modal G2 or G80: G53 positions at rapid
    EXPECT_EQ(error_where("G53 G33 Z-1 K1\n"), "bad-combination 1:1");
}

// ---- errors through the stream --------------------------------------------------------------

TEST(StreamErrors, SyntaxErrorCarriesItsLineAndColumn) {
    Diagnostic d = error_of("G0 X1\nG1 X1 $ F1\n");
    EXPECT_EQ(where(d), "syntax 2:7");
    EXPECT_EQ(format_diagnostic(d), "test.ngc:2:7: error: unexpected character '$'");
}

TEST(StreamErrors, MacroFormatErrorCarriesItsAlarm) {
    Diagnostic d = error_of("G0 X1\n#1 = [5\n");
    EXPECT_EQ(where(d), "macro-format 2:8");
    EXPECT_EQ(d.alarm, 114);
}

TEST(StreamErrors, TooLongLineCarriesItsLine) {
    std::string program = "G0 X1\n(" + std::string(ProgramSource::max_line_bytes, 'c') + ")\n";
    RunResult r = run_program(program);
    ASSERT_TRUE(r.error);
    EXPECT_EQ(where(*r.error), "line-too-long 2:1");
    EXPECT_EQ(r.moves.size(), 1U);
}

}  // namespace
}  // namespace nckit::test
