// Two x-y plots of a piston job: the drawing's D(Z) and E(Z), and the error turn by turn of the
// three fast tool servo runs.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include <fmt/format.h>

#include "nckit/process/piston/piston_svg.hpp"
#include "../svg_plot.hpp"

namespace nckit {

namespace {

constexpr double left_px = 90;
constexpr double right_px = 30;
constexpr double plot_width_px = 680;
constexpr double panel_height_px = 240;
constexpr double gap_px = 70;  //!< between panels: the upper one's Z labels
constexpr double title_px = 50;
constexpr double bottom_px = 60;

//! One plot area and the value ranges it shows.
struct Panel {
    double top = 0;
    double x_low = 0, x_high = 1;
    double y_low = 0, y_high = 1;  //!< decades (log10) when log_y
    bool log_y = false;

    [[nodiscard]] double x(double v) const { return left_px + (v - x_low) / (x_high - x_low) * plot_width_px; }
    [[nodiscard]] double y(double v) const {
        const double u = log_y ? std::log10(v) : v;
        return top + panel_height_px - (u - y_low) / (y_high - y_low) * panel_height_px;
    }
};

void text(std::string& out, double x, double y, const std::string& body, const char* anchor = "start",
          const char* fill = "#000000") {
    out += fmt::format(R"(<text x="{:.2f}" y="{:.2f}" text-anchor="{}" fill="{}">{}</text>)"
                       "\n",
                       x, y, anchor, fill, body);
}

void line(std::string& out, double x1, double y1, double x2, double y2, const char* stroke, const char* extra = "") {
    out += fmt::format(R"(<line x1="{:.2f}" y1="{:.2f}" x2="{:.2f}" y2="{:.2f}" stroke="{}"{}/>)"
                       "\n",
                       x1, y1, x2, y2, stroke, extra);
}

//! The frame, grid and tick labels; `x_label` below, `y_label` at the top left.
void draw_frame(std::string& out, const Panel& p, const std::string& x_label, const std::string& y_label) {
    out += fmt::format(R"(<rect x="{:.2f}" y="{:.2f}" width="{:.2f}" height="{:.2f}" fill="none" stroke="#000000"/>)"
                       "\n",
                       left_px, p.top, plot_width_px, panel_height_px);
    const double x_step = process_detail::tick_step(p.x_high - p.x_low, 8);
    for (double k = std::ceil(p.x_low / x_step - 1e-9); k * x_step <= p.x_high + 1e-9 * x_step; k += 1.0) {
        const double x = p.x(k * x_step);
        line(out, x, p.top, x, p.top + panel_height_px, "#dddddd");
        // + 0.0 turns a tick at -0 into 0.
        text(out, x, p.top + panel_height_px + 16,
             fmt::format("{:.{}f}", k * x_step + 0.0, process_detail::decimals_for(x_step)), "middle");
    }
    if (p.log_y) {
        for (double decade = std::ceil(p.y_low - 1e-9); decade <= p.y_high + 1e-9; decade += 1.0) {
            const double y = p.y(std::pow(10.0, decade));
            line(out, left_px, y, left_px + plot_width_px, y, "#dddddd");
            text(out, left_px - 6, y + 4, fmt::format("{:g}", std::pow(10.0, decade)), "end");
        }
    } else {
        const double y_step = process_detail::tick_step(p.y_high - p.y_low, 5);
        for (double k = std::ceil(p.y_low / y_step - 1e-9); k * y_step <= p.y_high + 1e-9 * y_step; k += 1.0) {
            const double y = p.y(k * y_step);
            line(out, left_px, y, left_px + plot_width_px, y, "#dddddd");
            text(out, left_px - 6, y + 4,
                 fmt::format("{:.{}f}", k * y_step + 0.0, process_detail::decimals_for(y_step)), "end");
        }
    }
    text(out, left_px + plot_width_px / 2, p.top + panel_height_px + 36, x_label, "middle");
    text(out, left_px, p.top - 8, y_label);
}

//! A value range padded by 8 % on each side (a flat curve gets a small span of its own).
std::array<double, 2> padded(double low, double high) {
    double span = high - low;
    if (!(span > 1e-12 * std::max(1.0, std::abs(high)))) span = std::max(1e-3, 1e-3 * std::abs(high));
    return {low - 0.08 * span, high + 0.08 * span};
}

template <class Curve>
void draw_drawing_panel(std::string& out, Panel panel, const std::vector<double>& stations, const Curve& value,
                        const std::string& y_label, const char* colour) {
    constexpr int samples = 400;
    std::vector<double> z(samples + 1), v(samples + 1);
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (int k = 0; k <= samples; ++k) {
        const auto i = static_cast<std::size_t>(k);
        z[i] = stations.front() + (stations.back() - stations.front()) * k / samples;
        v[i] = value(z[i]);
        low = std::min(low, v[i]);
        high = std::max(high, v[i]);
    }
    for (double s : stations) {
        low = std::min(low, value(s));
        high = std::max(high, value(s));
    }
    const auto range = padded(low, high);
    panel.y_low = range[0];
    panel.y_high = range[1];
    draw_frame(out, panel, "Z from the crown, mm", y_label);
    std::string points;
    for (std::size_t i = 0; i < z.size(); ++i) points += fmt::format("{:.2f},{:.2f} ", panel.x(z[i]), panel.y(v[i]));
    points.pop_back();
    out += fmt::format(R"(<polyline points="{}" fill="none" stroke="{}" stroke-width="1.6"/>)"
                       "\n",
                       points, colour);
    for (double s : stations) {
        out += fmt::format(R"(<circle cx="{:.2f}" cy="{:.2f}" r="4" fill="white" stroke="{}" stroke-width="2"/>)"
                           "\n",
                           panel.x(s), panel.y(value(s)), colour);
    }
}

}  // namespace

std::string piston_drawing_svg(const cam::PistonJob& job) {
    const double width = left_px + plot_width_px + right_px;
    const double height = title_px + 2 * panel_height_px + gap_px + bottom_px;
    std::string out = process_detail::svg_open(width, height);
    text(out, 20, 24,
         fmt::format("Piston drawing along Z: {} stations (points) and the drawing between them (line)",
                     job.z_mm.size()));
    Panel panel;
    panel.x_low = job.z_mm.front();
    panel.x_high = job.z_mm.back();
    panel.top = title_px;
    draw_drawing_panel(
        out, panel, job.z_mm, [&](double z) { return job.profile.major_diameter_mm(z); }, "major diameter D, mm",
        process_detail::line_colour(0));
    panel.top = title_px + panel_height_px + gap_px;
    draw_drawing_panel(
        out, panel, job.z_mm, [&](double z) { return job.profile.ovality_mm(z); }, "ovality E = D − d, mm",
        process_detail::line_colour(1));
    out += "</svg>\n";
    return out;
}

std::string piston_turn_error_svg(const FtsSimulation& simulation, int air_turns) {
    struct Run {
        const FtsRunResult* result;
        const char* name;
        const char* colour;
    };
    const std::array<Run, 3> runs{Run{&simulation.uncompensated, "uncompensated", "#d62728"},
                                  Run{&simulation.feedforward, "feedforward", "#ff7f0e"},
                                  Run{&simulation.learning, "feedforward + learning", "#1f77b4"}};
    // Log scale from the decade below the smallest error (a DAC step at the least) to above the largest.
    double low = std::numeric_limits<double>::infinity(), high = 0;
    std::size_t turns = 1;
    for (const Run& run : runs) {
        turns = std::max(turns, run.result->turn_pv_um.size());
        for (double v : run.result->turn_pv_um) {
            if (v > 0) low = std::min(low, v);
            high = std::max(high, v);
        }
    }
    const double floor_um = std::max(simulation.dac_step_mm * 1e3 / 10, 1e-6);
    low = std::max(std::isfinite(low) ? low : floor_um, floor_um);
    high = std::max(high, 10 * low);

    const double width = left_px + plot_width_px + right_px;
    const double height = title_px + panel_height_px + bottom_px + 80;  // the legend under the plot
    std::string out = process_detail::svg_open(width, height);
    text(out, 20, 24, "Profile error within each turn (peak to valley), three runs on the same spindle");
    Panel panel;
    panel.top = title_px + 10;
    panel.x_low = 0;
    panel.x_high = static_cast<double>(turns);
    panel.log_y = true;
    panel.y_low = std::floor(std::log10(low));
    panel.y_high = std::ceil(std::log10(high));
    draw_frame(out, panel, "spindle turn", "error per turn, µm (log)");

    const double engage = panel.x(air_turns);
    line(out, engage, panel.top, engage, panel.top + panel_height_px, "#555555", R"( stroke-dasharray="6 4")");
    text(out, engage + 4, panel.top + 14, "tool engages", "start", "#555555");
    for (const Run& run : runs) {
        std::string points;
        const std::vector<double>& pv = run.result->turn_pv_um;
        for (std::size_t k = 0; k < pv.size(); ++k) {
            const double v = std::max(pv[k], std::pow(10.0, panel.y_low));
            points += fmt::format("{:.2f},{:.2f} ", panel.x(static_cast<double>(k) + 0.5), panel.y(v));
        }
        if (points.empty()) continue;
        points.pop_back();
        out += fmt::format(R"(<polyline points="{}" fill="none" stroke="{}" stroke-width="1.4"/>)"
                           "\n",
                           points, run.colour);
    }
    double legend_y = panel.top + panel_height_px + 60;
    for (const Run& run : runs) {
        const double x = left_px;
        line(out, x, legend_y - 4, x + 24, legend_y - 4, run.colour, R"( stroke-width="2")");
        text(out, x + 30, legend_y, fmt::format("{}: {:.3g} µm P-V on the surface", run.name, run.result->pv_um));
        legend_y += 18;
    }
    out += "</svg>\n";
    return out;
}

}  // namespace nckit
