// Writing the pattern program.
#include "nckit/process/pattern/pattern_program.hpp"

#include <cmath>

#include <fmt/format.h>

#include "nckit/core/format_fixed.hpp"

namespace nckit::pattern {

namespace {

double grid(double v, double spu) {
    return spu > 0 ? std::round(v * spu) / spu : v;
}

std::string f4(double v) {
    std::string s;
    append_fixed4(s, std::abs(v) < 5e-5 ? 0.0 : v);
    return s;
}

PlaneCurve snap_start(const PlaneCurve& curve, Vec2 start) {
    if (const auto* line = std::get_if<Segment>(&curve)) return Segment{start, line->to};
    if (const auto* arc = std::get_if<ArcCurve>(&curve)) {
        const Vec2 end = point_at(curve, std::abs(arc->sweep_deg));
        Vec2 centre = arc->center;
        if (std::abs(arc->sweep_deg) < 359.999) {
            // The point of the bisector of start–end nearest the old centre.
            const Vec2 mid = 0.5 * (start + end);
            const Vec2 chord = end - start;
            const double len = length(chord);
            if (len > 1e-9) {
                const Vec2 n{-chord.y / len, chord.x / len};
                centre = mid + dot(arc->center - mid, n) * n;
            }
        }
        const Vec2 r = start - centre;
        return ArcCurve{centre, length(r), std::atan2(r.y, r.x) * 180.0 / 3.14159265358979323846, arc->sweep_deg};
    }
    CubicPath path = std::get<CubicPath>(curve);
    // Shift the first piece's start; its end (the second piece's start) stays.
    CubicPiece& p = path.pieces.front();
    const Vec2 shift = start - p.c[0];
    p.c[0] = start;
    p.c[1] = p.c[1] - shift;
    return path;
}

}  // namespace

std::vector<ProgramCut> program_cuts(const SoleLayout& layout, const Tour& tour, const MachineConfig& machine) {
    double spu_x = 0, spu_y = 0;
    if (const AxisConfig* x = machine.find(Axis::X)) spu_x = x->steps_per_unit;
    if (const AxisConfig* y = machine.find(Axis::Y)) spu_y = y->steps_per_unit;
    std::vector<ProgramCut> out;
    for (std::size_t p = 0; p < tour.order.size(); ++p) {
        const Cut& cut = layout.cuts[tour.order[p]];
        PlaneCurve curve = tour.flipped[p] ? reversed(cut.curve) : cut.curve;
        const Vec2 start = point_at(curve, 0);
        out.push_back(ProgramCut{snap_start(curve, {grid(start.x, spu_x), grid(start.y, spu_y)}), cut.depth_mm});
    }
    return out;
}

std::string pattern_program(const std::vector<ProgramCut>& cuts, const PatternJob& job, const std::string& title) {
    std::string out;
    out += fmt::format("({})\n", title);
    out += "(absolute mm from the reference hole X0 Y0, plate surface Z0, grooves below it)\n";
    out += "G21 G17 G90 G94 G40 G49 G80 G61\n";
    if (job.spindle_rpm > 0) out += fmt::format("S{} M3\n", job.spindle_rpm);
    const std::string clear = f4(job.clearance_mm);
    const std::string approach = f4(job.approach_mm);
    const std::string feed = fmt::format("{}", job.feed_mm_min);
    const std::string plunge = fmt::format("{}", job.plunge_feed_mm_min);
    out += "G0 Z" + clear + "\n";
    std::size_t number = 0;
    for (const ProgramCut& cut : cuts) {
        ++number;
        const Vec2 s = point_at(cut.curve, 0);
        out += fmt::format("(groove {} of {})\n", number, cuts.size());
        out += "G0 X" + f4(s.x) + " Y" + f4(s.y) + "\n";
        out += "G0 Z" + approach + "\n";
        out += "G1 Z" + f4(-cut.depth_mm) + " F" + plunge + "\n";
        if (const auto* line = std::get_if<Segment>(&cut.curve)) {
            out += "G1 X" + f4(line->to.x) + " Y" + f4(line->to.y) + " F" + feed + "\n";
        } else if (const auto* arc = std::get_if<ArcCurve>(&cut.curve)) {
            const Vec2 e = point_at(cut.curve, std::abs(arc->sweep_deg));
            const Vec2 ij = arc->center - s;
            const bool full = std::abs(arc->sweep_deg) >= 359.999;
            out += fmt::format("{} X{} Y{} I{} J{} F{}\n", arc->sweep_deg < 0 ? "G2" : "G3", f4(full ? s.x : e.x),
                               f4(full ? s.y : e.y), f4(ij.x), f4(ij.y), feed);
        } else {
            const std::vector<Vec2> points = polyline(cut.curve, spline_chord_tolerance_mm);
            for (std::size_t i = 1; i < points.size(); ++i) {
                std::string mode;
                if (points.size() > 2 && i == 1) mode = fmt::format("G64 P{} ", spline_chord_tolerance_mm);
                if (points.size() > 2 && i + 1 == points.size()) mode = "G61 ";
                out += mode + "G1 X" + f4(points[i].x) + " Y" + f4(points[i].y) + (i == 1 ? " F" + feed : "") + "\n";
            }
        }
        out += "G0 Z" + clear + "\n";
    }
    out += "G0 X0.0000 Y0.0000\n";
    if (job.spindle_rpm > 0) out += "M5\n";
    out += "M2\n";
    return out;
}

}  // namespace nckit::pattern
