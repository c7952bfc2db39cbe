#include "nckit/cam/profile_demand.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace nckit::cam {

namespace {
constexpr double two_pi = 2.0 * std::numbers::pi;

double omega_rad_s(double rpm) {
    return two_pi * rpm / 60.0;
}
}  // namespace

double ProfileDemand::acceleration_mm_s2(double rpm) const {
    const double omega = omega_rad_s(rpm);
    return omega * omega * curvature_mm_rad2;
}

double ProfileDemand::max_rpm(double max_acceleration_mm_s2) const {
    if (curvature_mm_rad2 <= 0) return std::numeric_limits<double>::infinity();
    return std::sqrt(max_acceleration_mm_s2 / curvature_mm_rad2) * 60.0 / two_pi;
}

std::vector<double> demand_z_grid(std::span<const double> z_mm, int z_subdivisions) {
    if (z_mm.empty() || z_subdivisions < 1) {
        throw std::invalid_argument("demand_z_grid needs stations and z_subdivisions >= 1");
    }
    std::vector<double> grid{z_mm.front()};
    for (std::size_t i = 1; i < z_mm.size(); ++i) {
        const double from = z_mm[i - 1];
        const double step = (z_mm[i] - from) / z_subdivisions;
        for (int k = 1; k < z_subdivisions; ++k) grid.push_back(from + k * step);
        grid.push_back(z_mm[i]);
    }
    return grid;
}

ProfileDemand measure_demand(const CamFunction& radius_mm, std::span<const double> z_mm, DemandGrid grid) {
    if (!(grid.theta_step_deg > 0) || grid.theta_step_deg > 90.0) {
        throw std::invalid_argument("measure_demand needs 0 < theta_step_deg <= 90");
    }
    const auto points = static_cast<std::size_t>(std::lround(360.0 / grid.theta_step_deg));
    const double step_deg = 360.0 / static_cast<double>(points);
    const double step_rad = step_deg * std::numbers::pi / 180.0;
    ProfileDemand demand;
    demand.min_radius_mm = std::numeric_limits<double>::infinity();
    std::vector<double> turn(points);
    for (double z : demand_z_grid(z_mm, grid.z_subdivisions)) {
        for (std::size_t i = 0; i < points; ++i) {
            turn[i] = radius_mm(static_cast<double>(i) * step_deg, z);
            demand.finite = demand.finite && std::isfinite(turn[i]);
        }
        if (!demand.finite) return demand;
        const auto [low, high] = std::minmax_element(turn.begin(), turn.end());
        if (*high - *low > demand.stroke_mm) {
            demand.stroke_mm = *high - *low;
            demand.stroke_z_mm = z;
        }
        demand.min_radius_mm = std::min(demand.min_radius_mm, *low);
        for (std::size_t i = 0; i < points; ++i) {
            const double before = turn[(i + points - 1) % points];
            const double after = turn[(i + 1) % points];
            const double curvature = std::abs(before - 2.0 * turn[i] + after) / (step_rad * step_rad);
            if (curvature > demand.curvature_mm_rad2) {
                demand.curvature_mm_rad2 = curvature;
                demand.curvature_theta_deg = static_cast<double>(i) * step_deg;
                demand.curvature_z_mm = z;
            }
        }
    }
    return demand;
}

}  // namespace nckit::cam
