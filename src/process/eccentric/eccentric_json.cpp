#include "nckit/process/eccentric/eccentric_json.hpp"

#include "../json_number.hpp"

#include <cmath>

namespace nckit {

namespace {

using Json = nlohmann::ordered_json;

Json fit_json(const SectionFit& fit) {
    return Json{{"roundness_um", fit.roundness_um},
                {"center_offset_um", fit.center_offset_um},
                {"radius_error_um", fit.radius_error_um},
                {"max_deviation_um", fit.max_deviation_um}};
}

}  // namespace

Json to_json(const EccentricReport& r) {
    return Json{
        {"roundness_um", r.compensated.roundness_um},
        {"center_offset_um", r.compensated.center_offset_um},
        {"max_rpm", r.max_rpm},
        {"limited_by", r.limited_by},
        {"rpm", r.job.rpm},
        {"max_rpm_by",
         {{"velocity", process_detail::finite_or_null(r.limits.velocity)},
          {"acceleration", process_detail::finite_or_null(r.limits.acceleration)},
          {"jerk", process_detail::finite_or_null(r.limits.jerk)},
          {"following", process_detail::finite_or_null(r.limits.following)}}},
        {"compensated", fit_json(r.compensated)},
        {"uncompensated", fit_json(r.uncompensated)},
        {"servo_axis", r.servo_axis},
        {"updates_per_turn", r.updates_per_turn},
        {"x_diameter_mm", {{"min", r.x_min_diameter_mm}, {"max", r.x_max_diameter_mm}}},
        {"peak_velocity_mm_s", r.peak_velocity_mm_s},
        {"peak_acceleration_mm_s2", r.peak_acceleration_mm_s2},
        {"peak_jerk_mm_s3", r.peak_jerk_mm_s3},
        {"turns", r.turns},
        {"cycle_time_s", r.cycle_time_s},
    };
}

}  // namespace nckit
