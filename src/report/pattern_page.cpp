// The pattern page: the order's figures against the bound, and the generated program's tool path
// (the layout, the cutting order as the moves run, the air moves dashed) with everything the
// program page has.
#include <fmt/format.h>

#include "nckit/report/pattern_page.hpp"

namespace nckit {

ReportPage pattern_page(const pattern::SoleRun& run, const std::string& title) {
    ReportPage page;
    page.kind = "pattern";
    page.title = title;
    auto tour = [](const pattern::TourCost& c) {
        return fmt::format("air {:.1f} mm, {:.2f} s; {} reversals ({:.2f} s)", c.air_distance_mm, c.air_time_s,
                           c.reversals, c.reversal_time_s);
    };
    page.figures = {
        {"cuts", fmt::format("{} grooves, {:.1f} mm of cut", run.layout.cuts.size(), run.cut_length_mm)},
        {"drawing order", tour(run.drawing)},
        {"optimised order", tour(run.optimised)},
        {"no order has less", fmt::format("{:.1f} mm, {:.2f} s of XY air", run.bound_distance_mm, run.bound_time_s)},
    };
    return page;
}

}  // namespace nckit
