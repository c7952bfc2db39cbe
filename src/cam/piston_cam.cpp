#include "nckit/cam/piston_cam.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

namespace nckit::cam {

std::size_t aligned_z_cells(std::span<const double> breaks_mm, std::size_t max_cells) {
    if (breaks_mm.size() < 2) return 1;
    const double from = breaks_mm.front();
    const double range = breaks_mm.back() - from;
    if (!(range > 0)) return 1;
    // Stations written with a few decimals land on a node to rounding error, never exactly.
    const double slack = 1e-9 * std::max(range, 1.0);
    for (std::size_t cells = 1; cells <= max_cells; ++cells) {
        const double h = range / static_cast<double>(cells);
        const bool aligned = std::all_of(breaks_mm.begin(), breaks_mm.end(), [&](double z) {
            const double node = std::round((z - from) / h);
            return std::abs(from + node * h - z) <= slack;
        });
        if (aligned) return cells;
    }
    return 0;
}

CamTableOptions piston_cam_options(std::span<const double> breaks_mm, double tolerance_mm) {
    if (breaks_mm.empty()) throw std::invalid_argument("piston_cam_options needs stations");
    CamTableOptions options;
    options.z_from_mm = breaks_mm.front();
    options.z_to_mm = breaks_mm.back();
    options.tolerance_mm = tolerance_mm;
    std::size_t cells = aligned_z_cells(breaks_mm);
    if (cells == 0) {
        double shortest = options.z_to_mm - options.z_from_mm;
        for (std::size_t i = 1; i < breaks_mm.size(); ++i) {
            shortest = std::min(shortest, breaks_mm[i] - breaks_mm[i - 1]);
        }
        cells = static_cast<std::size_t>(std::ceil((options.z_to_mm - options.z_from_mm) / shortest));
    }
    options.min_z_cells = std::max<std::size_t>(cells, 1);
    return options;
}

CamTable build_piston_cam_table(const PistonProfile& profile, const CamTableOptions& options) {
    return CamTable::build(std::cref(profile), options);
}

}  // namespace nckit::cam
