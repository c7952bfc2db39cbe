// Laser notching: run-up distance, speed along the cut before and after, refusals.
#include <gtest/gtest.h>

#include <random>
#include <set>
#include <string>
#include <variant>
#include <vector>

#include "nckit/gcode/program_source.hpp"
#include "nckit/interp/interpreter.hpp"
#include "nckit/plan/profile.hpp"
#include "nckit/process/notch/notch.hpp"
#include "notch_test_support.hpp"
#include "../../src/process/notch/notch_geometry.hpp"
#include "../../src/process/notch/notch_index.hpp"

namespace nckit {
namespace {

using notch_test::file;
using notch_test::interpret;
using notch_test::notcher;
using notch_test::program;

std::vector<Move> conrod(const MachineConfig& machine) {
    Result<ProgramSource> source = ProgramSource::open(std::string(NCKIT_SOURCE_DIR) + "/examples/notch/conrod.nc");
    EXPECT_TRUE(source.ok());
    return interpret(std::move(*source), machine);
}

TEST(Notch, RunUpIsTheSCurveDistanceToFeed) {
    // The reference's worked number: F950 (15.8333 mm/s), a = 500, j = 5000.
    ProfileLimits limits{950.0 / 60.0, 500.0, 5000.0};
    EXPECT_NEAR(speed_change_distance(0, 950.0 / 60.0, limits, ProfileKind::scurve), 0.890991, 5e-7);
    const MachineConfig machine = notcher();
    Result<NotchRewrite> rewrite = rewrite_notches(conrod(machine), machine);
    ASSERT_TRUE(rewrite.ok()) << format_diagnostic(rewrite.diagnostics().front());
    ASSERT_EQ(rewrite->cuts.size(), 1U);
    const NotchCut& cut = rewrite->cuts.front();
    EXPECT_NEAR(cut.run_up_mm, 0.890991, 5e-7);
    EXPECT_DOUBLE_EQ(cut.run_up_placed_mm, 0.8910);
    EXPECT_NEAR(cut.overrun_mm, 0.890991, 5e-7);
    EXPECT_TRUE(cut.approach_shortened);
    EXPECT_EQ(cut.sequence_number, 50);
    EXPECT_DOUBLE_EQ(cut.feed_mm_min, 950.0);
    ASSERT_TRUE(cut.profile_axis.has_value());
    EXPECT_EQ(*cut.profile_axis, Axis::Z);
}

TEST(Notch, LimitsAlongAnObliqueCutAreTheAxisLimitsOverTheDirection) {
    const MachineConfig machine = notcher();
    // 3-4-5 direction: Z moves 0.8 mm per mm of path, so a = 500/0.8, j = 5000/0.8 along it.
    Result<NotchRewrite> rewrite =
        rewrite_notches(program("G1 X10 Z-10 F3000\nM27\nG1 X16 Z-18 F950\nG1 X30\nM30\n", machine), machine);
    ASSERT_TRUE(rewrite.ok()) << format_diagnostic(rewrite.diagnostics().front());
    ProfileLimits along{950.0 / 60.0, 500.0 / 0.8, 5000.0 / 0.8};
    EXPECT_NEAR(rewrite->cuts.front().run_up_mm, speed_change_distance(0, 950.0 / 60.0, along, ProfileKind::scurve),
                1e-12);
    EXPECT_FALSE(rewrite->cuts.front().approach_shortened);
}

TEST(Notch, ConrodRunsTheWholeCutAtFeedAfterRewriting) {
    const MachineConfig machine = notcher();
    Result<NotchJob> job = notch_program(conrod(machine), machine, "conrod.nc");
    ASSERT_TRUE(job.ok()) << format_diagnostic(job.diagnostics().front());
    ASSERT_EQ(job->cuts.size(), 1U);
    const NotchCut& cut = job->cuts.front();
    // Before: the head starts the notch from rest.
    EXPECT_LT(cut.before.min_mm_min, 1.0);
    EXPECT_LT(cut.before.mean_mm_min, 0.99 * 950.0);
    // After: within 0.1 % of F over the whole programmed cut, Z -15.53 to -33.63.
    EXPECT_GE(cut.after.min_mm_min, 0.999 * 950.0);
    EXPECT_LE(cut.after.max_mm_min, 1.001 * 950.0);
    EXPECT_NEAR(cut.after.covered_mm, 18.1, 1e-6);
    ASSERT_GE(cut.after.profile.size(), 2U);
    EXPECT_NEAR(cut.after.profile.front()[0], -15.53, 1e-6);
    EXPECT_NEAR(cut.after.profile.back()[0], -33.63, 1e-6);
    // The beam goes off at the programmed end by position (M128 is no exact stop), and the
    // laser-on M-code sits at the run-up point.
    EXPECT_NE(job->program.find("Z-14.639 F5000.0"), std::string::npos) << job->program;
    const std::size_t cut_end = job->program.find("Z-33.63 ");
    const std::size_t off = job->program.find("M128");
    const std::size_t overrun_end = job->program.find("Z-34.521 ");
    ASSERT_NE(overrun_end, std::string::npos) << job->program;
    EXPECT_LT(cut_end, off);
    EXPECT_LT(off, overrun_end);
}

TEST(NotchRefuses, RunUpLeavingTheTravel) {
    const MachineConfig machine = notcher();  // Z travel -100..100
    Result<NotchRewrite> rewrite =
        rewrite_notches(program("G1 X10 Z99.5 F3000\nM27\nG1 Z80 F950\nG1 X20\nM30\n", machine), machine);
    ASSERT_FALSE(rewrite.ok());
    const Diagnostic& d = rewrite.diagnostics().front();
    EXPECT_EQ(d.code, "notch-travel");
    EXPECT_EQ(d.location.line, 3U);
    EXPECT_EQ(
        format_diagnostic(d),
        "t.nc:3:1: error: the run-up of 0.8910 mm for this notch takes Z to 100.3910, outside its travel (-100..100)");
}

TEST(NotchRefuses, OverrunLeavingTheTravel) {
    const MachineConfig machine = notcher();
    Result<NotchRewrite> rewrite =
        rewrite_notches(program("G1 X10 Z-50 F3000\nM27\nG1 Z-99.5 F950\nG1 X20\nM30\n", machine), machine);
    ASSERT_FALSE(rewrite.ok());
    EXPECT_EQ(rewrite.diagnostics().front().code, "notch-travel");
}

TEST(NotchRefuses, RunUpCrossingThePreviousMove) {
    const MachineConfig machine = notcher();
    // The head comes along Z -15 to X10, then 0.53 mm down to the notch start: the run-up back
    // up to Z -14.639 crosses the move along Z -15.
    Result<NotchRewrite> rewrite = rewrite_notches(
        program("G1 X5 Z-15 F3000\nG1 X10 Z-15\nG1 Z-15.53\nM27\nG1 Z-30 F950\nG1 X20\nM30\n", machine), machine);
    ASSERT_FALSE(rewrite.ok());
    const Diagnostic& d = rewrite.diagnostics().front();
    EXPECT_EQ(d.code, "notch-crossing");
    EXPECT_EQ(format_diagnostic(d),
              "t.nc:5:1: error: the run-up of 0.8910 mm for this notch crosses the path of line 2");
}

TEST(NotchRefuses, OverrunCrossingAnotherNotch) {
    const MachineConfig machine = notcher();
    // Two notches on one line, 0.5 mm apart: the first one's overrun runs into the second.
    Result<NotchRewrite> rewrite = rewrite_notches(
        program("G1 X10 Z-10 F3000\nM27\nG1 Z-20 F950\nG0 X20\nG0 X10 Z-20.5\nM27\nG1 Z-30 F950\nG0 X20\nM30\n",
                machine),
        machine);
    ASSERT_FALSE(rewrite.ok());
    EXPECT_EQ(rewrite.diagnostics().front().code, "notch-crossing");
}

TEST(NotchRefuses, MachineWithoutAnAtSpeedLaserOff) {
    MachineConfig machine = notcher();
    machine.laser_off_mcodes = {28};
    Result<NotchRewrite> rewrite = rewrite_notches(conrod(machine), machine);
    ASSERT_FALSE(rewrite.ok());
    EXPECT_EQ(rewrite.diagnostics().front().code, "notch-no-sync-off");
}

TEST(Notch, ProgramWithoutLaserCodesIsUnchanged) {
    const MachineConfig machine = notcher();
    const std::vector<Move> moves = program("G1 X10 Z-10 F3000\nG1 Z-20 F950\nM30\n", machine);
    Result<NotchRewrite> rewrite = rewrite_notches(moves, machine);
    ASSERT_TRUE(rewrite.ok());
    EXPECT_TRUE(rewrite->cuts.empty());
    EXPECT_EQ(rewrite->moves.size(), moves.size());
}

// Property: the sweep index behind the streamed checks misses no segment within the pad (it may
// visit more), for random short and long segments and queries over two axes.
TEST(NotchIndex, VisitsEverySegmentWithinThePad) {
    std::mt19937 random(10);
    std::uniform_real_distribution<double> place(-50.0, 50.0);
    std::uniform_real_distribution<double> reach(-3.0, 3.0);
    for (int round = 0; round < 50; ++round) {
        std::vector<notch_detail::SweepIndex::Segment> segments;
        for (int i = 0; i < 200; ++i) {
            AxisVector from;
            from[Axis::X] = place(random);
            from[Axis::Z] = place(random);
            AxisVector to = from;
            const double k = i % 20 == 0 ? 10.0 : 1.0;  // a few long ones
            to[Axis::X] += k * reach(random);
            to[Axis::Z] += k * reach(random);
            segments.push_back({from, to});
        }
        const notch_detail::SweepIndex index(segments);
        for (int q = 0; q < 50; ++q) {
            AxisVector a;
            a[Axis::X] = place(random);
            a[Axis::Z] = place(random);
            AxisVector b = a;
            b[Axis::X] += 4 * reach(random);
            b[Axis::Z] += 4 * reach(random);
            const double pad_mm = 0.5;
            std::set<std::size_t> visited;
            index.query(a, b, pad_mm, [&](std::size_t i) { visited.insert(i); });
            for (std::size_t i = 0; i < segments.size(); ++i) {
                if (notch_detail::segment_distance(a, b, segments[i].from, segments[i].to) < pad_mm) {
                    EXPECT_TRUE(visited.count(i)) << "round " << round << " query " << q << " segment " << i;
                }
            }
        }
    }
}

// The streamed job hands out the same cuts as the move list gives, and the cuts in order.
TEST(Notch, StreamedJobHandsOutTheCutsInOrder) {
    const MachineConfig machine = notcher();
    const std::vector<Move> moves = program(
        "G1 X10 Z50 F3000\nG1 Z20 F5000\nM27\nG1 Z5 F950\nM28\nG0 X30 Z25\nG1 Z20 F3000\nM27\nG1 Z10 F1200\n"
        "M27\nG1 X40 F800\nM28\nG0 X60 Z40\nM30\n",
        machine);
    Result<NotchJob> job = notch_program(moves, machine, "t.nc");
    ASSERT_TRUE(job.ok()) << format_diagnostic(job.diagnostics().front());
    ASSERT_EQ(job->cuts.size(), 3U);
    EXPECT_EQ(job->cuts[0].feed_mm_min, 950);
    EXPECT_EQ(job->cuts[1].feed_mm_min, 1200);
    EXPECT_EQ(job->cuts[2].feed_mm_min, 800);
    for (const NotchCut& cut : job->cuts) {
        EXPECT_NEAR(cut.after.min_mm_min, cut.feed_mm_min, 1e-3 * cut.feed_mm_min);
        EXPECT_NEAR(cut.after.covered_mm, cut.length_mm, 1e-6);
        EXPECT_LT(cut.before.min_mm_min, 1.0);
    }
    // Pass 1's planner check: a move the planner refuses fails the job before any cut.
    std::vector<Move> no_feed = moves;
    std::get<Line>(no_feed[0].what).feed.mm_per_min = 0;
    Result<NotchJob> refused = notch_program(no_feed, machine, "t.nc");
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.diagnostics().front().code, "no-feed");
}

}  // namespace
}  // namespace nckit
