#include "nckit/process/crosshatch/crosshatch_json.hpp"

namespace nckit {

const char* timing_name(CrosshatchTiming timing) {
    return timing == CrosshatchTiming::one_time_base ? "one_time_base" : "free_running_timers";
}

nlohmann::ordered_json to_json(const CrosshatchPlan& plan, const CrosshatchScan& scan) {
    using Json = nlohmann::ordered_json;
    const CrosshatchJob& job = plan.job;
    return Json{
        {"rotation_rpm", plan.rotation_rpm},
        {"feed_mm_min", plan.feed_mm_min},
        {"timer_divisor",
         {{"rotation", plan.rotation.timer.divisor},
          {"feed", plan.feed.timer.divisor},
          {"index", plan.index_timer.divisor}}},
        {"speed_error",
         {{"rotation", plan.rotation.timer.speed_error},
          {"feed", plan.feed.timer.speed_error},
          {"index", plan.index_timer.speed_error}}},
        {"step_rate_hz", {{"rotation", plan.rotation.timer.wanted_hz}, {"feed", plan.feed.timer.wanted_hz}}},
        {"timer_rate_hz", {{"rotation", plan.rotation.timer.rate_hz}, {"feed", plan.feed.timer.rate_hz}}},
        {"pattern", plan.special ? "special" : "arbitrary"},
        {"round_trip_deg", plan.round_trip_deg},
        {"index_deg", job.index_deg},
        {"index_move_deg", plan.index_move_deg},
        {"index_move_steps", plan.index_move_steps},
        {"crosshatch_angle_deg", plan.crosshatch_angle_deg},
        {"helix_angle_deg", plan.helix_angle_deg},
        {"track_angle_deg", scan.track_angle_deg},
        {"track_angle_error_deg", scan.track_angle_error_deg},
        {"timer_angle_error_bound_deg", scan.timer_angle_error_bound_deg},
        {"drift_deg_per_stroke", scan.drift_deg_per_stroke},
        {"closure_error_steps", scan.closure_error_steps},
        {"line_spacing_mm", plan.line_spacing_mm},
        {"surface_speed_mm_min", plan.surface_speed_mm_min},
        {"turns_per_stroke", plan.turns_per_stroke},
        {"stroke_mm", scan.stroke_mm},
        {"stroke_time_s", plan.stroke_time_s},
        {"steps_per_stroke", {{"rotation", plan.rotation_steps_per_stroke}, {"feed", plan.feed_steps_per_stroke}}},
        {"rotation_steps_per_turn", plan.rotation_steps_per_turn},
        {"cycles", job.cycles},
        {"tracks", scan.tracks.size()},
        {"steps", {{"rotation", scan.rotation_steps}, {"feed", scan.feed_steps}}},
        {"duration_s", scan.duration_s},
        {"timing", timing_name(job.timing)},
    };
}

}  // namespace nckit
