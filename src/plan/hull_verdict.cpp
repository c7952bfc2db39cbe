#include "hull_verdict.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace nckit::plan_detail {

double hull_verdict(const PathSegment& curve, const Transition& t, const AxisVector& a, const AxisVector& b,
                    double min_speed) {
    if (t.replaced_before.shape != SegmentShape::line || t.replaced_after.shape != SegmentShape::line) return -1;
    const AxisVector& c = t.replaced_after.origin;  // a line's start
    // A chained meeting point may lie off its line (moved onto the curve, chain_state.hpp): the
    // height is taken over the chord between the feet A', B' on the lines, and every point of
    // the chord A–B lies within the larger offset of the chord A'–B'.
    double along_a = 0;
    double along_b = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        along_a += (a[i] - c[i]) * t.replaced_before.rate[i];
        along_b += (b[i] - c[i]) * t.replaced_after.rate[i];
    }
    // The feet lie on the replaced pieces, A' before C and B' after it (up to rounding: a
    // nanometre past a piece's end, which the bound adds).
    constexpr double slack_mm = 1e-9;
    if (!(along_a <= slack_mm && -along_a <= t.replaced_before.length + slack_mm && along_b >= -slack_mm &&
          along_b <= t.replaced_after.length + slack_mm)) {
        return -1;
    }
    std::array<double, 3> ab{};
    std::array<double, 3> ac{};
    std::array<double, 3> bc{};
    double feet2 = 0;
    double off_a2 = 0;
    double off_b2 = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        const double foot_a = c[i] + along_a * t.replaced_before.rate[i];
        const double foot_b = c[i] + along_b * t.replaced_after.rate[i];
        off_a2 += (a[i] - foot_a) * (a[i] - foot_a);
        off_b2 += (b[i] - foot_b) * (b[i] - foot_b);
        ab[i] = foot_b - foot_a;
        ac[i] = c[i] - foot_a;
        bc[i] = c[i] - foot_b;
        feet2 += ab[i] * ab[i];
    }
    double dot_a = 0;
    double dot_b = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        dot_a += ac[i] * ab[i];
        dot_b -= bc[i] * ab[i];
    }
    if (!(feet2 > 0 && dot_a > 0 && dot_b > 0)) return -1;
    // Height of C over the line A'B'.
    double h2 = 0;
    const double along_c = dot_a / feet2;
    for (std::size_t i = 0; i < 3; ++i) {
        const double e = ac[i] - along_c * ab[i];
        h2 += e * e;
    }
    // From here on, the chord A–B itself.
    double ab2 = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        ab[i] = b[i] - a[i];
        ab2 += ab[i] * ab[i];
    }
    if (!(ab2 > 0)) return -1;
    // The roots are started early, so that their latency hides behind the control points.
    const double inv = 1.0 / std::sqrt(ab2);
    const double height = std::sqrt(h2);
    const double off = std::sqrt(std::max(off_a2, off_b2));
    // Bernstein coefficients of the quintic in u = s/L: b_i = sum_k C(i,k)/C(5,k) a_k.
    const double l = curve.length;
    std::array<std::array<double, 3>, 6> ctrl{};
    for (std::size_t i = 0; i < 3; ++i) {
        const double a0 = curve.origin[i];
        const double a1 = curve.rate[i] * l;
        const double a2 = curve.poly[0][i] * l * l;
        const double a3 = curve.poly[1][i] * l * l * l;
        const double a4 = curve.poly[2][i] * l * l * l * l;
        const double a5 = curve.poly[3][i] * l * l * l * l * l;
        // Six divisions where the formula has ten: scaling by a power of two is exact and
        // commutes with rounding, so 2·a1/5 = 2·(a1/5), a2/10 = (a2/5)/2, 6·a2/10 = 3·a2/5,
        // 3·a2/10 = (3·a2/5)/2, 4·a3/10 = 2·(a3/5) and a3/10 = (a3/5)/2, the same numbers
        // (outside the subnormal range, far below any coordinate).
        const double a1_5 = a1 / 5;
        const double a2_5 = a2 / 5;
        const double a2_3_5 = 3 * a2 / 5;
        const double a3_5 = a3 / 5;
        ctrl[0][i] = a0;
        ctrl[1][i] = a0 + a1_5;
        ctrl[2][i] = a0 + 2 * a1_5 + a2_5 / 2;
        ctrl[3][i] = a0 + 3 * a1 / 5 + a2_3_5 / 2 + a3_5 / 2;
        ctrl[4][i] = a0 + 4 * a1_5 + a2_3_5 + 2 * a3_5 + a4 / 5;
        ctrl[5][i] = a0 + a1 + a2 + a3 + a4 + a5;
    }
    // The velocity's control points 5 (b_{i+1} - b_i) / L along the chord's direction.
    for (std::size_t k = 0; k < 5; ++k) {
        double along = 0;
        for (std::size_t i = 0; i < 3; ++i) along += 5 * (ctrl[k + 1][i] - ctrl[k][i]) / l * ab[i] * inv;
        if (!(along >= min_speed)) return -1;
    }
    // The first and the last control point are A and B themselves (on the chord).
    double far2 = 0;
    for (std::size_t k = 1; k < 5; ++k) {
        double along = 0;
        for (std::size_t i = 0; i < 3; ++i) along += (ctrl[k][i] - a[i]) * ab[i];
        const double f = std::clamp(along / ab2, 0.0, 1.0);
        double d2 = 0;
        for (std::size_t i = 0; i < 3; ++i) {
            const double e = ctrl[k][i] - a[i] - f * ab[i];
            d2 += e * e;
        }
        far2 = std::max(far2, d2);
    }
    return std::sqrt(far2) + height + off + slack_mm;
}

}  // namespace nckit::plan_detail
