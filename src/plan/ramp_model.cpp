#include "ramp_model.hpp"

#include <algorithm>
#include <cmath>

namespace nckit::plan_detail {

namespace {

void add_knot(RampModel& m, double x, double c, double a, double b) {
    m.x[static_cast<std::size_t>(m.knots)] = x;
    m.f[static_cast<std::size_t>(m.knots)] = {c, a, b};
    ++m.knots;
}

void note_span(RampSolution& s, const Offset& start, double h, double fa, double fb, double k) {
    for (int q = 1; q <= 8; ++q) {
        const double u = h * q / 8;
        const double y = start.y + start.slope * u + fa * u * u / 2 + (fb - fa) * u * u * u / (6 * h);
        s.max_y = std::max(s.max_y, std::abs(y));
    }
    s.peak_curvature = std::max({s.peak_curvature, std::abs(k + fa), std::abs(k + fb)});
    if (h > 0) s.peak_rate = std::max(s.peak_rate, std::abs(fb - fa) / h);
}

//! With `stats`, also the largest |y|, |κ| and |dκ/dx| (the 2×2 system needs only the end).
RampSolution integrate(const RampModel& m, double da, double db, bool stats) {
    RampSolution s;
    auto df = [&](int i) {
        const auto& c = m.f[static_cast<std::size_t>(i)];
        return c[0] + c[1] * da + c[2] * db;
    };
    Offset o;
    s.at[0] = o;
    for (int i = 0; i + 1 < m.knots; ++i) {
        const double fa = df(i);
        const double fb = df(i + 1);
        if (i == m.ramp) {
            // The curve's curvature runs linearly from ka + da to kb + db; the path's steps at 0.
            const double mid = 0.5 * (m.ka + da + m.kb + db);
            Offset start = o;
            advance(o, m.w, fa, mid - m.ka);
            if (stats) note_span(s, start, m.w, fa, mid - m.ka, m.ka);
            o.slope -= m.kink;
            start = o;
            advance(o, m.w, mid - m.kb, fb);
            if (stats) note_span(s, start, m.w, mid - m.kb, fb, m.kb);
            s.peak_rate = std::max(s.peak_rate, std::abs(m.kb + db - m.ka - da) / (2 * m.w));
        } else {
            const double h = m.x[static_cast<std::size_t>(i + 1)] - m.x[static_cast<std::size_t>(i)];
            const Offset start = o;
            advance(o, h, fa, fb);
            if (stats) note_span(s, start, h, fa, fb, i < m.ramp ? m.ka : m.kb);
        }
        s.at[static_cast<std::size_t>(i + 1)] = o;
    }
    return s;
}

}  // namespace

void set_knots(RampModel& m) {
    m.knots = 0;
    add_knot(m, -m.ta, 0, 0, 0);
    const double plateau_a = m.ta - m.w - m.ease_a;
    add_knot(m, -m.ta + m.ease_a, 0, 1, 0);
    if (plateau_a > 1e-9) {
        for (int k = 1; k <= m.plateau_a; ++k) add_knot(m, -m.ta + m.ease_a + plateau_a * k / m.plateau_a, 0, 1, 0);
    }
    m.ramp = m.knots - 1;
    add_knot(m, m.w, 0, 0, 1);
    const double plateau_b = m.tb - m.w - m.ease_b;
    if (plateau_b > 1e-9) {
        for (int k = 1; k <= m.plateau_b; ++k) add_knot(m, m.w + plateau_b * k / m.plateau_b, 0, 0, 1);
    }
    add_knot(m, m.tb, 0, 0, 0);
}

void advance(Offset& o, double h, double fa, double fb) {
    o.y += o.slope * h + h * h * (fa / 3 + fb / 6);
    o.slope += h * (fa + fb) / 2;
    o.dk = fb;
}

bool solve(const RampModel& m, RampSolution& out, double& da, double& db) {
    const RampSolution s0 = integrate(m, 0, 0, false);
    const RampSolution s1 = integrate(m, 1, 0, false);
    const RampSolution s2 = integrate(m, 0, 1, false);
    const auto end = static_cast<std::size_t>(m.knots - 1);
    const double y0 = s0.at[end].y, p0 = s0.at[end].slope;
    const double ya = s1.at[end].y - y0, pa = s1.at[end].slope - p0;
    const double yb = s2.at[end].y - y0, pb = s2.at[end].slope - p0;
    const double det = ya * pb - yb * pa;
    if (!(std::abs(det) > 1e-300)) return false;
    da = (-y0 * pb + yb * p0) / det;
    db = (-ya * p0 + y0 * pa) / det;
    out = integrate(m, da, db, true);
    return std::isfinite(da) && std::isfinite(db);
}

double offset_length(const Offset& start, double h, double fa, double fb, double k) {
    constexpr int steps = 8;
    auto speed = [&](double u) {
        const double y = start.y + start.slope * u + fa * u * u / 2 + (fb - fa) * u * u * u / (6 * h);
        const double slope = start.slope + fa * u + (fb - fa) * u * u / (2 * h);
        return std::sqrt((1 - k * y) * (1 - k * y) + slope * slope);
    };
    const double step = h / steps;
    double sum = speed(0) + speed(h);
    for (int q = 1; q < steps; ++q) sum += (q % 2 == 1 ? 4 : 2) * speed(step * q);
    return sum * step / 3;
}

}  // namespace nckit::plan_detail
