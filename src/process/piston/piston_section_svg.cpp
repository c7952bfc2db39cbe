// The piston section as its drawing shows it: an oval a few tenths of a millimetre out of round on
// a diameter of tens of millimetres is invisible to scale, so the base circle stands for the
// major radius and only the deviation from it is drawn magnified.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <fmt/format.h>

#include "nckit/process/piston/piston_svg.hpp"
#include "../svg_plot.hpp"

namespace nckit {

namespace {

constexpr double base_radius_px = 200;  //!< the base circle (D/2)
constexpr double ring_margin_px = 70;   //!< room around it for axis labels
constexpr double title_px = 60;         //!< above the plot
constexpr double legend_px = 290;       //!< right of the plot
constexpr int samples = 720;            //!< points around each section (every 0.5°)

//! Where a deviation of `dev_mm` at `phi_deg` lands: φ counter-clockwise from the right.
struct Polar {
    double cx = 0, cy = 0;
    double px_per_mm = 1;  //!< deviation scale: the magnification times the base circle's scale

    [[nodiscard]] double radius(double dev_mm) const { return std::max(0.0, base_radius_px + dev_mm * px_per_mm); }
    [[nodiscard]] double x(double phi_deg, double dev_mm) const {
        return cx + radius(dev_mm) * std::cos(phi_deg * std::numbers::pi / 180.0);
    }
    [[nodiscard]] double y(double phi_deg, double dev_mm) const {
        return cy - radius(dev_mm) * std::sin(phi_deg * std::numbers::pi / 180.0);
    }
};

//! Rings at round deviations between the smallest and largest drawn, the base circle among them.
void draw_rings(std::string& out, const Polar& polar, double low_mm, double high_mm) {
    // Up to 4 rings, at least 22 px apart so their labels do not collide.
    const double span_mm = std::max(high_mm - low_mm, 1e-9);
    const double step = process_detail::tick_step(span_mm, std::clamp(span_mm * polar.px_per_mm / 22.0, 1.0, 4.0));
    const int decimals = process_detail::decimals_for(step);
    for (double k = std::floor(low_mm / step); k * step <= high_mm + 1e-12; k += 1.0) {
        const double dev = k * step;
        if (k == 0.0 || polar.radius(dev) < 0.25 * base_radius_px) continue;
        out += fmt::format(R"(<circle cx="{:.2f}" cy="{:.2f}" r="{:.2f}" fill="none" stroke="#bbbbbb" )"
                           R"(stroke-dasharray="4 4"/>)"
                           "\n",
                           polar.cx, polar.cy, polar.radius(dev));
        out += fmt::format(R"(<text x="{:.2f}" y="{:.2f}" fill="#777777" font-size="10" text-anchor="end">)"
                           R"({:+.{}f} mm</text>)"
                           "\n",
                           polar.cx - 4, polar.y(90, dev) - 3, dev, decimals);
    }
    out += fmt::format(R"(<circle cx="{:.2f}" cy="{:.2f}" r="{:.2f}" fill="none" stroke="#444444" stroke-width="1.2"/>)"
                       "\n",
                       polar.cx, polar.cy, base_radius_px);
    out += fmt::format(R"(<text x="{:.2f}" y="{:.2f}" fill="#444444">base circle D/2 (deviation 0)</text>)"
                       "\n",
                       polar.x(62, 0) + 6, polar.y(62, 0) - 6);
}

void draw_axes(std::string& out, const Polar& polar) {
    const double reach = base_radius_px + 0.75 * ring_margin_px;
    out += fmt::format(R"(<line x1="{:.2f}" y1="{:.2f}" x2="{:.2f}" y2="{:.2f}" stroke="#000000" )"
                       R"(stroke-dasharray="12 3 2 3"/>)"
                       "\n",
                       polar.cx - reach, polar.cy, polar.cx + reach, polar.cy);
    out += fmt::format(R"(<line x1="{:.2f}" y1="{:.2f}" x2="{:.2f}" y2="{:.2f}" stroke="#000000" )"
                       R"(stroke-dasharray="12 3 2 3"/>)"
                       "\n",
                       polar.cx, polar.cy - reach, polar.cx, polar.cy + reach);
    out +=
        fmt::format(R"(<text x="{0:.2f}" y="{1:.2f}">major axis</text><text x="{0:.2f}" y="{2:.2f}">D, φ = 0°</text>)"
                    "\n",
                    polar.cx + base_radius_px + 6, polar.cy - 20, polar.cy - 6);
    out += fmt::format(R"(<text x="{:.2f}" y="{:.2f}" text-anchor="end">180°</text>)"
                       "\n",
                       polar.cx - reach + 30, polar.cy - 6);
    out += fmt::format(R"(<text x="{:.2f}" y="{:.2f}">minor axis d = D − E, φ = 90°</text>)"
                       "\n",
                       polar.cx + 6, polar.cy - reach + 12);
    out += fmt::format(R"(<text x="{:.2f}" y="{:.2f}">270°</text>)"
                       "\n",
                       polar.cx + 6, polar.cy + reach - 2);
}

}  // namespace

std::string piston_section_svg(const cam::PistonJob& job) {
    const cam::PistonProfile& profile = job.profile;
    const std::size_t stations = job.z_mm.size();
    const std::size_t middle = stations / 2;

    // Deviation r − D/2 of every station, every half degree.
    std::vector<std::vector<double>> dev(stations, std::vector<double>(samples));
    double low = 0, high = 0;
    for (std::size_t i = 0; i < stations; ++i) {
        const double z = job.z_mm[i];
        const double half_d = profile.major_diameter_mm(z) / 2;
        for (int k = 0; k < samples; ++k) {
            const double d = profile.radius_mm(360.0 * k / samples, z) - half_d;
            dev[i][static_cast<std::size_t>(k)] = d;
            low = std::min(low, d);
            high = std::max(high, d);
        }
    }
    // The base circle is D/2 of the middle station to scale; the largest deviation is drawn at
    // no more than 30 % of it. An oval drawn this way, R − m (1 − cos 2φ), stays convex while
    // its full deviation 2m is below R/3: beyond, the minor axis shows a dent the part lacks.
    const double radius_px_per_mm = base_radius_px / (profile.major_diameter_mm(job.z_mm[middle]) / 2);
    const double largest = std::max(-low, high);
    const double magnification =
        largest > 0
            ? std::max(1.0, process_detail::round_down_scale(0.3 * base_radius_px / (largest * radius_px_per_mm)))
            : 1.0;
    Polar polar;
    polar.cx = ring_margin_px + base_radius_px;
    polar.cy = title_px + ring_margin_px + base_radius_px;
    polar.px_per_mm = magnification * radius_px_per_mm;

    const double width = 2 * (ring_margin_px + base_radius_px) + legend_px;
    const double height = title_px + 2 * (ring_margin_px + base_radius_px) + 20;
    std::string out = process_detail::svg_open(width, height);
    out += fmt::format(R"(<text x="20" y="24" font-size="16">Piston section at {} stations: radial deviation )"
                       R"(from D/2 magnified ×{:g}</text>)"
                       "\n",
                       stations, magnification);
    out += fmt::format(R"(<text x="20" y="44" fill="#555555">base circle = D/2 to scale; deviation drawn {:g} times )"
                       R"(larger; φ from the major axis, counter-clockwise</text>)"
                       "\n",
                       magnification);
    draw_rings(out, polar, low, high);
    draw_axes(out, polar);

    for (std::size_t i = 0; i < stations; ++i) {
        std::string points;
        for (int k = 0; k <= samples; ++k) {
            const int wrapped = k % samples;
            const double phi = 360.0 * wrapped / samples;
            const double d = dev[i][static_cast<std::size_t>(wrapped)];
            points += fmt::format("{:.2f},{:.2f} ", polar.x(phi, d), polar.y(phi, d));
        }
        points.pop_back();
        out += fmt::format(R"(<polyline points="{}" fill="none" stroke="{}" stroke-width="{}"/>)"
                           "\n",
                           points, process_detail::line_colour(i), i == middle ? 2.6 : 1.2);
    }

    // Legend: each station's Z, D, the minor diameter and E as the drawing gives them.
    const double legend_x = 2 * (ring_margin_px + base_radius_px) + 10;
    double y = title_px + 30;
    out += fmt::format(R"(<text x="{:.2f}" y="{:.2f}" font-weight="bold">station: Z, D, d = D − E (mm)</text>)"
                       "\n",
                       legend_x, y);
    for (std::size_t i = 0; i < stations; ++i) {
        y += 20;
        const double z = job.z_mm[i];
        const double d = profile.major_diameter_mm(z);
        const double e = profile.ovality_mm(z);
        out +=
            fmt::format(R"(<line x1="{:.2f}" y1="{:.2f}" x2="{:.2f}" y2="{:.2f}" stroke="{}" stroke-width="{}"/>)"
                        "\n",
                        legend_x, y - 4, legend_x + 24, y - 4, process_detail::line_colour(i), i == middle ? 2.6 : 1.2);
        out += fmt::format(R"(<text x="{:.2f}" y="{:.2f}">Z {:g}: D {:.4f}, d {:.4f}{}</text>)"
                           "\n",
                           legend_x + 30, y, z, d, d - e, i == middle ? " (middle)" : "");
    }
    y += 30;
    out += fmt::format(R"(<text x="{:.2f}" y="{:.2f}" fill="#555555">shape: {}</text>)"
                       "\n",
                       legend_x, y, cam::name(profile.shape().kind()));
    out += "</svg>\n";
    return out;
}

}  // namespace nckit
