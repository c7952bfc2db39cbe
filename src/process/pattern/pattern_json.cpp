#include "nckit/process/pattern/pattern_json.hpp"

#include <cmath>
#include <cstdint>

namespace nckit::pattern {

using Json = nlohmann::ordered_json;

namespace {

//! A shoe size is a label as much as a number (file names are made of it): 40 is written 40, not
//! 40.0; a half size stays 40.5.
Json size_label(double size) {
    const double whole = std::round(size);
    if (whole == size && std::abs(whole) < 1e15) return Json(static_cast<std::int64_t>(whole));
    return Json(size);
}

}  // namespace

Json to_json(const TourCost& c) {
    return Json{{"air_distance_mm", c.air_distance_mm},
                {"air_time_s", c.air_time_s},
                {"reversals", c.reversals},
                {"reversal_time_s", c.reversal_time_s}};
}

Json to_json(const SoleRun& r) {
    const Grading& g = r.layout.grading;
    // Relative gap of the optimised order above the lower bound (0 when the bound is 0).
    const auto gap = [](double value, double bound) { return bound > 0 ? value / bound - 1 : 0.0; };
    return Json{
        {"size", size_label(g.size)},
        {"mirror", g.mirror},
        {"scale", {{"length", g.scale_x}, {"width", g.scale_y}}},
        {"motif_instances", r.layout.motif_instances},
        {"cuts", r.layout.cuts.size()},
        {"cut_length_mm", r.cut_length_mm},
        {"outline_fit_error_mm", r.layout.fit_error_mm},
        {"outline_control_points", r.layout.control_points},
        {"border_offset_error_mm", r.layout.border_offset_error_mm},
        {"drawing_order", to_json(r.drawing)},
        {"optimised_order", to_json(r.optimised)},
        {"bound", {{"air_distance_mm", r.bound_distance_mm}, {"air_time_s", r.bound_time_s}}},
        {"gap_to_bound",
         {{"air_distance", gap(r.optimised.air_distance_mm, r.bound_distance_mm)},
          {"air_time", gap(r.optimised.air_time_s, r.bound_time_s)}}},
        {"z_air_time_s", r.z_air_time_s},
        {"order_search",
         {{"passes", r.search.passes}, {"evaluations", r.search.evaluations}, {"budget_spent", r.search.budget_spent}}},
        {"planned",
         {{"cycle_time_s", r.planned_cycle_s}, {"air_time_s", r.planned_air_s}, {"cut_time_s", r.planned_cut_s}}},
    };
}

}  // namespace nckit::pattern
