// LinuxCNC's polar words and G93 inverse time through the Interpreter, seen from the moves: where
// they end and the feed they carry. (tests/real_linuxcnc compares both with rs274 on LinuxCNC's
// own example programs.)
#include <cmath>
#include <numbers>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "interp_support.hpp"

namespace nckit::test {
namespace {

std::vector<Line> feeds_of(std::string_view program) {
    return only<Line>(moves_of(program, linuxcnc_mill()));
}

TEST(NgcPolar, AbsolutePolarGoesToRadiusAndAngleAboutTheOrigin) {
    const auto lines = feeds_of("G21 G17 G90\nG0 @10 ^30\nG0 ^120\nG0 @5\nM2\n");
    ASSERT_EQ(lines.size(), 3u);
    const double c30 = 10 * std::cos(std::numbers::pi / 6);
    EXPECT_NEAR(lines[0].to[Axis::X], c30, 1e-9);
    EXPECT_NEAR(lines[0].to[Axis::Y], 5.0, 1e-9);
    // ^ alone keeps the radius, @ alone the angle.
    EXPECT_NEAR(std::hypot(lines[1].to[Axis::X], lines[1].to[Axis::Y]), 10.0, 1e-9);
    EXPECT_NEAR(std::atan2(lines[1].to[Axis::Y], lines[1].to[Axis::X]), 2 * std::numbers::pi / 3, 1e-9);
    EXPECT_NEAR(std::hypot(lines[2].to[Axis::X], lines[2].to[Axis::Y]), 5.0, 1e-9);
    EXPECT_NEAR(std::atan2(lines[2].to[Axis::Y], lines[2].to[Axis::X]), 2 * std::numbers::pi / 3, 1e-9);
}

TEST(NgcPolar, IncrementalAngleStepsKeepTheRadiusOnEveryStep) {
    // Property: 36 G91 steps of ^10 walk a full circle of the start radius and come back.
    std::string program = "G21 G17 G90\nG0 X7 Y0\nG91\n";
    for (int i = 0; i < 36; ++i) program += "G1 ^10 F100\n";
    program += "M2\n";
    const auto lines = feeds_of(program);
    ASSERT_EQ(lines.size(), 37u);
    for (const Line& l : lines) EXPECT_NEAR(std::hypot(l.to[Axis::X], l.to[Axis::Y]), 7.0, 1e-9);
    EXPECT_NEAR(lines.back().to[Axis::X], 7.0, 1e-9);
    EXPECT_NEAR(lines.back().to[Axis::Y], 0.0, 1e-9);
}

TEST(NgcPolar, IncrementalCycleRepeatsTurnOnEveryHole) {
    // From X15 Y0, six holes 60 degrees apart on the circle of radius 15; one feed per hole.
    const auto lines = feeds_of("G21 G17 G90\nG0 X15 Y0 Z5\nG91 G81 R-4 Z-5 ^60 L6 F100\nM2\n");
    int holes = 0;
    for (const Line& l : lines) {
        if (l.rapid) continue;
        EXPECT_NEAR(std::hypot(l.to[Axis::X], l.to[Axis::Y]), 15.0, 1e-9);
        const double angle_deg = std::atan2(l.to[Axis::Y], l.to[Axis::X]) * 180 / std::numbers::pi;
        EXPECT_NEAR(std::remainder(angle_deg - 60.0 * (holes + 1), 360.0), 0.0, 1e-9);
        ++holes;
    }
    EXPECT_EQ(holes, 6);
}

TEST(NgcPolar, ErrorsAtTheWord) {
    const Diagnostic beside_x = error_of("G17 G0 X1 @1 ^30\nM2\n", linuxcnc_mill());
    EXPECT_EQ(beside_x.location.line, 1u);
    EXPECT_EQ(beside_x.location.column, 11u);  // the @
    EXPECT_EQ(beside_x.message, "cannot specify both polar coordinate and X word");
    EXPECT_EQ(error_of("G18 G0 @1 ^30\nM2\n", linuxcnc_mill()).message,
              "cannot use polar coordinate except in G17 plane");
    EXPECT_EQ(error_of("G0 X0 Y0\nG0 @3\nM2\n", linuxcnc_mill()).message,
              "must specify angle in polar coordinate if at the origin");
}

TEST(NgcInverseTime, FeedIsFTimesTheLengthOfEachMove) {
    // G93 F20 on moves of 2 and 3 mm: 40 and 60 mm/min; the arc of a quarter turn of radius 10
    // under F4: 4 x 5 pi mm/min. G94 ends it.
    const auto moves = moves_of(
        "G21 G17 G90\nG0 X1\nG93 G1 X-1 F20\nY3 F20\nG3 X-11 Y13 I-10 J0 F4\nG94 G1 X0 F500\nM2\n", linuxcnc_mill());
    std::vector<double> feeds;
    for (const Move& m : moves) {
        if (const auto* l = std::get_if<Line>(&m.what); l != nullptr && !l->rapid) feeds.push_back(l->feed.mm_per_min);
        if (const auto* a = std::get_if<Arc>(&m.what)) feeds.push_back(a->feed.mm_per_min);
    }
    ASSERT_EQ(feeds.size(), 4u);
    EXPECT_NEAR(feeds[0], 40.0, 1e-9);
    EXPECT_NEAR(feeds[1], 60.0, 1e-9);
    EXPECT_NEAR(feeds[2], 4 * 5 * std::numbers::pi, 1e-9);
    EXPECT_NEAR(feeds[3], 500.0, 1e-9);
}

TEST(NgcInverseTime, EveryFeedBlockNeedsItsF) {
    const Diagnostic d = error_of("G21\nG93 G1 X1 F10\nY1\nM2\n", linuxcnc_mill());
    EXPECT_EQ(d.location.line, 3u);
    EXPECT_EQ(d.message, "F word missing with inverse time g1 move");
}

TEST(NgcG92Kept, G92Point2ClearsTheOffsetAndG92Point3BringsItBack) {
    // G92 X1 Y2 from X5 Y5 shifts by (4, 3); G92.2 clears the shift but keeps #5211/#5212 (4, 3),
    // G92.3 brings the shift back: X1 Y2 is then the machine's X5 Y5 again.
    const auto lines = feeds_of(
        "G21 G17 G90\nG0 X5 Y5\nG92 X1 Y2\nG92.2\n"
        "G1 X[#5211] Y[#5212] F100\nG92.3\nG1 X1 Y2\nM2\n");
    ASSERT_EQ(lines.size(), 3u);
    EXPECT_NEAR(lines[1].to[Axis::X], 4.0, 1e-9);
    EXPECT_NEAR(lines[1].to[Axis::Y], 3.0, 1e-9);
    EXPECT_NEAR(lines[2].to[Axis::X], 5.0, 1e-9);
    EXPECT_NEAR(lines[2].to[Axis::Y], 5.0, 1e-9);
}

}  // namespace
}  // namespace nckit::test
