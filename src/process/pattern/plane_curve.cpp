// Evaluation, splitting and measuring of the pattern's plane curves.
#include "nckit/process/pattern/plane_curve.hpp"

#include <algorithm>
#include <numbers>

namespace nckit::pattern {

namespace {

constexpr double deg = std::numbers::pi / 180.0;

template <class... F>
struct Overload : F... {
    using F::operator()...;
};
template <class... F>
Overload(F...) -> Overload<F...>;

// The cubic piece of `path` that holds s and the local parameter in it.
std::pair<const CubicPiece*, double> locate(const CubicPath& path, double s) {
    const auto n = static_cast<double>(path.pieces.size());
    s = std::clamp(s, 0.0, n);
    auto i = static_cast<std::size_t>(std::min(std::floor(s), n - 1));
    return {&path.pieces[i], s - static_cast<double>(i)};
}

// The piece p restricted to u in [u0, u1] and re-parametrised onto [0, 1].
CubicPiece restrict(const CubicPiece& p, double u0, double u1) {
    const double h = u1 - u0;
    // Taylor expansion about u0: derivatives scaled by h^k / k!.
    const Vec2 d0 = p.point(u0);
    const Vec2 d1 = p.tangent(u0);
    const Vec2 d2 = 0.5 * p.second(u0);
    const Vec2 d3 = p.c[3];
    return CubicPiece{{d0, h * d1, (h * h) * d2, (h * h * h) * d3}};
}

CubicPiece flip(const CubicPiece& p) {
    // q(u) = p(1 - u).
    const Vec2 a = p.point(1.0);
    const Vec2 b = -1.0 * p.tangent(1.0);
    const Vec2 c = 0.5 * p.second(1.0);
    const Vec2 d = -1.0 * p.c[3];
    return CubicPiece{{a, b, c, d}};
}

}  // namespace

double parameter_end(const PlaneCurve& curve) {
    return std::visit(
        Overload{[](const Segment&) { return 1.0; }, [](const ArcCurve& a) { return std::abs(a.sweep_deg); },
                 [](const CubicPath& p) { return static_cast<double>(p.pieces.size()); }},
        curve);
}

Vec2 point_at(const PlaneCurve& curve, double s) {
    return std::visit(Overload{[&](const Segment& l) { return l.from + s * (l.to - l.from); },
                               [&](const ArcCurve& a) {
                                   const double angle = (a.start_deg + (a.sweep_deg < 0 ? -s : s)) * deg;
                                   return a.center + a.radius_mm * Vec2{std::cos(angle), std::sin(angle)};
                               },
                               [&](const CubicPath& p) {
                                   auto [piece, u] = locate(p, s);
                                   return piece->point(u);
                               }},
                      curve);
}

Vec2 tangent_at(const PlaneCurve& curve, double s) {
    return std::visit(Overload{[&](const Segment& l) { return l.to - l.from; },
                               [&](const ArcCurve& a) {
                                   const double sign = a.sweep_deg < 0 ? -1.0 : 1.0;
                                   const double angle = (a.start_deg + sign * s) * deg;
                                   return (sign * a.radius_mm * deg) * Vec2{-std::sin(angle), std::cos(angle)};
                               },
                               [&](const CubicPath& p) {
                                   auto [piece, u] = locate(p, s);
                                   return piece->tangent(u);
                               }},
                      curve);
}

PlaneCurve sub_curve(const PlaneCurve& curve, double s0, double s1) {
    return std::visit(Overload{[&](const Segment&) -> PlaneCurve {
                                   return Segment{point_at(curve, s0), point_at(curve, s1)};
                               },
                               [&](const ArcCurve& a) -> PlaneCurve {
                                   const double sign = a.sweep_deg < 0 ? -1.0 : 1.0;
                                   return ArcCurve{a.center, a.radius_mm, a.start_deg + sign * s0, sign * (s1 - s0)};
                               },
                               [&](const CubicPath& p) -> PlaneCurve {
                                   CubicPath out;
                                   const auto n = static_cast<double>(p.pieces.size());
                                   s0 = std::clamp(s0, 0.0, n);
                                   s1 = std::clamp(s1, s0, n);
                                   auto first = static_cast<std::size_t>(std::min(std::floor(s0), n - 1));
                                   for (std::size_t i = first; i < p.pieces.size() && static_cast<double>(i) < s1;
                                        ++i) {
                                       const double u0 = std::max(0.0, s0 - static_cast<double>(i));
                                       const double u1 = std::min(1.0, s1 - static_cast<double>(i));
                                       if (u1 - u0 <= 1e-15 && !out.pieces.empty()) continue;
                                       out.pieces.push_back(restrict(p.pieces[i], u0, u1));
                                   }
                                   return out;
                               }},
                      curve);
}

PlaneCurve reversed(const PlaneCurve& curve) {
    return std::visit(Overload{[](const Segment& l) -> PlaneCurve {
                                   return Segment{l.to, l.from};
                               },
                               [](const ArcCurve& a) -> PlaneCurve {
                                   return ArcCurve{a.center, a.radius_mm, a.start_deg + a.sweep_deg, -a.sweep_deg};
                               },
                               [](const CubicPath& p) -> PlaneCurve {
                                   CubicPath out;
                                   for (auto it = p.pieces.rbegin(); it != p.pieces.rend(); ++it) {
                                       out.pieces.push_back(flip(*it));
                                   }
                                   return out;
                               }},
                      curve);
}

double curve_length(const PlaneCurve& curve) {
    return std::visit(Overload{[](const Segment& l) { return length(l.to - l.from); },
                               [](const ArcCurve& a) { return a.radius_mm * std::abs(a.sweep_deg) * deg; },
                               [](const CubicPath& p) {
                                   // 5-point Gauss–Legendre on 4 sub-intervals of each piece.
                                   static constexpr std::array<double, 5> x{0.0, -0.5384693101056831,
                                                                            0.5384693101056831, -0.9061798459386640,
                                                                            0.9061798459386640};
                                   static constexpr std::array<double, 5> w{0.5688888888888889, 0.4786286704993665,
                                                                            0.4786286704993665, 0.2369268850561891,
                                                                            0.2369268850561891};
                                   double total = 0;
                                   for (const CubicPiece& piece : p.pieces) {
                                       for (int k = 0; k < 4; ++k) {
                                           for (std::size_t i = 0; i < 5; ++i) {
                                               const double u = (k + 0.5 + 0.5 * x[i]) / 4.0;
                                               total += w[i] * length(piece.tangent(u)) / 8.0;
                                           }
                                       }
                                   }
                                   return total;
                               }},
                      curve);
}

std::vector<Vec2> polyline(const PlaneCurve& curve, double deviation_mm, std::size_t max_points) {
    std::vector<Vec2> out;
    const double end = parameter_end(curve);
    if (std::holds_alternative<Segment>(curve)) return {point_at(curve, 0), point_at(curve, 1)};
    std::size_t steps = 1;
    if (const auto* arc = std::get_if<ArcCurve>(&curve)) {
        // Sagitta r(1 - cos(θ/2)) <= deviation.
        const double ratio = std::clamp(1.0 - deviation_mm / std::max(arc->radius_mm, 1e-12), -1.0, 1.0);
        const double step_deg = std::max(2.0 * std::acos(ratio) / deg, 1e-6);
        steps = static_cast<std::size_t>(std::ceil(std::abs(arc->sweep_deg) / step_deg));
    } else {
        // Chord error of a piece split into k parts <= max|p''|·(1/k)²/8.
        const auto& path = std::get<CubicPath>(curve);
        double worst = 0;
        for (const CubicPiece& p : path.pieces) worst = std::max({worst, length(p.second(0)), length(p.second(1))});
        const double per_piece = std::ceil(std::sqrt(worst / (8.0 * std::max(deviation_mm, 1e-9))));
        steps = static_cast<std::size_t>(std::max(1.0, per_piece)) * path.pieces.size();
    }
    steps = std::clamp<std::size_t>(steps, 1, max_points - 1);
    out.reserve(steps + 1);
    for (std::size_t i = 0; i <= steps; ++i)
        out.push_back(point_at(curve, end * static_cast<double>(i) / static_cast<double>(steps)));
    return out;
}

Box bounding_box(const CubicPiece& p) {
    // Bézier control points of the power-basis cubic: their hull holds the piece.
    Box box;
    box.add(p.c[0]);
    box.add(p.c[0] + (1.0 / 3.0) * p.c[1]);
    box.add(p.c[0] + (2.0 / 3.0) * p.c[1] + (1.0 / 3.0) * p.c[2]);
    box.add(p.point(1.0));
    return box;
}

Box bounding_box(const PlaneCurve& curve) {
    Box box;
    std::visit(Overload{[&](const Segment& l) {
                            box.add(l.from);
                            box.add(l.to);
                        },
                        [&](const ArcCurve& a) {
                            box.add(point_at(curve, 0));
                            box.add(point_at(curve, std::abs(a.sweep_deg)));
                            const double lo = std::min(a.start_deg, a.start_deg + a.sweep_deg);
                            const double hi = std::max(a.start_deg, a.start_deg + a.sweep_deg);
                            for (double q = std::ceil(lo / 90.0) * 90.0; q <= hi && q - lo <= 720; q += 90.0) {
                                box.add(a.center + a.radius_mm * Vec2{std::cos(q * deg), std::sin(q * deg)});
                            }
                        },
                        [&](const CubicPath& p) {
                            for (const CubicPiece& piece : p.pieces) {
                                const Box b = bounding_box(piece);
                                box.add(b.low);
                                box.add(b.high);
                            }
                        }},
               curve);
    return box;
}

CubicPiece transformed(const CubicPiece& piece, const Affine& map) {
    return CubicPiece{{map.apply(piece.c[0]), map.linear(piece.c[1]), map.linear(piece.c[2]), map.linear(piece.c[3])}};
}

PlaneCurve transformed(const PlaneCurve& curve, const Affine& map) {
    return std::visit(Overload{[&](const Segment& l) -> PlaneCurve {
                                   return Segment{map.apply(l.from), map.apply(l.to)};
                               },
                               [&](const ArcCurve& a) -> PlaneCurve {
                                   const Vec2 s = map.apply(point_at(curve, 0)) - map.apply(a.center);
                                   const double det = map.determinant();
                                   const double scale = std::sqrt(std::abs(det));
                                   return ArcCurve{map.apply(a.center), a.radius_mm * scale, std::atan2(s.y, s.x) / deg,
                                                   det < 0 ? -a.sweep_deg : a.sweep_deg};
                               },
                               [&](const CubicPath& p) -> PlaneCurve {
                                   CubicPath out;
                                   out.pieces.reserve(p.pieces.size());
                                   for (const CubicPiece& piece : p.pieces)
                                       out.pieces.push_back(transformed(piece, map));
                                   return out;
                               }},
                      curve);
}

}  // namespace nckit::pattern
