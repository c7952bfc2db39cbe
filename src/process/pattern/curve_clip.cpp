// Crossings of motif curves with the border and the clip that keeps the inside parts.
#include "nckit/process/pattern/curve_clip.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "nckit/process/pattern/spline_fit.hpp"

namespace nckit::pattern {

namespace {

constexpr double pi = 3.14159265358979323846;

// Roots of f on [0, 1] where f changes sign between grid points (or is zero at one), each solved
// by safeguarded Newton (bisection when a step would leave the bracket) to machine precision.
std::vector<double> roots_in_unit(const std::function<double(double)>& f, const std::function<double(double)>& df,
                                  int grid) {
    std::vector<double> roots;
    double u0 = 0, f0 = f(0);
    if (f0 == 0) roots.push_back(0);
    for (int k = 1; k <= grid; ++k) {
        const double u1 = static_cast<double>(k) / grid;
        const double f1 = f(u1);
        if (f1 == 0) {
            roots.push_back(u1);
        } else if (f0 != 0 && (f0 < 0) != (f1 < 0)) {
            double lo = u0, hi = u1, flo = f0;
            double u = 0.5 * (lo + hi);
            for (int it = 0; it < 200 && hi - lo > 1e-16; ++it) {
                const double fu = f(u);
                if (fu == 0) break;
                if ((fu < 0) == (flo < 0)) {
                    lo = u;
                    flo = fu;
                } else {
                    hi = u;
                }
                const double d = df(u);
                double next = d != 0 ? u - fu / d : 0.5 * (lo + hi);
                if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
                if (std::abs(next - u) < 1e-17) break;
                u = next;
            }
            roots.push_back(u);
        }
        u0 = u1;
        f0 = f1;
    }
    return roots;
}

// Newton on M(s) − B(u) = 0 from (s, u); false when it does not converge inside the pieces.
bool polish(const CubicPiece& m, const CubicPiece& b, double& s, double& u) {
    for (int it = 0; it < 50; ++it) {
        const Vec2 r = m.point(s) - b.point(u);
        if (length(r) < 1e-13) return s >= -1e-12 && s <= 1 + 1e-12 && u >= -1e-12 && u <= 1 + 1e-12;
        const Vec2 ms = m.tangent(s);
        const Vec2 bu = -1.0 * b.tangent(u);
        const double det = cross(ms, bu);
        if (std::abs(det) < 1e-300) return false;
        // [ms bu]·[ds du]ᵀ = −r
        const double ds = -cross(r, bu) / det;
        const double du = -cross(ms, r) / det;
        s += ds;
        u += du;
        if (s < -0.5 || s > 1.5 || u < -0.5 || u > 1.5) return false;
    }
    return length(m.point(s) - b.point(u)) < 1e-9 && s >= -1e-12 && s <= 1 + 1e-12 && u >= -1e-12 && u <= 1 + 1e-12;
}

}  // namespace

ClipBorder::ClipBorder(CubicPath border) : path_(std::move(border)) {
    constexpr int per_piece = 16;
    for (const CubicPiece& piece : path_.pieces) {
        Box b = bounding_box(piece);
        piece_boxes_.push_back(b);
        box_.add(b.low);
        box_.add(b.high);
        double curvature_bound = std::max(length(piece.second(0)), length(piece.second(1)));
        polygon_error_mm_ = std::max(polygon_error_mm_, curvature_bound / (8.0 * per_piece * per_piece));
        for (int k = 0; k < per_piece; ++k) polygon_.push_back(piece.point(static_cast<double>(k) / per_piece));
    }
}

bool ClipBorder::contains(Vec2 p) const {
    if (p.x < box_.low.x || p.x > box_.high.x || p.y < box_.low.y || p.y > box_.high.y) return false;
    // Near the border the polygon's chords may put p on the wrong side: ask the curve itself.
    const NearestPoint nearest = nearest_on_path(path_, p);
    if (nearest.distance_mm < 4 * polygon_error_mm_ + 1e-6) {
        const auto n = static_cast<double>(path_.pieces.size());
        const auto i = static_cast<std::size_t>(std::min(std::floor(nearest.s), n - 1));
        const double u = nearest.s - static_cast<double>(i);
        return cross(path_.pieces[i].tangent(u), p - path_.pieces[i].point(u)) > 0;
    }
    int winding = 0;
    for (std::size_t i = 0; i < polygon_.size(); ++i) {
        const Vec2 a = polygon_[i];
        const Vec2 b = polygon_[(i + 1) % polygon_.size()];
        if (a.y <= p.y) {
            if (b.y > p.y && cross(b - a, p - a) > 0) ++winding;
        } else if (b.y <= p.y && cross(b - a, p - a) < 0) {
            --winding;
        }
    }
    return winding != 0;
}

std::vector<double> ClipBorder::crossings(const PlaneCurve& curve) const {
    std::vector<double> out;
    const Box cbox = bounding_box(curve);
    if (!cbox.overlaps(box_, 1e-9)) return out;
    if (const auto* line = std::get_if<Segment>(&curve)) {
        const Vec2 d = line->to - line->from;
        const double dd = dot(d, d);
        const Vec2 normal{-d.y, d.x};
        for (std::size_t i = 0; i < path_.pieces.size(); ++i) {
            if (!piece_boxes_[i].overlaps(cbox, 1e-9)) continue;
            const CubicPiece& b = path_.pieces[i];
            auto f = [&](double u) { return dot(normal, b.point(u) - line->from); };
            auto df = [&](double u) { return dot(normal, b.tangent(u)); };
            for (double u : roots_in_unit(f, df, 24)) {
                const double s = dot(b.point(u) - line->from, d) / dd;
                if (s >= 0 && s <= 1) out.push_back(s);
            }
        }
    } else if (const auto* arc = std::get_if<ArcCurve>(&curve)) {
        for (std::size_t i = 0; i < path_.pieces.size(); ++i) {
            if (!piece_boxes_[i].overlaps(cbox, 1e-9)) continue;
            const CubicPiece& b = path_.pieces[i];
            auto f = [&](double u) {
                const Vec2 r = b.point(u) - arc->center;
                return dot(r, r) - arc->radius_mm * arc->radius_mm;
            };
            auto df = [&](double u) { return 2.0 * dot(b.point(u) - arc->center, b.tangent(u)); };
            for (double u : roots_in_unit(f, df, 48)) {
                const Vec2 r = b.point(u) - arc->center;
                const double angle = std::atan2(r.y, r.x) * 180.0 / pi;
                double s = arc->sweep_deg >= 0 ? angle - arc->start_deg : arc->start_deg - angle;
                s = std::fmod(std::fmod(s, 360.0) + 360.0, 360.0);
                const double end = std::abs(arc->sweep_deg);
                if (s > end && 360.0 - s < 1e-9) s = 0;  // just before the start
                if (s <= end + 1e-12) out.push_back(std::min(s, end));
            }
        }
    } else {
        const auto& path = std::get<CubicPath>(curve);
        constexpr int chords_per_piece = 16;
        for (std::size_t j = 0; j < path.pieces.size(); ++j) {
            const CubicPiece& m = path.pieces[j];
            const Box mbox = bounding_box(m);
            for (std::size_t i = 0; i < path_.pieces.size(); ++i) {
                if (!piece_boxes_[i].overlaps(mbox, 1e-9)) continue;
                const CubicPiece& b = path_.pieces[i];
                for (int k = 0; k < chords_per_piece; ++k) {
                    const double s0 = static_cast<double>(k) / chords_per_piece;
                    const double s1 = static_cast<double>(k + 1) / chords_per_piece;
                    const Vec2 a = m.point(s0);
                    const Vec2 d = m.point(s1) - a;
                    const Vec2 normal{-d.y, d.x};
                    auto f = [&](double u) { return dot(normal, b.point(u) - a); };
                    auto df = [&](double u) { return dot(normal, b.tangent(u)); };
                    for (double u : roots_in_unit(f, df, 24)) {
                        const double t = dot(b.point(u) - a, d) / std::max(dot(d, d), 1e-300);
                        if (t < -0.25 || t > 1.25) continue;
                        double s = s0 + t * (s1 - s0);
                        double uu = u;
                        if (polish(m, b, s, uu)) out.push_back(static_cast<double>(j) + std::clamp(s, 0.0, 1.0));
                    }
                }
            }
        }
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end(), [](double a, double b) { return b - a < 1e-9; }), out.end());
    return out;
}

std::vector<ClippedCurve> clip_to_border(const PlaneCurve& curve, const ClipBorder& border, double min_length_mm) {
    std::vector<ClippedCurve> out;
    std::vector<double> cuts = border.crossings(curve);
    const double end = parameter_end(curve);
    std::vector<double> bounds{0.0};
    for (double s : cuts) {
        if (s > 1e-12 && s < end - 1e-12) bounds.push_back(s);
    }
    bounds.push_back(end);
    auto is_crossing = [&](double s) {
        return std::any_of(cuts.begin(), cuts.end(), [&](double c) { return std::abs(c - s) < 1e-9; });
    };
    for (std::size_t k = 0; k + 1 < bounds.size(); ++k) {
        const double s0 = bounds[k], s1 = bounds[k + 1];
        if (!border.contains(point_at(curve, 0.5 * (s0 + s1)))) continue;
        ClippedCurve piece{sub_curve(curve, s0, s1), is_crossing(s0), is_crossing(s1)};
        if (curve_length(piece.curve) < min_length_mm) continue;
        out.push_back(std::move(piece));
    }
    return out;
}

}  // namespace nckit::pattern
