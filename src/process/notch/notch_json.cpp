#include "nckit/process/notch/notch_json.hpp"

#include <string>

namespace nckit {

using Json = nlohmann::ordered_json;

Json to_json(const CutSpeed& speed) {
    Json profile = Json::array();
    for (const auto& [coordinate, speed_mm_min] : speed.profile)
        profile.push_back(Json::array({coordinate, speed_mm_min}));
    return Json{{"min_mm_min", speed.min_mm_min},
                {"max_mm_min", speed.max_mm_min},
                {"mean_mm_min", speed.mean_mm_min},
                {"covered_mm", speed.covered_mm},
                {"profile", std::move(profile)}};
}

Json to_json(const NotchCut& cut) {
    return Json{
        {"line", cut.where.line},
        {"sequence_number", cut.sequence_number},
        {"laser_on_mcode", cut.laser_on_mcode},
        {"length_mm", cut.length_mm},
        {"feed_mm_min", cut.feed_mm_min},
        {"cut_speed_mm_min", cut.cut_speed_mm_min},
        {"run_up_mm", cut.run_up_mm},
        {"run_up_placed_mm", cut.run_up_placed_mm},
        {"overrun_mm", cut.overrun_mm},
        {"approach_shortened", cut.approach_shortened},
        // The one axis the cut moves, or "s" (path length from the start) when it moves several.
        {"profile_coordinate", cut.profile_axis ? std::string(1, letter(*cut.profile_axis)) : std::string("s")},
        {"before", to_json(cut.before)},
        {"after", to_json(cut.after)},
    };
}

}  // namespace nckit
