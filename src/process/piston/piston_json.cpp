#include "nckit/process/piston/piston_json.hpp"

#include "../json_number.hpp"

#include <cmath>

namespace nckit {

namespace {

using Json = nlohmann::ordered_json;

Json run_json(const FtsRunResult& run) {
    return Json{{"pv", run.pv_um}, {"rms", run.rms_um}};
}

}  // namespace

Json to_json(const PistonSimulation& s) {
    const FtsSimulation& f = s.fts;
    const FtsParameters& p = s.parameters;
    return Json{
        {"profile_error_um",
         {{"uncompensated", run_json(f.uncompensated)},
          {"feedforward", run_json(f.feedforward)},
          {"learning", run_json(f.learning)}}},
        {"rpm", p.rpm},
        {"encoder_counts", p.encoder_counts},
        {"tick_rate_hz", f.tick_rate_hz},
        {"dac_step_mm", f.dac_step_mm},
        {"model_error", p.servo.model_error},
        {"spindle_ripple", p.ripple.fraction},
        {"servo",
         {{"natural_frequency_hz", p.servo.natural_frequency_hz},
          {"damping", p.servo.damping},
          {"stroke_mm", p.servo.stroke_mm},
          {"dac_bits", p.servo.dac_bits}}},
        {"cam_table",
         {{"theta_cells", s.table_theta_cells},
          {"z_cells", s.table_z_cells},
          {"cells", s.table_theta_cells * s.table_z_cells},
          {"bytes", s.table_bytes},
          {"error_bound_mm", s.table_error_bound_mm},
          {"tolerance_mm", s.table_tolerance_mm}}},
        {"learning",
         {{"settled_turn", s.settled_turn},
          {"settle_limit_um", PistonRunOptions{}.settle_limit_um},
          {"air_turns", p.air_turns},
          {"harmonics", p.learning.harmonics},
          {"gain", p.learning.gain},
          {"contraction", f.learning_contraction.any_frequency},
          {"contraction_learned", f.learning_contraction.learned_harmonics}}},
        {"servo_demand",
         {{"peak_displacement_mm", s.fit.peak_displacement_mm},
          {"displacement_limit_mm", s.fit.limit_mm},
          {"peak_displacement_theta_deg", s.fit.theta_deg},
          {"peak_displacement_z_mm", s.fit.z_mm},
          {"peak_command_mm",
           {{"uncompensated", f.uncompensated.peak_command_mm},
            {"feedforward", f.feedforward.peak_command_mm},
            {"learning", f.learning.peak_command_mm}}},
          {"acceleration_mm_s2", s.acceleration_mm_s2},
          {"acceleration_limit_mm_s2", s.acceleration_limit_mm_s2},
          {"max_rpm", process_detail::finite_or_null(s.max_rpm)}}},
        {"z_mm", {{"from", p.z_start_mm}, {"to", p.z_end_mm}}},
        {"feed_mm_rev", p.feed_mm_rev},
        {"ticks", f.ticks},
        {"cut_ticks", f.cut_ticks},
        {"duration_s", f.duration_s},
    };
}

}  // namespace nckit
