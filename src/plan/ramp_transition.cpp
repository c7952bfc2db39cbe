#include "ramp_transition.hpp"

#include "ramp_model.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace nckit::plan_detail {

namespace {

using Vec3 = std::array<double, 3>;

constexpr double inf = std::numeric_limits<double>::infinity();
// The same margin as the single quintic's: the deviation is sampled, the target leaves room for
// what lies between the samples.
constexpr double deviation_target = 0.95;
// The model's deviation is aimed at this share of the tolerance first (it leaves out terms of
// second order in the offset, which the measurement then sees).
constexpr double model_target = 0.8;
// Largest direction step (rad) at the join taken into the model, and how far (1/mm, relative)
// the curvature vectors and the step may leave the common plane.
constexpr double max_kink_rad = 2e-3;
constexpr double plane_tolerance = 1e-6;
// Each side gives at most the length over which its arc turns this far (rad): the quintic
// pieces that follow the arc stay close to it (each turns by at most max_piece_turn_rad).
constexpr double max_side_turn_rad = 0.6;
constexpr double max_piece_turn_rad = 0.3;
constexpr int max_plateau_pieces = 4;
constexpr int max_rounds = 4;
constexpr int bisections = 30;

double dot(const Vec3& a, const Vec3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3 xyz(const AxisVector& v) {
    return {v[0], v[1], v[2]};
}
Vec3 scaled(const Vec3& a, double f) {
    return {a[0] * f, a[1] * f, a[2] * f};
}
double norm(const Vec3& a) {
    return std::sqrt(dot(a, a));
}
Vec3 unit(const Vec3& a) {
    const double n = norm(a);
    return n > 0 ? scaled(a, 1.0 / n) : Vec3{};
}

//! The speed a model allows at constant path speed with the smallest axis limits (its curvature
//! and curvature rate taken on one axis, as at a join where the normal lies along an axis).
double model_speed(const RampSolution& s, double amax, double jmax) {
    const double by_a = s.peak_curvature > 0 ? std::sqrt(amax / s.peak_curvature) : inf;
    const double by_j = s.peak_rate > 0 ? std::cbrt(turning_jerk_share * jmax / s.peak_rate) : inf;
    return std::min(by_a, by_j);
}

struct JoinPlane {
    Vec3 normal{};  // B, the plane's normal
    Vec3 n0{};      // the path's normal at the join
};

bool flat(const PathSegment& g, const Vec3& normal) {
    if (std::abs(dot(xyz(g.rate), normal)) > 1e-9) return false;
    if (g.shape == SegmentShape::line) return true;
    return std::abs(std::abs(dot(cross(g.u, g.v), normal)) - 1.0) < 1e-9;
}

//! A state of the curve at the model's x with offset o: the programmed point moved by y along
//! its normal, turned by the offset's slope, with curvature κ + Δκ + κ²·y (an offset curve's, to
//! first order).
PathPoint state_at(const PathSegment& g, double s, const Offset& o, const Vec3& normal) {
    PathPoint p = point_at(g, s);
    const Vec3 t = unit(xyz(p.d1));
    const Vec3 n = cross(normal, t);
    const double k = dot(xyz(p.d2), n);
    const Vec3 dir = unit({(1 - k * o.y) * t[0] + o.slope * n[0], (1 - k * o.y) * t[1] + o.slope * n[1],
                           (1 - k * o.y) * t[2] + o.slope * n[2]});
    const Vec3 nd = cross(normal, dir);
    const double curvature = k + o.dk + k * k * o.y;
    for (std::size_t i = 0; i < 3; ++i) {
        p.position[i] += o.y * n[i];
        p.d1[i] = dir[i];
        p.d2[i] = curvature * nd[i];
        p.d3[i] = 0;
    }
    for (std::size_t i = 3; i < axis_count; ++i) {
        p.d1[i] = 0;
        p.d2[i] = 0;
    }
    return p;
}

//! The chain of quintics for a solved model, written to out (curve, more) and measured.
bool build_chain(const PathSegment& before, const PathSegment& after, const RampModel& m, const RampSolution& s,
                 double da, double db, const Vec3& normal, double tolerance_mm, Transition& out) {
    auto state = [&](int i) {
        const double x = m.x[static_cast<std::size_t>(i)];
        if (i == 0) return out.start;
        if (i == m.knots - 1) return out.end;
        return x < 0 ? state_at(before, before.length + x, s.at[static_cast<std::size_t>(i)], normal)
                     : state_at(after, x, s.at[static_cast<std::size_t>(i)], normal);
    };
    auto df = [&](int i) {
        const auto& c = m.f[static_cast<std::size_t>(i)];
        return c[0] + c[1] * da + c[2] * db;
    };
    out.more.clear();
    PathPoint from = state(0);
    for (int i = 0; i + 1 < m.knots; ++i) {
        const PathPoint to = state(i + 1);
        const Offset& o = s.at[static_cast<std::size_t>(i)];
        double length = 0;
        if (i == m.ramp) {
            const double mid = 0.5 * (m.ka + da + m.kb + db);
            length = offset_length(o, m.w, df(i), mid - m.ka, m.ka);
            Offset half = o;
            advance(half, m.w, df(i), mid - m.ka);
            half.slope -= m.kink;
            length += offset_length(half, m.w, mid - m.kb, df(i + 1), m.kb);
        } else {
            const double h = m.x[static_cast<std::size_t>(i + 1)] - m.x[static_cast<std::size_t>(i)];
            length = offset_length(o, h, df(i), df(i + 1), i < m.ramp ? m.ka : m.kb);
        }
        PathSegment piece = make_quintic(from, to, length, AxisVector{});
        if (i == 0) {
            out.curve = piece;
        } else {
            out.more.push_back(piece);
        }
        from = to;
    }
    // Measured against the replaced path at once (it is cut into chords once).
    std::vector<PathSegment> curves{out.curve};
    curves.insert(curves.end(), out.more.begin(), out.more.end());
    const CurveDeviation d = measure_deviation(curves.data(), curves.size(), out, tolerance_mm);
    out.deviation_mm = d.deviation_mm;
    return d.slowest >= 0.3 && d.deviation_mm <= deviation_target * tolerance_mm;
}

}  // namespace

bool make_ramp_transition(const PathSegment& before, double before_room, const PathSegment& after, double after_room,
                          double tolerance_mm, const TurningLimits& limits, Transition& out) {
    if (!(tolerance_mm > 0)) return false;
    if (before.shape == SegmentShape::quintic || after.shape == SegmentShape::quintic) return false;
    if (before.shape != SegmentShape::arc && after.shape != SegmentShape::arc) return false;
    for (std::size_t i = 3; i < axis_count; ++i) {
        if (before.rate[i] != 0 || after.rate[i] != 0) return false;
    }
    const PathPoint e = point_at(before, before.length);
    const PathPoint st = point_at(after, 0.0);
    const Vec3 t = unit({e.d1[0] + st.d1[0], e.d1[1] + st.d1[1], e.d1[2] + st.d1[2]});
    const Vec3 k1 = xyz(e.d2);
    const Vec3 k2 = xyz(st.d2);
    const Vec3 k1p = {k1[0] - dot(k1, t) * t[0], k1[1] - dot(k1, t) * t[1], k1[2] - dot(k1, t) * t[2]};
    const Vec3 k2p = {k2[0] - dot(k2, t) * t[0], k2[1] - dot(k2, t) * t[1], k2[2] - dot(k2, t) * t[2]};
    JoinPlane plane;
    plane.n0 = unit(norm(k1p) >= norm(k2p) ? k1p : k2p);
    if (!(norm(plane.n0) > 0)) return false;
    plane.normal = unit(cross(t, plane.n0));
    const double scale = norm(k1) + norm(k2);
    if (std::abs(dot(k1, plane.normal)) > plane_tolerance * scale ||
        std::abs(dot(k2, plane.normal)) > plane_tolerance * scale) {
        return false;
    }
    const Vec3 d1a = unit(xyz(e.d1));
    const Vec3 d1b = unit(xyz(st.d1));
    if (std::abs(dot(d1b, plane.normal) - dot(d1a, plane.normal)) > 1e-9) return false;
    if (!flat(before, plane.normal) || !flat(after, plane.normal)) return false;
    RampModel m;
    m.ka = dot(k1, plane.n0);
    m.kb = dot(k2, plane.n0);
    m.kink = dot(cross(d1a, d1b), plane.normal);
    if (std::abs(m.kink) > max_kink_rad || !(std::abs(m.ka - m.kb) > 1e-6)) return false;

    // Trims: the room, at most the length over which the side's arc turns max_side_turn_rad (a
    // line side takes the arc side's length).
    const double ka = std::abs(m.ka);
    const double kb = std::abs(m.kb);
    const double cap_a = ka > 1e-9 ? max_side_turn_rad / ka : max_side_turn_rad / kb;
    const double cap_b = kb > 1e-9 ? max_side_turn_rad / kb : max_side_turn_rad / ka;
    before_room = std::min({before_room, before.length, cap_a});
    after_room = std::min({after_room, after.length, cap_b});
    if (before.length - before_room < min_leftover_mm) before_room = before.length;
    if (!(before_room > 1e-6 && after_room > 1e-6)) return false;
    double amax = inf;
    double jmax = inf;
    for (std::size_t i = 0; i < 3; ++i) {
        amax = std::min(amax, limits.max_acceleration[i]);
        jmax = std::min(jmax, limits.max_jerk[i]);
    }
    if (!(amax > 0 && jmax > 0)) return false;

    double target = model_target * tolerance_mm;
    for (int round = 0; round < max_rounds; ++round) {
        // The candidates: trims (a share of the room) and easing lengths; for each the widest ramp
        // whose model stays within the target, and the one whose model allows the highest speed.
        RampModel best;
        RampSolution best_solved;
        double best_da = 0;
        double best_db = 0;
        double best_speed = -1;
        for (double share : {1.0, 0.7, 0.5, 0.35}) {
            for (double ease : {0.35, 1.0}) {
                RampModel m2 = m;
                m2.ta = share * before_room;
                if (before.length - m2.ta < min_leftover_mm) m2.ta = before.length;
                m2.tb = share * after_room;
                double lo = 0.0;
                double hi = 0.95 * std::min(m2.ta, m2.tb);
                auto fits = [&](double w, RampSolution& s, double& da, double& db) {
                    m2.w = w;
                    m2.ease_a = ease * (m2.ta - w);
                    m2.ease_b = ease * (m2.tb - w);
                    m2.plateau_a =
                        std::clamp(static_cast<int>(std::ceil(ka * (m2.ta - w - m2.ease_a) / max_piece_turn_rad)), 1,
                                   max_plateau_pieces);
                    m2.plateau_b =
                        std::clamp(static_cast<int>(std::ceil(kb * (m2.tb - w - m2.ease_b) / max_piece_turn_rad)), 1,
                                   max_plateau_pieces);
                    set_knots(m2);
                    return solve(m2, s, da, db) && s.max_y <= target;
                };
                // The widest ramp that fits: lo stays 0 when none does.
                RampSolution s;
                double da = 0;
                double db = 0;
                if (fits(hi, s, da, db)) {
                    lo = hi;
                } else {
                    for (int k = 0; k < bisections; ++k) {
                        const double mid = 0.5 * (lo + hi);
                        if (fits(mid, s, da, db)) {
                            lo = mid;
                        } else {
                            hi = mid;
                        }
                    }
                }
                if (!(lo > 1e-6)) continue;
                // m2 back at the widest ramp that fits (the bisection may have left it at a wider one).
                RampSolution found;
                double fda = 0;
                double fdb = 0;
                if (!fits(lo, found, fda, fdb)) continue;
                const double speed = model_speed(found, amax, jmax);
                if (speed > best_speed) {
                    best_speed = speed;
                    best = m2;
                    best_solved = found;
                    best_da = fda;
                    best_db = fdb;
                }
            }
        }
        if (best_speed < 0) return false;
        out.trim_before = best.ta;
        out.trim_after = best.tb;
        out.replaced_before = trim_start(before, before.length - best.ta);
        out.replaced_after = after;
        out.replaced_after.length = best.tb;
        out.start = point_at(before, before.length - best.ta);
        out.end = point_at(after, best.tb);
        out.chained = false;
        if (build_chain(before, after, best, best_solved, best_da, best_db, plane.normal, tolerance_mm, out)) {
            return true;
        }
        if (!(out.deviation_mm > 0)) return false;
        target *= std::min(0.9, 0.9 * deviation_target * tolerance_mm / out.deviation_mm);
    }
    return false;
}

double turning_speed(const Transition& transition, const TurningLimits& limits) {
    double v = inf;
    auto visit = [&](const PathSegment& g) {
        if (g.shape != SegmentShape::quintic) return;
        constexpr int samples = 32;
        for (int k = 0; k <= samples; ++k) {
            const double s = g.length * k / samples;
            for (std::size_t i = 0; i < 3; ++i) {
                const double c2 = g.poly[0][i];
                const double c3 = g.poly[1][i];
                const double c4 = g.poly[2][i];
                const double c5 = g.poly[3][i];
                const double q2 = std::abs(2 * c2 + s * (6 * c3 + s * (12 * c4 + s * 20 * c5)));
                const double q3 = std::abs(6 * c3 + s * (24 * c4 + s * 60 * c5));
                if (q2 > 0) v = std::min(v, std::sqrt(limits.max_acceleration[i] / q2));
                if (q3 > 0) v = std::min(v, std::cbrt(turning_jerk_share * limits.max_jerk[i] / q3));
            }
        }
    };
    visit(transition.curve);
    for (const PathSegment& g : transition.more) visit(g);
    return v;
}

TurningLimits turning_limits(const MachineConfig& machine) {
    TurningLimits limits;
    limits.max_acceleration.fill(std::numeric_limits<double>::infinity());
    limits.max_jerk.fill(std::numeric_limits<double>::infinity());
    for (const AxisConfig& axis : machine.axes) {
        const std::size_t i = index(axis.axis);
        if (i < 3) {
            limits.max_acceleration[i] = axis.max_acceleration;
            limits.max_jerk[i] = axis.max_jerk;
        }
    }
    return limits;
}

}  // namespace nckit::plan_detail
