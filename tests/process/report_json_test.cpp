// The JSON reports of `nckit crosshatch`, `eccentric`, `pattern` and `notch` (per cut) as library
// values: every key of the contract, in the order the commands print them, with the number of
// the field it reports; a speed limit the axis does not have is null.
#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

#include "nckit/process/crosshatch/crosshatch_json.hpp"
#include "nckit/process/eccentric/eccentric_json.hpp"
#include "nckit/process/notch/notch_json.hpp"
#include "nckit/process/pattern/pattern_json.hpp"

namespace nckit {
namespace {

using Json = nlohmann::ordered_json;

std::vector<std::string> keys_of(const Json& object) {
    std::vector<std::string> out;
    for (const auto& [key, value] : object.items()) out.push_back(key);
    return out;
}

TEST(ReportJson, CrosshatchKeysInOrderWithTheirFields) {
    CrosshatchPlan plan;
    plan.job.index_deg = 7.5;
    plan.job.cycles = 3;
    plan.job.timing = CrosshatchTiming::free_running_timers;
    plan.rotation_rpm = 61.25;
    plan.feed_mm_min = 300.5;
    plan.rotation.timer.divisor = 1234;
    plan.feed.timer.divisor = 567;
    plan.index_timer.divisor = 89;
    plan.rotation.timer.speed_error = -1e-4;
    plan.special = false;
    plan.index_move_steps = -3;
    plan.crosshatch_angle_deg = 45.125;
    CrosshatchScan scan;
    scan.tracks.resize(17);
    scan.rotation_steps = 98765;
    scan.feed_steps = 4321;
    scan.duration_s = 12.5;

    const Json j = to_json(plan, scan);
    EXPECT_EQ(keys_of(j), (std::vector<std::string>{"rotation_rpm",
                                                    "feed_mm_min",
                                                    "timer_divisor",
                                                    "speed_error",
                                                    "step_rate_hz",
                                                    "timer_rate_hz",
                                                    "pattern",
                                                    "round_trip_deg",
                                                    "index_deg",
                                                    "index_move_deg",
                                                    "index_move_steps",
                                                    "crosshatch_angle_deg",
                                                    "helix_angle_deg",
                                                    "track_angle_deg",
                                                    "track_angle_error_deg",
                                                    "timer_angle_error_bound_deg",
                                                    "drift_deg_per_stroke",
                                                    "closure_error_steps",
                                                    "line_spacing_mm",
                                                    "surface_speed_mm_min",
                                                    "turns_per_stroke",
                                                    "stroke_mm",
                                                    "stroke_time_s",
                                                    "steps_per_stroke",
                                                    "rotation_steps_per_turn",
                                                    "cycles",
                                                    "tracks",
                                                    "steps",
                                                    "duration_s",
                                                    "timing"}));
    EXPECT_EQ(j["rotation_rpm"], 61.25);
    EXPECT_EQ(j["timer_divisor"]["rotation"], 1234);
    EXPECT_EQ(j["timer_divisor"]["index"], 89);
    EXPECT_EQ(j["speed_error"]["rotation"], -1e-4);
    EXPECT_EQ(j["pattern"], "arbitrary");
    EXPECT_EQ(j["index_deg"], 7.5);
    EXPECT_EQ(j["index_move_steps"], -3);
    EXPECT_EQ(j["tracks"], 17);
    EXPECT_EQ(j["steps"]["rotation"], 98765);
    EXPECT_EQ(j["steps"]["feed"], 4321);
    EXPECT_EQ(j["cycles"], 3);
    EXPECT_EQ(j["timing"], "free_running_timers");
    plan.special = true;
    EXPECT_EQ(to_json(plan, scan)["pattern"], "special");
}

TEST(ReportJson, EccentricMissingLimitsAreNull) {
    EccentricReport r;
    r.job.rpm = 450;
    r.compensated.roundness_um = 0.25;
    r.compensated.center_offset_um = 0.125;
    r.uncompensated.roundness_um = 3.5;
    r.limits.velocity = 900;
    r.limits.acceleration = std::numeric_limits<double>::infinity();
    r.limits.jerk = std::numeric_limits<double>::quiet_NaN();
    r.limits.following = 1200;
    r.max_rpm = 900;
    r.limited_by = "velocity";
    r.servo_axis = true;
    r.x_min_diameter_mm = 38;
    r.x_max_diameter_mm = 44;

    const Json j = to_json(r);
    EXPECT_EQ(keys_of(j),
              (std::vector<std::string>{"roundness_um", "center_offset_um", "max_rpm", "limited_by", "rpm",
                                        "max_rpm_by", "compensated", "uncompensated", "servo_axis", "updates_per_turn",
                                        "x_diameter_mm", "peak_velocity_mm_s", "peak_acceleration_mm_s2",
                                        "peak_jerk_mm_s3", "turns", "cycle_time_s"}));
    EXPECT_EQ(j["roundness_um"], 0.25);
    EXPECT_EQ(j["rpm"], 450);
    EXPECT_EQ(j["max_rpm_by"]["velocity"], 900);
    EXPECT_TRUE(j["max_rpm_by"]["acceleration"].is_null());
    EXPECT_TRUE(j["max_rpm_by"]["jerk"].is_null());
    EXPECT_EQ(j["uncompensated"]["roundness_um"], 3.5);
    EXPECT_EQ(j["servo_axis"], true);
    EXPECT_EQ(j["x_diameter_mm"]["max"], 44);
    // The dump is valid JSON that reads back to the same value (no inf or nan text).
    EXPECT_EQ(Json::parse(j.dump()), j);
}

TEST(ReportJson, PatternGapToTheBoundAndZeroBound) {
    pattern::SoleRun r;
    r.layout.grading = {42, 1.05, 1.02, true};
    r.layout.cuts.resize(5);
    r.optimised = {110, 22, 7, 1.5};
    r.drawing = {200, 40, 9, 2.0};
    r.bound_distance_mm = 100;
    r.bound_time_s = 20;
    r.search.passes = 4;
    r.search.budget_spent = true;

    const Json j = pattern::to_json(r);
    EXPECT_EQ(j["size"], 42);
    EXPECT_EQ(j["size"].dump(), "42");  // a whole size is written as one (file names use it)
    EXPECT_EQ(j["mirror"], true);
    EXPECT_EQ(j["scale"]["width"], 1.02);
    EXPECT_EQ(j["cuts"], 5);
    EXPECT_EQ(j["optimised_order"]["reversals"], 7);
    EXPECT_EQ(j["drawing_order"]["air_distance_mm"], 200);
    EXPECT_NEAR(j["gap_to_bound"]["air_distance"].get<double>(), 0.1, 1e-12);
    EXPECT_NEAR(j["gap_to_bound"]["air_time"].get<double>(), 0.1, 1e-12);
    EXPECT_EQ(j["order_search"]["budget_spent"], true);
    EXPECT_EQ(keys_of(j).back(), "planned");
    r.layout.grading.size = 40.5;
    EXPECT_EQ(pattern::to_json(r)["size"].dump(), "40.5");
    r.bound_distance_mm = 0;
    EXPECT_EQ(pattern::to_json(r)["gap_to_bound"]["air_distance"], 0.0);
}

TEST(ReportJson, NotchCutWithItsProfilesAndCoordinate) {
    NotchCut cut;
    cut.where.line = 12;
    cut.sequence_number = 120;
    cut.laser_on_mcode = 24;
    cut.length_mm = 2.5;
    cut.feed_mm_min = 600;
    cut.run_up_placed_mm = 0.0123;
    cut.approach_shortened = true;
    cut.before.min_mm_min = 410.5;
    cut.before.profile = {{10.0, 410.5}, {12.5, 600.0}};
    cut.after.min_mm_min = 600;

    Json j = to_json(cut);
    EXPECT_EQ(keys_of(j),
              (std::vector<std::string>{"line", "sequence_number", "laser_on_mcode", "length_mm", "feed_mm_min",
                                        "cut_speed_mm_min", "run_up_mm", "run_up_placed_mm", "overrun_mm",
                                        "approach_shortened", "profile_coordinate", "before", "after"}));
    EXPECT_EQ(j["line"], 12);
    EXPECT_EQ(j["sequence_number"], 120);
    EXPECT_EQ(j["approach_shortened"], true);
    EXPECT_EQ(j["profile_coordinate"], "s");
    EXPECT_EQ(j["before"]["profile"], Json::parse("[[10.0,410.5],[12.5,600.0]]"));
    EXPECT_EQ(keys_of(j["after"]),
              (std::vector<std::string>{"min_mm_min", "max_mm_min", "mean_mm_min", "covered_mm", "profile"}));
    cut.profile_axis = Axis::Y;
    EXPECT_EQ(to_json(cut)["profile_coordinate"], "Y");
}

}  // namespace
}  // namespace nckit
