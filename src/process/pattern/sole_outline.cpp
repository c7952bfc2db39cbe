// Reading, fitting and offsetting the sole outline.
#include "nckit/process/pattern/sole_outline.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <fstream>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "nckit/process/pattern/dxf_drawing.hpp"
#include "nckit/process/pattern/spline_fit.hpp"

namespace nckit::pattern {

namespace {

constexpr std::size_t max_outline_points = 100000;

std::string_view trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

bool parse_number(std::string_view text, double& out) {
    text = trim(text);
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
    return ec == std::errc() && end == text.data() + text.size() && std::isfinite(out);
}

double signed_area(const std::vector<Vec2>& p) {
    double a = 0;
    for (std::size_t i = 0; i < p.size(); ++i) a += cross(p[i], p[(i + 1) % p.size()]);
    return 0.5 * a;
}

std::vector<Vec2> sample(const CubicPath& path, int per_piece) {
    std::vector<Vec2> out;
    for (const CubicPiece& piece : path.pieces) {
        for (int k = 0; k < per_piece; ++k) out.push_back(piece.point(static_cast<double>(k) / per_piece));
    }
    return out;
}

}  // namespace

Result<OutlinePoints> load_outline_csv(const std::filesystem::path& path) {
    auto file = std::make_shared<const std::string>(path.string());
    std::ifstream in(path);
    if (!in) return error_at(SourceLocation{file, 0, 0}, "config-io", "cannot read the outline file");
    OutlinePoints out;
    std::string line;
    std::uint32_t number = 0;
    bool header = false;
    while (std::getline(in, line)) {
        ++number;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        const std::string_view text = trim(line);
        if (text.empty() || text.front() == '#') continue;
        if (!header) {
            std::string compact;
            for (char c : text) {
                if (!std::isspace(static_cast<unsigned char>(c))) compact += c;
            }
            if (compact != "x_mm,y_mm") {
                return error_at(SourceLocation{file, number, 1}, "outline-csv",
                                "the outline's header must be 'x_mm,y_mm'");
            }
            header = true;
            continue;
        }
        const std::size_t comma = line.find(',');
        Vec2 p;
        if (comma == std::string::npos) {
            return error_at(SourceLocation{file, number, 1}, "outline-csv", "expected 'x_mm,y_mm' (two numbers)");
        }
        if (!parse_number(std::string_view(line).substr(0, comma), p.x)) {
            return error_at(SourceLocation{file, number, 1}, "outline-csv", "x_mm is not a number");
        }
        if (!parse_number(std::string_view(line).substr(comma + 1), p.y)) {
            return error_at(SourceLocation{file, number, static_cast<std::uint32_t>(comma + 2)}, "outline-csv",
                            "y_mm is not a number");
        }
        if (out.points.size() >= max_outline_points) {
            return error_at(SourceLocation{file, number, 1}, "outline-csv",
                            fmt::format("more than {} outline points", max_outline_points));
        }
        out.points.push_back(p);
        out.where.push_back(SourceLocation{file, number, 1});
    }
    if (!header)
        return error_at(SourceLocation{file, 1, 1}, "outline-csv", "the outline file is empty (no 'x_mm,y_mm' header)");
    return out;
}

Result<OutlinePoints> load_outline_dxf(const std::filesystem::path& path) {
    Result<DxfDrawing> drawing = load_dxf_drawing(path);
    if (!drawing) return drawing.diagnostics();
    auto file = std::make_shared<const std::string>(path.string());
    for (const DxfChain& chain : drawing->chains) {
        if (!chain.closed || chain.points.size() < 4) continue;
        OutlinePoints out;
        out.points = chain.points;
        out.where.assign(chain.points.size(), SourceLocation{file, 1, 1});
        return out;
    }
    return error_at(SourceLocation{file, 1, 1}, "outline-dxf",
                    "the drawing has no closed POLYLINE, LWPOLYLINE or SPLINE of 4 points or more");
}

Result<OutlinePoints> load_outline_points(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext == ".dxf" ? load_outline_dxf(path) : load_outline_csv(path);
}

bool polygon_crosses_itself(const std::vector<Vec2>& polygon, Vec2& at) {
    const std::size_t n = polygon.size();
    struct Edge {
        double xmin, xmax;
        std::size_t i;
    };
    std::vector<Edge> edges;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2 a = polygon[i], b = polygon[(i + 1) % n];
        edges.push_back({std::min(a.x, b.x), std::max(a.x, b.x), i});
    }
    std::sort(edges.begin(), edges.end(), [](const Edge& l, const Edge& r) { return l.xmin < r.xmin; });
    for (std::size_t k = 0; k < edges.size(); ++k) {
        const std::size_t i = edges[k].i;
        const Vec2 a = polygon[i], b = polygon[(i + 1) % n];
        for (std::size_t m = k + 1; m < edges.size() && edges[m].xmin <= edges[k].xmax; ++m) {
            const std::size_t j = edges[m].i;
            if (j == i || (j + 1) % n == i || (i + 1) % n == j) continue;  // neighbours share a point
            const Vec2 c = polygon[j], d = polygon[(j + 1) % n];
            const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
            const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
            if (((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 && d4 != 0) {
                at = a + (d3 / (d3 - d4)) * (b - a);
                return true;
            }
        }
    }
    return false;
}

Result<SoleOutline> fit_sole_outline(const OutlinePoints& input, double smoothing_tolerance_mm) {
    OutlinePoints pts;
    for (std::size_t i = 0; i < input.points.size(); ++i) {
        // A repeated point (or the first repeated at the end) would give a piece of no length.
        if (!pts.points.empty() && length(input.points[i] - pts.points.back()) < 1e-9) continue;
        pts.points.push_back(input.points[i]);
        pts.where.push_back(input.where[i]);
    }
    while (pts.points.size() > 1 && length(pts.points.back() - pts.points.front()) < 1e-9) {
        pts.points.pop_back();
        pts.where.pop_back();
    }
    if (pts.points.size() < 4) {
        const SourceLocation at = input.where.empty() ? SourceLocation{} : input.where.back();
        return error_at(at, "outline",
                        fmt::format("an outline needs at least 4 distinct points, not {}", pts.points.size()));
    }
    auto nearest_point = [&](Vec2 q) {
        std::size_t best = 0;
        for (std::size_t i = 1; i < pts.points.size(); ++i) {
            if (length(pts.points[i] - q) < length(pts.points[best] - q)) best = i;
        }
        return pts.where[best];
    };
    Vec2 at;
    if (polygon_crosses_itself(pts.points, at)) {
        return error_at(nearest_point(at), "outline-crosses",
                        fmt::format("the outline crosses itself near ({:.3f}, {:.3f}) mm", at.x, at.y));
    }
    if (signed_area(pts.points) < 0) {
        std::reverse(pts.points.begin(), pts.points.end());
        std::reverse(pts.where.begin(), pts.where.end());
    }
    const ClosedSpline spline = fit_closed_spline(pts.points, smoothing_tolerance_mm);
    if (polygon_crosses_itself(sample(spline.path, 8), at)) {
        return error_at(nearest_point(at), "outline-crosses",
                        fmt::format("the outline's spline crosses itself near ({:.3f}, {:.3f}) mm (points too "
                                    "close for their turn: digitise more densely there)",
                                    at.x, at.y));
    }
    SoleOutline out{spline.path, spline.max_fit_error_mm, spline.control_points, bounding_box(PlaneCurve(spline.path))};
    return out;
}

Result<Border> inner_border(const SoleOutline& outline, double width_mm, const SourceLocation& where) {
    constexpr int per_piece = 16;
    auto offset_at = [&](const CubicPiece& piece, double u) {
        const Vec2 t = piece.tangent(u);
        const double len = length(t);
        // Counter-clockwise: the inside is on the left of the tangent.
        return piece.point(u) + (width_mm / len) * Vec2{-t.y, t.x};
    };
    std::vector<Vec2> points;
    for (const CubicPiece& piece : outline.curve.pieces) {
        for (int k = 0; k < per_piece; ++k) points.push_back(offset_at(piece, static_cast<double>(k) / per_piece));
    }
    Vec2 at;
    if (width_mm > 0 && polygon_crosses_itself(points, at)) {
        return error_at(where, "border-width",
                        fmt::format("a border {} mm wide folds over near ({:.3f}, {:.3f}) mm: the outline turns "
                                    "tighter than that there",
                                    width_mm, at.x, at.y));
    }
    // The offset must also stay a curve of the same sense: a fold inside one sample step.
    double area = 0;
    for (std::size_t i = 0; i < points.size(); ++i) area += cross(points[i], points[(i + 1) % points.size()]);
    if (area <= 0)
        return error_at(where, "border-width",
                        fmt::format("a border {} mm wide leaves nothing inside the outline", width_mm));
    Border border{fit_closed_spline(points, 0).path, 0};
    // Measure the fit against the exact offset halfway between samples.
    for (std::size_t i = 0; i < border.curve.pieces.size(); ++i) {
        const std::size_t piece = i / per_piece;
        const double u = (static_cast<double>(i % per_piece) + 0.5) / per_piece;
        const Vec2 exact = offset_at(outline.curve.pieces[piece], u);
        border.offset_error_mm = std::max(border.offset_error_mm, nearest_on_path(border.curve, exact).distance_mm);
    }
    return border;
}

}  // namespace nckit::pattern
