#pragma once
// What nckit's SVG plots share (crosshatch, piston): round tick steps, the document frame,
// line colours.
// Written by hand: a few dozen elements per plot need no plotting
// library, and plain text keeps the files byte-identical from run to run.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <string>

#include <fmt/format.h>

namespace nckit::process_detail {

//! A round step near span / count, at least that: 1, 2 or 5 times a power of ten.
inline double tick_step(double span, double count) {
    const double raw = span / count;
    if (!(raw > 0.0) || !std::isfinite(raw)) return 1.0;
    const double decade = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0}) {
        if (m * decade >= raw * (1.0 - 1e-12)) return m * decade;
    }
    return 10.0 * decade;
}

//! The largest 1, 2, 2.5 or 5 times a power of ten at or below `value` (> 0): a scale factor
//! a reader multiplies by in their head.
inline double round_down_scale(double value) {
    const double decade = std::pow(10.0, std::floor(std::log10(value)));
    for (double m : {5.0, 2.5, 2.0, 1.0}) {
        if (m * decade <= value * (1.0 + 1e-12)) return m * decade;
    }
    return decade;
}

//! Decimals that show a multiple of `step` exactly (0 for whole steps).
inline int decimals_for(double step) {
    return std::clamp(static_cast<int>(-std::floor(std::log10(step) + 1e-9)), 0, 9);
}

//! Opening tag with a white background; the caller closes it with "</svg>\n".
inline std::string svg_open(double width_px, double height_px) {
    return fmt::format(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0:.0f}\" height=\"{1:.0f}\" "
        "viewBox=\"0 0 {0:.0f} {1:.0f}\" font-family=\"sans-serif\" font-size=\"12\">\n"
        "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
        width_px, height_px);
}

//! A colour per curve, distinguishable in print and by most colour-blind readers.
inline const char* line_colour(std::size_t index) {
    static constexpr std::array<const char*, 8> colours{"#1f77b4", "#d62728", "#2ca02c", "#9467bd",
                                                        "#ff7f0e", "#17becf", "#8c564b", "#e377c2"};
    return colours[index % colours.size()];
}

}  // namespace nckit::process_detail
