// The stroke reference: the middle of the cam table's radial range at each Z, as a spline.
#include "nckit/process/fts/stroke_reference.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

namespace nckit {

namespace {

//! Z spacing of the stroke reference's points, mm: a drawing's D and E change over tens of mm,
//! so half a millimetre follows them to far below a DAC step.
constexpr double reference_spacing_mm = 0.5;

//! The extreme of three neighbouring samples (spacing 1) through their parabola; the middle
//! sample when they lie on a line.
double parabola_peak(double before, double middle, double after) {
    const double curvature = before - 2.0 * middle + after;
    if (curvature == 0.0) return middle;
    const double offset = 0.5 * (before - after) / curvature;
    return middle - 0.25 * (before - after) * offset;
}

cam::NaturalSpline reference_spline(const cam::CamTable& table, std::size_t points, double theta_step_deg) {
    if (points < 2 || !(theta_step_deg > 0.0) || !(table.z_to_mm() > table.z_from_mm())) {
        throw std::invalid_argument("a stroke reference needs 2 points, a positive step and a Z range");
    }
    const auto count = static_cast<std::size_t>(std::max(3.0, std::round(360.0 / theta_step_deg)));
    std::vector<double> z(points), mid(points), turn;
    for (std::size_t i = 0; i < points; ++i) {
        const double f = static_cast<double>(i) / static_cast<double>(points - 1);
        z[i] = i + 1 == points ? table.z_to_mm() : table.z_from_mm() + f * (table.z_to_mm() - table.z_from_mm());
        sample_turn(table, z[i], count, turn);
        const auto high = static_cast<std::size_t>(std::max_element(turn.begin(), turn.end()) - turn.begin());
        const auto low = static_cast<std::size_t>(std::min_element(turn.begin(), turn.end()) - turn.begin());
        auto at = [&](std::size_t k, int step) { return turn[(k + count + static_cast<std::size_t>(step)) % count]; };
        const double r_max = parabola_peak(at(high, -1), turn[high], at(high, 1));
        const double r_min = parabola_peak(at(low, -1), turn[low], at(low, 1));
        mid[i] = 0.5 * (r_max + r_min);
    }
    return cam::NaturalSpline(std::move(z), std::move(mid));
}

}  // namespace

void sample_turn(const cam::CamTable& table, double z_mm, std::size_t count, std::vector<double>& out) {
    out.resize(count);
    for (std::size_t k = 0; k < count; ++k) {
        out[k] = table(360.0 * static_cast<double>(k) / static_cast<double>(count), z_mm);
    }
}

std::size_t stroke_reference_points(const cam::CamTable& table) {
    const double span = table.z_to_mm() - table.z_from_mm();
    return std::clamp<std::size_t>(static_cast<std::size_t>(std::ceil(span / reference_spacing_mm)) + 1, 17, 4097);
}

StrokeReference::StrokeReference(const cam::CamTable& table, std::size_t points, double theta_step_deg)
    : spline_(reference_spline(table, points, theta_step_deg)) {}

}  // namespace nckit
