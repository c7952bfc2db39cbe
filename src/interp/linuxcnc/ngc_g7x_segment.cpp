// The geometry of one profile element of LinuxCNC's lathe cycles: offsets, where it crosses a
// level of X, where two neighbours meet, and the three ways a roughing pass follows it (dive:
// down into the stock; climb: back up along the shape; climb_only: G71.1's final pass).
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "ngc_g7x_profile.hpp"

namespace nckit::interp::ngc::g7x_detail {

namespace {

constexpr ZX unit_x(0, 1);

//! Back from the working frame: the inverse of the turn and mirrors, in LinuxCNC's numbering.
ZX unflip(int flips, ZX p) {
    switch (flips) {
        case 1:
            return -std::conj(p);
        case 2:
            return std::conj(p);
        case 3:
            return -p;
        case 4:
            return unit_x * p;
        case 5:
            return std::conj(unit_x * p);
        case 6:
            return -std::conj(unit_x * p);
        case 7:
            return -unit_x * p;
        default:
            return p;
    }
}

bool mirrors(int flips) {
    return flips == 1 || flips == 2 || flips == 5 || flips == 6;
}

bool on_arc(const ProfileSegment& s, ZX p) {
    const double from_start = std::imag(std::conj(s.start - s.center) * (p - s.center));
    const double to_end = std::imag(std::conj(s.end - s.center) * (p - s.center));
    if (s.ccw) return from_start >= -tolerance && to_end <= tolerance;
    return from_start <= tolerance && to_end >= -tolerance;
}

//! Where the circle through `arc` crosses the line through `line` nearest to `near`.
ZX circle_meets_line(const ProfileSegment& arc, ZX line_from, ZX line_to, ZX near) {
    const ZX rot = std::conj(line_from - line_to) / std::abs(line_from - line_to);
    const ZX end_rel = (arc.end - line_to) * rot;
    const ZX center_rel = (arc.center - line_to) * rot;
    double b = std::norm(center_rel - end_rel) - std::imag(center_rel) * std::imag(center_rel);
    b = b < 0 ? 0 : std::sqrt(b);
    const ZX s1 = (std::real(center_rel) + b) / rot + line_to;
    const ZX s2 = (std::real(center_rel) - b) / rot + line_to;
    return std::abs(near - s1) < std::abs(near - s2) ? s1 : s2;
}

}  // namespace

namespace {
constexpr std::size_t max_moves = 2'000'000;  //!< a cycle making more has lost its way
}

void MoveSink::rapid(ZX end, bool comp_off) {
    if (out->size() >= max_moves) return fail("the cycle makes more than 2,000,000 moves");
    ProfileMove m{ProfileMove::Kind::rapid, unflip(flips, end), {}, false, comp_off};
    out->push_back(m);
}

void MoveSink::feed(ZX end) {
    if (out->size() >= max_moves) return fail("the cycle makes more than 2,000,000 moves");
    out->push_back(ProfileMove{ProfileMove::Kind::feed, unflip(flips, end), {}, false});
}

void MoveSink::arc(bool ccw, ZX center, ZX end) {
    if (out->size() >= max_moves) return fail("the cycle makes more than 2,000,000 moves");
    const bool turned_ccw = mirrors(flips) ? !ccw : ccw;
    out->push_back(ProfileMove{ProfileMove::Kind::arc, unflip(flips, end), unflip(flips, center), turned_ccw});
}

double length_scale(const ProfileSegment& s) {
    if (!s.arc) return std::abs(s.start - s.end);
    return std::min(std::abs(s.start - s.end), std::abs(s.start - s.center));
}

bool monotonic(const ProfileSegment& s) {
    if (!s.arc) return std::real(s.end - s.start) <= 1e-3;
    if (s.finish != 0) return true;
    const double entry = std::imag(s.start - s.center);
    const double exit = std::imag(s.end - s.center);
    const double dz = std::real(s.end - s.start);
    if (s.ccw) return entry >= -1e-3 && exit >= -1e-3 && dz <= -1e-3;
    return entry <= 1e-3 && exit <= 1e-3 && dz <= -1e-3;
}

void offset(ProfileSegment& s, double distance) {
    if (!s.arc) {
        const ZX by = unit_x * distance * (s.start - s.end) / std::abs(s.start - s.end);
        s.start += by;
        s.end += by;
        return;
    }
    const double radius = std::abs(s.start - s.center);
    const double factor = (radius + (s.ccw ? 1 : -1) * distance) / radius;
    s.start = factor * (s.start - s.center) + s.center;
    s.end = factor * (s.end - s.center) + s.center;
}

void shift(ProfileSegment& s, ZX by) {
    s.start += by;
    s.end += by;
    if (s.arc) s.center += by;
}

void mirror_x(ProfileSegment& s) {
    s.start = std::conj(s.start);
    s.end = std::conj(s.end);
    if (s.arc) {
        s.ccw = !s.ccw;
        s.center = std::conj(s.center);
    }
}

void mirror_z(ProfileSegment& s) {
    s.start = -std::conj(s.start);
    s.end = -std::conj(s.end);
    if (s.arc) {
        s.ccw = !s.ccw;
        s.center = -std::conj(s.center);
    }
}

void turn(ProfileSegment& s) {
    s.start = -s.start * unit_x;
    s.end = -s.end * unit_x;
    if (s.arc) s.center = -s.center * unit_x;
}

std::vector<double> crossings_at_x(const ProfileSegment& s, double x) {
    std::vector<double> found;
    if (!s.arc) {
        if (std::min(s.start.imag(), s.end.imag()) > x + tolerance ||
            std::max(s.start.imag(), s.end.imag()) < x - tolerance) {
            return found;
        }
        if (std::abs(std::imag(s.start - s.end)) < tolerance) {
            found = {s.start.real(), s.end.real()};
        } else {
            found.push_back((x - s.start.imag()) / (s.end.imag() - s.start.imag()) * (s.end.real() - s.start.real()) +
                            s.start.real());
        }
        return found;
    }
    const double r = std::abs(s.start - s.center);
    double square = -(x - r - s.center.imag()) * (x + r - s.center.imag());
    if (square < -tolerance) return found;
    const double half = std::sqrt(std::max(square, 0.0));
    const ZX p1(std::real(s.center) + half, x);
    if (on_arc(s, p1)) found.push_back(std::real(p1));
    const ZX p2(std::real(s.center) - half, x);
    if (on_arc(s, p2)) found.push_back(std::real(p2));
    return found;
}

void meet(ProfileSegment& p, ProfileSegment& n, MoveSink& sink) {
    if (!p.arc && !n.arc) {
        const ZX rot = std::conj(n.start - n.end) / std::abs(n.start - n.end);
        const ZX ps = (p.start - n.end) * rot;
        const ZX pe = (p.end - n.end) * rot;
        if (std::imag(ps - pe) == 0) {
            sink.fail("cannot intersect parallel lines");
            return;
        }
        const double f = std::imag(ps) / std::imag(ps - pe);
        n.start = p.end = (ps + f * (pe - ps)) / rot + n.end;
    } else if (p.arc && !n.arc) {
        if (std::abs(n.start - p.end) < tolerance) return;
        n.start = p.end = circle_meets_line(p, n.start, n.end, n.start);
    } else if (!p.arc && n.arc) {
        if (std::abs(n.start - p.end) < tolerance) return;
        n.start = p.end = circle_meets_line(n, p.start, p.end, n.start);
    } else {
        // Two circles: the law of cosines in the triangle of their centres and the meeting point.
        const double a = std::abs(n.start - n.center);
        const double b = std::abs(p.start - p.center);
        const double c = std::abs(n.center - p.center);
        const double cos_b = (c * c + a * a - b * b) / 2.0 / a / c;
        const double cos_b2 = std::min(cos_b * cos_b, 1.0);
        const ZX rot(cos_b, std::sqrt(1 - cos_b2));
        n.start = p.end = rot * (p.center - n.center) / c * a + n.center;
    }
}

void draw(const ProfileSegment& s, MoveSink& sink) {
    if (s.arc) {
        sink.arc(s.ccw, s.center, s.end);
    } else {
        sink.feed(s.end);
    }
}

bool climb(const ProfileSegment& s, ZX& at, MoveSink& sink) {
    if (!s.arc) {
        if (s.end.imag() + tolerance < s.start.imag()) return true;  // going down: not a climb
        if (std::abs(at - s.start) > tolerance) {
            sink.fail(fmt::format("climb off the profile at Z{:.4f} X{:.4f}", at.real(), at.imag()));
            return true;
        }
        sink.feed(s.end);
        at = s.end;
        return false;
    }
    if (!s.ccw) {
        if (at.real() > s.center.real()) return true;
        if (std::abs(at - s.end) > 1e-3) sink.arc(s.ccw, s.center, s.end);
        at = s.end;
        return false;
    }
    if (at.real() < s.center.real()) return true;
    ZX top = s.end;
    if (s.end.real() < s.center.real()) top = ZX(s.center.real(), s.center.imag() + std::abs(s.start - s.center));
    if (std::abs(at - top) > 1e-3) sink.arc(s.ccw, s.center, top);
    at = top;
    return true;
}

void climb_only(const ProfileSegment& s, ZX& at, MoveSink& sink) {
    if (!s.arc && s.end.imag() < s.start.imag()) return;
    const std::vector<double> is = crossings_at_x(s, at.imag());
    if (is.empty()) return;
    if (!s.arc) {
        at.real(is.front());
        sink.feed(at);
        sink.feed(s.end);
        at = s.end;
        return;
    }
    if (!s.ccw) {
        if (is.back() > s.center.real()) return;
        at.real(is.back());
        sink.feed(at);
        if (std::abs(at - s.end) > 1e-3) sink.arc(s.ccw, s.center, s.end);
        at = s.end;
        return;
    }
    if (is.front() < s.center.real()) return;
    at.real(is.front());
    sink.feed(at);
    ZX top = s.end;
    if (s.end.real() < s.center.real()) top = ZX(s.center.real(), s.center.imag() + std::abs(s.start - s.center));
    if (std::abs(at - top) > 1e-3) sink.arc(s.ccw, s.center, top);
    at = top;
}

bool dive(const ProfileSegment& s, ZX& at, double x, MoveSink& sink, bool fast) {
    if (!s.arc) {
        if (s.start.imag() <= s.end.imag() + tolerance) return true;  // not going down
        ZX to = s.end;
        if (x >= s.end.imag()) {
            const std::vector<double> is = crossings_at_x(s, x);
            if (is.empty()) {
                sink.fail("level above a line going down");
                return true;
            }
            to = ZX(is.front(), x);
        }
        if (fast) {
            sink.rapid(to);
        } else {
            sink.feed(to);
        }
        at = to;
        return false;
    }
    if (std::abs(at - s.end) < tolerance || std::real(at - s.end) <= tolerance) {
        at = s.end;
        return false;
    }
    std::vector<double> is = crossings_at_x(s, x);
    if (is.empty()) is = crossings_at_x(s, x - tolerance);
    if (s.ccw) {
        if (at.real() - tolerance > s.center.real()) return true;
        if (is.empty() || is.back() > std::real(s.center)) {
            sink.arc(s.ccw, s.center, s.end);
            at = s.end;
        } else {
            const ZX to(is.back(), x);
            sink.arc(s.ccw, s.center, to);
            at = to;
        }
        return false;
    }
    if (at.real() <= s.center.real()) return true;  // already climbing
    if (is.empty()) {
        sink.arc(s.ccw, s.center, s.end);
        at = s.end;
    } else if (is.front() >= std::real(s.center)) {
        const ZX to(is.front(), x);
        sink.arc(s.ccw, s.center, to);
        at = to;
    }
    // else: the level meets only the arc's rising side; the pass search lowers the level.
    return false;
}

void shape_corner(ProfileSegment& corner, ProfileSegment& prev, ProfileSegment& next, MoveSink& sink) {
    // Offset both neighbours by the finish's size towards the corner's inside (where they still
    // overlap in Z); where the offsets meet is the fillet's centre (the chamfer's middle).
    double size = corner.finish;
    ProfileSegment p = prev;
    ProfileSegment n = next;
    offset(p, size);
    offset(n, size);
    if (std::real(p.end - n.start) > 1e-2) {
        size = -size;
        p = prev;
        n = next;
        offset(p, size);
        offset(n, size);
    }
    if (std::real(p.end - n.start) > 1e-2) {
        sink.fail(fmt::format("corner finish failed at Z{:.4f} X{:.4f}", prev.end.real(), prev.end.imag()));
        return;
    }
    meet(p, n, sink);
    const ZX center = (p.end + n.start) / 2.0;
    offset(p, -size);
    offset(n, -size);
    corner.start = prev.end = p.end;
    corner.end = next.start = n.start;
    if (corner.corner == CornerFinish::fillet) {
        corner.center = center;
        corner.ccw = std::imag(corner.start - center) > 0 || std::imag(corner.end - center) > 0;
        corner.finish = 0;
    } else {
        corner.finish = size;
    }
}

}  // namespace nckit::interp::ngc::g7x_detail
