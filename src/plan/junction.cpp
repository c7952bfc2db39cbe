#include "junction.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "transition.hpp"

namespace nckit::plan_detail {

bool tangent(const PathSegment& before, const PathSegment& after) {
    const AxisVector d_end = point_at(before, before.length).d1;
    const AxisVector d_start = point_at(after, 0.0).d1;
    for (std::size_t i = 0; i < axis_count; ++i) {
        if (std::abs(d_end[i] - d_start[i]) > tangent_tolerance) return false;
    }
    return true;
}

std::optional<Blend> blend_lines(const PathSegment& before, double before_full_mm, const PathSegment& after,
                                 double tolerance_mm) {
    if (before.shape != SegmentShape::line || after.shape != SegmentShape::line || !(tolerance_mm > 0)) {
        return std::nullopt;
    }
    // Unit XYZ directions (the measured axes must be XYZ on both).
    std::array<double, 3> d1{};
    std::array<double, 3> d2{};
    double n1 = 0;
    double n2 = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        d1[i] = before.rate[i];
        d2[i] = after.rate[i];
        n1 += d1[i] * d1[i];
        n2 += d2[i] * d2[i];
    }
    if (std::abs(n1 - 1.0) > 1e-9 || std::abs(n2 - 1.0) > 1e-9) return std::nullopt;
    for (std::size_t i = 3; i < axis_count; ++i) {
        if (std::abs(before.rate[i] - after.rate[i]) > 1e-12 * std::max(1.0, std::abs(before.rate[i]))) {
            return std::nullopt;
        }
    }
    // Turning angle without cancellation at small angles.
    const double dot = d1[0] * d2[0] + d1[1] * d2[1] + d1[2] * d2[2];
    const std::array<double, 3> cross{d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2],
                                      d1[0] * d2[1] - d1[1] * d2[0]};
    const double sin_phi = std::sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]);
    const double phi = std::atan2(sin_phi, dot);
    if (!(phi > 0) || phi > std::numbers::pi - reversal_margin_rad) return std::nullopt;

    // 1/cos(φ/2) − 1 = 2 sin²(φ/4) / cos(φ/2), so the trim at the tolerance is
    // R·tan(φ/2) = tol·sin(φ/2) / (2 sin²(φ/4)).
    const double s4 = std::sin(0.25 * phi);
    const double half_tan = std::tan(0.5 * phi);
    const double trim_at_tolerance = tolerance_mm * std::sin(0.5 * phi) / (2.0 * s4 * s4);
    const double trim = std::min({trim_at_tolerance, 0.5 * before_full_mm, 0.5 * after.length, before.length});
    const double radius = trim / half_tan;
    if (!(radius >= min_blend_radius_mm)) return std::nullopt;

    Blend blend;
    blend.trim_mm = trim;
    blend.deviation_mm = radius * 2.0 * s4 * s4 / std::cos(0.5 * phi);
    const AxisVector start = position_at(before, before.length - trim);
    // The centre lies R from the start, perpendicular to d1, toward d2.
    std::array<double, 3> normal{};
    double nn = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        normal[i] = d2[i] - dot * d1[i];
        nn += normal[i] * normal[i];
    }
    nn = std::sqrt(nn);
    std::array<double, 3> centre{};
    for (std::size_t i = 0; i < 3; ++i) centre[i] = start[i] + radius * normal[i] / nn;
    blend.arc = make_circular(start, centre, d1, phi, before.rate);
    return blend;
}

std::optional<Blend> parabolic_corner(const PathSegment& before, double before_full_mm, const PathSegment& after,
                                      double tolerance_mm) {
    // The same corners as the circular blend (lines of unit XYZ direction, other axes at one rate).
    const std::optional<Blend> circle = blend_lines(before, before_full_mm, after, tolerance_mm);
    if (!circle) return std::nullopt;
    std::array<double, 3> jump{};
    double jump_norm = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        jump[i] = after.rate[i] - before.rate[i];
        jump_norm += jump[i] * jump[i];
    }
    jump_norm = std::sqrt(jump_norm);
    double trim = std::min({4.0 * tolerance_mm / jump_norm, 0.5 * before_full_mm, 0.5 * after.length, before.length});
    // A sliver of `before` left between this corner and the one before would be planned as a
    // segment of its own: the corner takes it when that keeps the tolerance and half of `after`,
    // else it leaves a whole min_leftover_mm.
    const double leftover = before.length - trim;
    if (leftover > 0 && leftover < min_leftover_mm) {
        const bool fits = before.length <= 0.5 * after.length && before.length * jump_norm / 4.0 <= tolerance_mm;
        if (fits) {
            trim = before.length;
        } else if (before.length > 2 * min_leftover_mm) {
            trim = before.length - min_leftover_mm;
        }
    }
    if (!(trim > 0)) return std::nullopt;
    Blend blend;
    blend.trim_mm = trim;
    blend.deviation_mm = trim * jump_norm / 4.0;
    PathSegment& g = blend.arc;
    g.shape = SegmentShape::quintic;
    g.length = 2.0 * trim;
    g.origin = position_at(before, before.length - trim);
    g.rate = before.rate;
    for (std::size_t i = 0; i < 3; ++i) g.poly[0][i] = jump[i] / (4.0 * trim);  // K/2
    return blend;
}

}  // namespace nckit::plan_detail
