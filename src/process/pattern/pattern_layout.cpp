// Grading, tiling and clipping of one sole.
#include "nckit/process/pattern/pattern_layout.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "nckit/process/pattern/curve_clip.hpp"

namespace nckit::pattern {

namespace {

constexpr double deg = 3.14159265358979323846 / 180.0;
constexpr double max_lattice_places = 200000;

double depth_at(const PatternJob& job, const Box& outline_box, Vec2 p) {
    const double length = outline_box.size().x;
    const double pct = length > 0 ? 100.0 * (p.x - outline_box.low.x) / length : 0.0;
    for (const DepthRegion& r : job.regions) {
        if (pct >= r.from_pct && pct <= r.to_pct) return r.depth_mm;
    }
    return job.depth_mm;
}

// Parameters where the curve crosses one of the lines x = X (region boundaries): sign changes
// on 64 steps, each solved by bisection on the exact curve.
std::vector<double> crossings_of_lines(const PlaneCurve& curve, const std::vector<double>& xs) {
    std::vector<double> out;
    const double end = parameter_end(curve);
    constexpr int steps = 64;
    for (double x : xs) {
        auto f = [&](double s) { return point_at(curve, s).x - x; };
        double s0 = 0, f0 = f(0);
        for (int k = 1; k <= steps; ++k) {
            const double s1 = end * k / steps;
            const double f1 = f(s1);
            if ((f0 < 0) != (f1 < 0) && f0 != 0 && f1 != 0) {
                double lo = s0, hi = s1;
                for (int it = 0; it < 200 && hi - lo > 1e-15 * std::max(1.0, end); ++it) {
                    const double mid = 0.5 * (lo + hi);
                    if ((f(mid) < 0) == (f0 < 0)) {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                out.push_back(0.5 * (lo + hi));
            }
            s0 = s1;
            f0 = f1;
        }
    }
    std::sort(out.begin(), out.end());
    return out;
}

// A clipped piece split where it crosses a region boundary (no part shorter than min_mm), each
// part at the depth of its own region.
void add_cuts(const ClippedCurve& piece, const PatternJob& job, const Box& outline_box, double min_mm,
              const Affine& to_program, std::vector<Cut>& out) {
    std::vector<double> lines;
    for (const DepthRegion& r : job.regions) {
        for (double pct : {r.from_pct, r.to_pct})
            lines.push_back(outline_box.low.x + pct / 100.0 * outline_box.size().x);
    }
    const double end = parameter_end(piece.curve);
    std::vector<double> bounds{0.0};
    for (double s : crossings_of_lines(piece.curve, lines)) {
        if (curve_length(sub_curve(piece.curve, bounds.back(), s)) >= min_mm &&
            curve_length(sub_curve(piece.curve, s, end)) >= min_mm) {
            bounds.push_back(s);
        }
    }
    bounds.push_back(end);
    for (std::size_t k = 0; k + 1 < bounds.size(); ++k) {
        const PlaneCurve part = bounds.size() == 2 ? piece.curve : sub_curve(piece.curve, bounds[k], bounds[k + 1]);
        const Vec2 mid = point_at(part, 0.5 * parameter_end(part));
        out.push_back(Cut{transformed(part, to_program), depth_at(job, outline_box, mid),
                          k == 0 && piece.start_on_border, k + 2 == bounds.size() && piece.end_on_border});
    }
}

}  // namespace

Result<Grading> grading_for(const PatternJob& job, std::optional<double> size, bool mirror) {
    Grading g;
    g.mirror = mirror;
    if (!size) {
        g.size = job.base_size;
        return g;
    }
    g.size = *size;
    if (*size == job.base_size && !job.sizes.empty()) return g;  // the outline as digitised
    for (const SeriesSize& s : job.sizes) {
        if (s.size != *size) continue;
        if (s.scale) {
            g.scale_x = g.scale_y = *s.scale;
        } else {
            g.scale_x = std::nan("");  // filled from the outline's box in lay_out_sole
            g.scale_y = std::nan("");
        }
        return g;
    }
    SourceLocation at = job.series_at;
    if (!at.file) at = SourceLocation{job.file, 1, 1};
    return error_at(at, "series-size",
                    job.sizes.empty() ? fmt::format("the job has no [series]; --size {} cannot be made", *size)
                                      : fmt::format("size {} is not in the series", *size));
}

Result<SoleLayout> lay_out_sole(const PatternJob& job, const OutlinePoints& points, const Grading& wanted) {
    Result<SoleOutline> base = fit_sole_outline(points, job.smoothing_tolerance_mm);
    if (!base) return base.diagnostics();
    SoleLayout layout;
    layout.grading = wanted;
    layout.fit_error_mm = base->fit_error_mm;
    layout.control_points = base->control_points;
    const Box base_box = base->box;
    const Vec2 c = base_box.centre();
    Grading& g = layout.grading;
    if (std::isnan(g.scale_x)) {
        for (const SeriesSize& s : job.sizes) {
            if (s.size != g.size) continue;
            g.scale_x = (base_box.size().x + s.length_mm) / base_box.size().x;
            g.scale_y = (base_box.size().y + s.width_mm) / base_box.size().y;
            if (g.scale_x <= 0.1 || g.scale_y <= 0.1) {
                return error_at(s.where, "series-size",
                                fmt::format("size {} shrinks the outline to {:.4g} x {:.4g} of the base", s.size,
                                            g.scale_x, g.scale_y));
            }
        }
    }
    // Sole frame → graded (and mirrored) sole frame. A mirror turns the outline clockwise, so
    // it is traversed backwards to stay counter-clockwise.
    const double my = g.mirror ? -1.0 : 1.0;
    const Affine grade{{g.scale_x, 0, 0, my * g.scale_y}, {c.x - g.scale_x * c.x, c.y - my * g.scale_y * c.y}};
    CubicPath outline = std::get<CubicPath>(transformed(PlaneCurve(base->curve), grade));
    if (g.mirror) outline = std::get<CubicPath>(reversed(PlaneCurve(outline)));
    SoleOutline graded{outline, base->fit_error_mm, base->control_points, bounding_box(PlaneCurve(outline))};
    Result<Border> border = inner_border(graded, job.border_width_mm, job.border_at);
    if (!border) return border.diagnostics();
    layout.border_offset_error_mm = border->offset_error_mm;
    const ClipBorder clip(border->curve);

    // The motif: as drawn, or scaled by the size's mean factor (arcs stay arcs); mirrored with
    // the sole.
    const double motif_scale = job.motif_grading == MotifGrading::scale ? std::sqrt(g.scale_x * g.scale_y) : 1.0;
    const Vec2 border_size = clip.box().size();
    const Vec2 motif_size = motif_scale * job.motif_box.size();
    if (motif_size.x > border_size.x || motif_size.y > border_size.y) {
        return error_at(job.motif_at, "motif-size",
                        fmt::format("the motif ({:.3f} x {:.3f} mm) is larger than the sole inside its border "
                                    "({:.3f} x {:.3f} mm)",
                                    motif_size.x, motif_size.y, border_size.x, border_size.y));
    }
    // Lattice vectors in the base frame, then graded with the sole when motifs scale.
    const double ca = std::cos(job.lattice_angle_deg * deg), sa = std::sin(job.lattice_angle_deg * deg);
    auto rotate = [&](Vec2 v) { return Vec2{ca * v.x - sa * v.y, sa * v.x + ca * v.y}; };
    Vec2 a = rotate({job.lattice_spacing_mm.x, 0});
    Vec2 b = rotate({job.row_offset_mm, job.lattice_spacing_mm.y});
    if (job.motif_grading == MotifGrading::scale) {
        a = {g.scale_x * a.x, g.scale_y * a.y};
        b = {g.scale_x * b.x, g.scale_y * b.y};
    }
    a.y *= my;
    b.y *= my;
    const Vec2 origin = grade.apply(job.lattice_origin_mm.value_or(c));
    const Affine motif_map{{motif_scale, 0, 0, my * motif_scale}, {}};

    // Places whose motif can reach the border's box: invert the lattice basis at the corners of
    // the box grown by the motif's extent.
    const Box mb =
        bounding_box(PlaneCurve(Segment{motif_map.apply(job.motif_box.low), motif_map.apply(job.motif_box.high)}));
    const Box& bb = clip.box();
    const double det = cross(a, b);
    double i_lo = 1e300, i_hi = -1e300, j_lo = 1e300, j_hi = -1e300;
    for (Vec2 corner :
         {Vec2{bb.low.x - mb.high.x, bb.low.y - mb.high.y}, Vec2{bb.high.x - mb.low.x, bb.low.y - mb.high.y},
          Vec2{bb.low.x - mb.high.x, bb.high.y - mb.low.y}, Vec2{bb.high.x - mb.low.x, bb.high.y - mb.low.y}}) {
        const Vec2 d = corner - origin;
        const double i = cross(d, b) / det, j = cross(a, d) / det;
        i_lo = std::min(i_lo, i);
        i_hi = std::max(i_hi, i);
        j_lo = std::min(j_lo, j);
        j_hi = std::max(j_hi, j);
    }
    const double places = (std::floor(i_hi) - std::ceil(i_lo) + 1) * (std::floor(j_hi) - std::ceil(j_lo) + 1);
    if (!(places <= max_lattice_places)) {
        return error_at(job.lattice_at, "lattice-size",
                        fmt::format("the lattice puts {:.0f} motifs on the sole (at most {:.0f}): the spacing is too "
                                    "small for this outline",
                                    places, max_lattice_places));
    }
    const Affine to_program{{1, 0, 0, 1}, {-job.reference_hole_mm.x, -job.reference_hole_mm.y}};
    const Box graded_box = graded.box;
    for (auto j = static_cast<long>(std::ceil(j_lo)); j <= static_cast<long>(std::floor(j_hi)); ++j) {
        for (auto i = static_cast<long>(std::ceil(i_lo)); i <= static_cast<long>(std::floor(i_hi)); ++i) {
            const Vec2 place = origin + static_cast<double>(i) * a + static_cast<double>(j) * b;
            Affine map = motif_map;
            map.t = place;
            const Box placed{map.apply(job.motif_box.low), map.apply(job.motif_box.high)};
            Box check;
            check.add(placed.low);
            check.add(placed.high);
            if (!check.overlaps(bb, 1e-9)) continue;
            ++layout.motif_instances;
            for (const PlaneCurve& curve : job.motif) {
                for (const ClippedCurve& piece : clip_to_border(transformed(curve, map), clip, job.min_cut_mm)) {
                    add_cuts(piece, job, graded_box, job.min_cut_mm, to_program, layout.cuts);
                }
            }
        }
    }
    layout.outline = std::get<CubicPath>(transformed(PlaneCurve(outline), to_program));
    layout.border = std::get<CubicPath>(transformed(PlaneCurve(border->curve), to_program));
    return layout;
}

}  // namespace nckit::pattern
