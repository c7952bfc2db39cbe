// The eccentric cam in closed form, and the least-squares circle through a cut section.
#include <cmath>

#include <Eigen/Dense>

#include "eccentric_section.hpp"
#include "nckit/process/eccentric/eccentric.hpp"

namespace nckit {

// With R = r + Rn and S = R² − e² sin² θ, q = sqrt(S): a = e cos θ + q − Rn, and q's derivatives
// follow from S' = −e² sin 2θ, S'' = −2e² cos 2θ, S''' = 4e² sin 2θ:
//   q' = S'/(2q),  q'' = S''/(2q) − S'²/(4q³),  q''' = S'''/(2q) − 3S'S''/(4q³) + 3S'³/(8q⁵).
EccentricCamPoint eccentric_cam(const EccentricJob& job, double theta_rad) {
    const double e = job.eccentricity_mm;
    const double big_r = job.eccentric_radius_mm + job.nose_radius_mm;
    const double s = std::sin(theta_rad);
    const double c = std::cos(theta_rad);
    const double sin2 = std::sin(2 * theta_rad);
    const double cos2 = std::cos(2 * theta_rad);
    const double big_s = big_r * big_r - e * e * s * s;
    const double q = std::sqrt(big_s);
    const double s1 = -e * e * sin2;
    const double s2 = -2 * e * e * cos2;
    const double s3 = 4 * e * e * sin2;
    const double q3 = q * q * q;
    EccentricCamPoint p;
    p.radius_mm = e * c + q - job.nose_radius_mm;
    p.d1_mm_rad = -e * s + s1 / (2 * q);
    p.d2_mm_rad2 = -e * c + s2 / (2 * q) - s1 * s1 / (4 * q3);
    p.d3_mm_rad3 = e * s + s3 / (2 * q) - 3 * s1 * s2 / (4 * q3) + 3 * s1 * s1 * s1 / (8 * q3 * q * q);
    return p;
}

namespace eccentric_detail {

// Kåsa's algebraic fit: x² + y² + D x + E y + F = 0 in least squares, a linear problem; for a
// whole section with µm deviations it agrees with the geometric fit far below a nanometre.
SectionFit fit_section(const std::vector<std::array<double, 2>>& points, const EccentricJob& job) {
    Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
    Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
    for (const auto& p : points) {
        const Eigen::Vector3d row(p[0], p[1], 1.0);
        normal += row * row.transpose();
        rhs -= row * (p[0] * p[0] + p[1] * p[1]);
    }
    const Eigen::Vector3d solution = normal.ldlt().solve(rhs);
    const double cx = -solution[0] / 2;
    const double cy = -solution[1] / 2;
    const double fitted_radius = std::sqrt(cx * cx + cy * cy - solution[2]);
    const double drawing_radius = job.eccentric_radius_mm + job.nose_radius_mm;  // of the nose centre's path
    double low = HUGE_VAL;
    double high = -HUGE_VAL;
    double worst = 0;
    for (const auto& p : points) {
        const double d = std::hypot(p[0] - cx, p[1] - cy);
        low = std::min(low, d);
        high = std::max(high, d);
        worst = std::max(worst, std::abs(std::hypot(p[0] - job.eccentricity_mm, p[1]) - drawing_radius));
    }
    SectionFit fit;
    fit.roundness_um = (high - low) * 1000;
    fit.center_offset_um = std::hypot(cx - job.eccentricity_mm, cy) * 1000;
    fit.radius_error_um = (fitted_radius - drawing_radius) * 1000;
    fit.max_deviation_um = worst * 1000;
    return fit;
}

}  // namespace eccentric_detail

}  // namespace nckit
