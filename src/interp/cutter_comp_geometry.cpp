#include "cutter_comp_geometry.hpp"

#include <algorithm>
#include <numbers>

namespace nckit::interp::comp {

namespace {
constexpr double pi = std::numbers::pi;
// A crossing this far off (squared distance, mm²) still counts as touching: offsets computed
// from rounded program values miss a tangent crossing by about this much.
constexpr double touch_mm2 = 1e-12;

//! Up to two points where the line through p along unit d meets the circle (c, rho).
int line_circle(Vec2 p, Vec2 d, Vec2 c, double rho, Vec2 (&out)[2]) {
    Vec2 w = p - c;
    double b = dot(w, d);
    double disc = b * b - (dot(w, w) - rho * rho);
    if (disc < -touch_mm2) return 0;
    double root = std::sqrt(std::max(0.0, disc));
    out[0] = p + (-b - root) * d;
    out[1] = p + (-b + root) * d;
    return 2;
}

int circle_circle(Vec2 c1, double r1, Vec2 c2, double r2, Vec2 (&out)[2]) {
    Vec2 d = c2 - c1;
    double dist = length(d);
    if (dist == 0) return 0;
    double a = (r1 * r1 - r2 * r2 + dist * dist) / (2 * dist);
    double h2 = r1 * r1 - a * a;
    if (h2 < -touch_mm2) return 0;
    double h = std::sqrt(std::max(0.0, h2));
    Vec2 u = (1.0 / dist) * d;
    Vec2 mid = c1 + a * u;
    out[0] = mid + h * left_normal(u);
    out[1] = mid - h * left_normal(u);
    return 2;
}

}  // namespace

Vec2 start_tangent(const Segment& s) {
    if (!s.arc) return unit(s.end - s.start);
    return static_cast<double>(s.turn) * unit(left_normal(s.start - s.center));
}

Vec2 end_tangent(const Segment& s) {
    if (!s.arc) return unit(s.end - s.start);
    return static_cast<double>(s.turn) * unit(left_normal(s.end - s.center));
}

std::optional<Segment> offset(const Segment& s, int side, double r) {
    Segment o = s;
    if (!s.arc) {
        Vec2 n = static_cast<double>(side) * left_normal(unit(s.end - s.start));
        o.start = s.start + r * n;
        o.end = s.end + r * n;
        return o;
    }
    double r_start = length(s.start - s.center);
    double r_end = length(s.end - s.center);
    double grow = tool_inside(s, side) ? -r : r;
    // An inside arc of the tool's own radius shrinks to its centre, where the tool pivots (as
    // LinuxCNC runs it); only a smaller arc cannot be cut.
    auto shrunk = [&](double radius) { return std::abs(radius + grow) <= same_radius_mm ? 0.0 : radius + grow; };
    const double new_start = shrunk(r_start);
    const double new_end = shrunk(r_end);
    if (new_start < 0 || new_end < 0) return std::nullopt;
    o.start = s.center + (new_start / r_start) * (s.start - s.center);
    o.end = s.center + (new_end / r_end) * (s.end - s.center);
    return o;
}

Corner classify(const Segment& a, const Segment& b, int side) {
    Vec2 ta = end_tangent(a);
    Vec2 tb = start_tangent(b);
    // Turn toward the tool's side is positive: the path closes in on the tool.
    double toward_tool = side * std::atan2(cross(ta, tb), dot(ta, tb));
    if (std::abs(toward_tool) <= corner_tolerance_rad) return Corner::tangent;
    if (std::abs(toward_tool) >= pi - corner_tolerance_rad) {
        bool follows_outside = b.arc ? !tool_inside(b, side) : (a.arc && !tool_inside(a, side));
        return follows_outside ? Corner::inside : Corner::outside;
    }
    return toward_tool > 0 ? Corner::inside : Corner::outside;
}

std::optional<Vec2> inside_corner(const Segment& a_off, const Segment& b_off, Vec2 corner) {
    Vec2 points[2];
    int count = 0;
    if (!a_off.arc && !b_off.arc) {
        Vec2 da = unit(a_off.end - a_off.start);
        Vec2 db = unit(b_off.end - b_off.start);
        double denominator = cross(da, db);
        if (denominator == 0) return std::nullopt;
        double t = cross(b_off.start - a_off.end, db) / denominator;
        return a_off.end + t * da;
    }
    if (!a_off.arc) {
        count = line_circle(a_off.end, unit(a_off.end - a_off.start), b_off.center, length(b_off.start - b_off.center),
                            points);
    } else if (!b_off.arc) {
        count = line_circle(b_off.start, unit(b_off.end - b_off.start), a_off.center, length(a_off.end - a_off.center),
                            points);
    } else {
        count = circle_circle(a_off.center, length(a_off.end - a_off.center), b_off.center,
                              length(b_off.start - b_off.center), points);
    }
    if (count == 0) return std::nullopt;
    return length(points[0] - corner) <= length(points[1] - corner) ? points[0] : points[1];
}

double distance_to(Vec2 p, const Segment& s) {
    if (!s.arc) {
        Vec2 d = s.end - s.start;
        double len2 = dot(d, d);
        double t = len2 > 0 ? std::clamp(dot(p - s.start, d) / len2, 0.0, 1.0) : 0.0;
        return length(p - (s.start + t * d));
    }
    // On the arc's span the distance is radial; beyond it, the nearer end point.
    double span = sweep_rad(s.start, s.end, s.center, s.turn);
    double to_p = sweep_rad(s.start, p, s.center, s.turn);
    if (length(s.end - s.start) == 0 || to_p <= span) {
        return std::abs(length(p - s.center) - length(s.start - s.center));
    }
    return std::min(length(p - s.start), length(p - s.end));
}

double sweep_rad(Vec2 from, Vec2 to, Vec2 center, int turn) {
    double a0 = std::atan2(from.y - center.y, from.x - center.x);
    double a1 = std::atan2(to.y - center.y, to.x - center.x);
    double sweep = turn > 0 ? a1 - a0 : a0 - a1;
    while (sweep <= 0) sweep += 2 * pi;
    while (sweep > 2 * pi) sweep -= 2 * pi;
    return sweep;
}

}  // namespace nckit::interp::comp
