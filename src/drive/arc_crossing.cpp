#include "arc_crossing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "nckit/core/bracketed_newton.hpp"

namespace nckit::drive_detail {

namespace {

// q_i(s) and dq_i/ds of one XYZ axis of an arc, as point_at computes them.
struct AxisPoint {
    double position = 0;
    double d1 = 0;
};

AxisPoint arc_axis_at(const PathSegment& g, std::size_t i, double s) {
    if (g.shape == SegmentShape::quintic) {
        const PathPoint p = point_at(g, s);
        return {p.position[i], p.d1[i]};
    }
    const double k = g.angle_rate;
    const double theta = k * s;
    const double c = std::cos(theta);
    const double sn = std::sin(theta);
    return {g.origin[i] + g.rate[i] * s + g.radius_mm * (c * g.u[i] + sn * g.v[i]),
            g.rate[i] + g.radius_mm * k * (-sn * g.u[i] + c * g.v[i])};
}

constexpr double two_pi = 2 * std::numbers::pi;

}  // namespace

//! A quintic transition's turning points on axis i: the roots of the quartic dq/ds, bracketed
//! by sign changes over 64 samples and bisected. The transitions are short and gently curved
//! (their direction turns by at most the corner's angle), so two roots never share a sample step.
static std::vector<double> quintic_turning_points(const PathSegment& g, std::size_t i) {
    std::vector<double> out;
    constexpr int samples = 64;
    auto slope = [&](double s) { return point_at(g, s).d1[i]; };
    double s_a = 0;
    double f_a = slope(0.0);
    for (int k = 1; k <= samples; ++k) {
        const double s_b = g.length * k / samples;
        const double f_b = slope(s_b);
        if ((f_a < 0 && f_b > 0) || (f_a > 0 && f_b < 0)) {
            double lo = s_a;
            double hi = s_b;
            for (int it = 0; it < 100 && hi - lo > 1e-15 * g.length; ++it) {
                const double mid = 0.5 * (lo + hi);
                if ((slope(mid) > 0) == (f_a > 0))
                    lo = mid;
                else
                    hi = mid;
            }
            const double s = 0.5 * (lo + hi);
            if (s > 0 && s < g.length) out.push_back(s);
        }
        s_a = s_b;
        f_a = f_b;
    }
    return out;
}

std::vector<double> arc_turning_points(const PathSegment& g, std::size_t i) {
    if (g.shape == SegmentShape::quintic) return quintic_turning_points(g, i);
    std::vector<double> out;
    const double k = g.angle_rate;
    const double m = std::hypot(g.u[i], g.v[i]);
    if (g.radius_mm <= 0 || k == 0 || m < 1e-15) return out;
    // dq/ds = rate + R k (v cos θ − u sin θ) = rate + R k m cos(θ + φ), φ = atan2(u, v).
    const double c = -g.rate[i] / (g.radius_mm * k * m);
    if (!(std::abs(c) <= 1)) return out;
    const double phi = std::atan2(g.u[i], g.v[i]);
    const double alpha = std::acos(c);
    const double theta_lo = std::min(0.0, k * g.length);
    const double theta_hi = std::max(0.0, k * g.length);
    for (double base : {alpha - phi, -alpha - phi}) {
        double theta = base - two_pi * std::floor((base - theta_lo) / two_pi);
        for (; theta < theta_hi; theta += two_pi) {
            const double s = theta / k;
            if (s > 0 && s < g.length) out.push_back(s);
        }
    }
    std::sort(out.begin(), out.end());
    return out;
}

// Stops when a Newton step is below 1e-13 of the length scale, or the bracket is exhausted.
double arc_crossing_newton(const PathSegment& g, std::size_t i, double spu, double target, double lo, double hi,
                           int direction, double guess) {
    // Searched as an increasing function: direction * (q(s) * spu - target).
    const auto residual = [&](double s) {
        const AxisPoint p = arc_axis_at(g, i, s);
        return ValueSlope{direction * (p.position * spu - target), direction * p.d1 * spu};
    };
    const double scale = 1e-13 * std::max(1.0, g.length);
    return bracketed_newton(residual, lo, hi, guess, NewtonStop{.step_tolerance = scale, .max_iterations = 200}).x;
}

bool ArcAxisCrossings::applies(const PathSegment& g, std::size_t i) {
    const double amplitude = g.radius_mm * std::hypot(g.u[i], g.v[i]);
    const double k = g.angle_rate;
    return amplitude > 0 && k > 0 && std::isfinite(amplitude * k) && std::abs(g.rate[i]) <= 1e-6 * amplitude * k;
}

ArcAxisCrossings::ArcAxisCrossings(const PathSegment& g, std::size_t i) {
    // u cos θ + v sin θ = m cos(θ − ψ) with m = |(u, v)|, ψ = atan2(v, u).
    const double amplitude = g.radius_mm * std::hypot(g.u[i], g.v[i]);
    origin_ = g.origin[i];
    rate_ = g.rate[i];
    inv_amplitude_ = 1.0 / amplitude;
    psi_ = std::atan2(g.v[i], g.u[i]);
    k_ = g.angle_rate;
    inv_k_ = 1.0 / g.angle_rate;
    q_ulp_ = std::numeric_limits<double>::epsilon() * (std::abs(origin_) + amplitude);
    slack_ = 1e-9 * std::max(1.0, g.length);
}

void ArcAxisCrossings::set_interval(double s_a, double s_b) {
    // The branch [n π, (n + 1) π] of k s − ψ that holds the interval: its middle decides, so
    // roundings at the ends (turning points) cannot tip it into the neighbour.
    s_middle_ = 0.5 * (s_a + s_b);
    const double middle = k_ * s_middle_ - psi_;
    const double n = std::floor(middle / std::numbers::pi);
    const bool even = std::fmod(n, 2.0) == 0;
    // cos falls on even branches: φ = n π + acos(c); it rises on odd ones: φ = (n + 1) π − acos(c).
    branch_base_ = even ? n * std::numbers::pi : (n + 1) * std::numbers::pi;
    branch_sign_ = even ? 1.0 : -1.0;
}

}  // namespace nckit::drive_detail
