// SVG drawing of a sole's layout and order.
#include "nckit/process/pattern/pattern_svg.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "../svg_plot.hpp"

namespace nckit::pattern {

namespace {

constexpr double px_per_mm = 3.0;
constexpr double margin_px = 30.0;

struct Frame {
    Box box;
    double height_px = 0;
    [[nodiscard]] std::string xy(Vec2 p) const {
        return fmt::format("{:.2f},{:.2f}", margin_px + (p.x - box.low.x) * px_per_mm,
                           height_px - margin_px - (p.y - box.low.y) * px_per_mm);
    }
};

std::string path_of(const Frame& f, const std::vector<Vec2>& points, bool closed) {
    std::string d = "M" + f.xy(points.front());
    for (std::size_t i = 1; i < points.size(); ++i) d += " L" + f.xy(points[i]);
    if (closed) d += " Z";
    return d;
}

// Blue → red through the order.
std::string order_colour(std::size_t i, std::size_t n) {
    const double t = n > 1 ? static_cast<double>(i) / static_cast<double>(n - 1) : 0.0;
    const int r = static_cast<int>(std::lround(30 + 200 * t));
    const int b = static_cast<int>(std::lround(220 - 190 * t));
    return fmt::format("#{:02x}40{:02x}", r, b);
}

}  // namespace

std::string pattern_svg(const SoleRun& run, const PatternJob& job, const std::string& title) {
    Frame f;
    f.box = bounding_box(PlaneCurve(run.layout.outline));
    f.box.add({0, 0});
    const double width_px = f.box.size().x * px_per_mm + 2 * margin_px;
    f.height_px = f.box.size().y * px_per_mm + 2 * margin_px + 20;
    std::string out = process_detail::svg_open(width_px, f.height_px);
    out += fmt::format("<text x=\"{:.0f}\" y=\"16\">{}</text>\n", margin_px, title);
    out += fmt::format("<path d=\"{}\" fill=\"none\" stroke=\"black\" stroke-width=\"1.5\"/>\n",
                       path_of(f, polyline(PlaneCurve(run.layout.outline), 0.02), true));
    out += fmt::format("<path d=\"{}\" fill=\"none\" stroke=\"#888\" stroke-width=\"1\"/>\n",
                       path_of(f, polyline(PlaneCurve(run.layout.border), 0.02), true));
    // Air moves first, under the grooves.
    std::string air;
    Vec2 at{0, 0};
    for (const ProgramCut& cut : run.program_cuts) {
        const Vec2 s = point_at(cut.curve, 0);
        air += " M" + f.xy(at) + " L" + f.xy(s);
        at = point_at(cut.curve, parameter_end(cut.curve));
    }
    air += " M" + f.xy(at) + " L" + f.xy({0, 0});
    out += fmt::format("<path d=\"{}\" fill=\"none\" stroke=\"#999\" stroke-width=\"0.6\" stroke-dasharray=\"3,3\"/>\n",
                       air);
    const double groove_px = std::max(1.0, job.tool_diameter_mm * px_per_mm);
    for (std::size_t i = 0; i < run.program_cuts.size(); ++i) {
        out += fmt::format(
            "<path d=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"{:.2f}\" stroke-linecap=\"round\"/>\n",
            path_of(f, polyline(run.program_cuts[i].curve, 0.02), false), order_colour(i, run.program_cuts.size()),
            groove_px);
    }
    const std::string hole = f.xy({0, 0});
    const auto comma = hole.find(',');
    out += fmt::format("<circle cx=\"{}\" cy=\"{}\" r=\"6\" fill=\"none\" stroke=\"black\"/>\n", hole.substr(0, comma),
                       hole.substr(comma + 1));
    out += fmt::format("<path d=\"M{0} m-9,0 h18 M{0} m0,-9 v18\" stroke=\"black\"/>\n", hole);
    out += "</svg>\n";
    return out;
}

}  // namespace nckit::pattern
