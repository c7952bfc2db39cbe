// DXF entities through dxflib's creation adapter.
#include "nckit/process/pattern/dxf_drawing.hpp"

#include <cmath>
#include <fstream>
#include <memory>

#include <dxflib/dl_creationadapter.h>
#include <dxflib/dl_dxf.h>

#include "nckit/process/pattern/spline_fit.hpp"

namespace nckit::pattern {

namespace {

constexpr double rad_to_deg = 180.0 / 3.14159265358979323846;

class Collector : public DL_CreationAdapter {
public:
    DxfDrawing drawing;

    void addBlock(const DL_BlockData&) override { in_block_ = true; }
    void endBlock() override { in_block_ = false; }

    void addLine(const DL_LineData& d) override {
        if (!in_block_) drawing.curves.emplace_back(Segment{{d.x1, d.y1}, {d.x2, d.y2}});
    }
    void addArc(const DL_ArcData& d) override {
        if (in_block_) return;
        double sweep = d.angle2 - d.angle1;
        while (sweep <= 0) sweep += 360.0;
        drawing.curves.emplace_back(ArcCurve{{d.cx, d.cy}, d.radius, d.angle1, sweep});
    }
    void addCircle(const DL_CircleData& d) override {
        if (!in_block_) drawing.curves.emplace_back(ArcCurve{{d.cx, d.cy}, d.radius, 0.0, 360.0});
    }
    void addPolyline(const DL_PolylineData& d) override {
        finish_chain();
        if (in_block_) return;
        chain_ = DxfChain{{}, (d.flags & 1) != 0};
        bulges_.clear();
        open_ = Open::polyline;
    }
    void addVertex(const DL_VertexData& d) override {
        if (open_ != Open::polyline) return;
        chain_.points.push_back({d.x, d.y});
        bulges_.push_back(d.bulge);
    }
    void addSpline(const DL_SplineData& d) override {
        finish_chain();
        if (in_block_) return;
        chain_ = DxfChain{{}, (d.flags & 1) != 0};
        control_.clear();
        open_ = Open::spline;
    }
    void addFitPoint(const DL_FitPointData& d) override {
        if (open_ == Open::spline) chain_.points.push_back({d.x, d.y});
    }
    void addControlPoint(const DL_ControlPointData& d) override {
        if (open_ == Open::spline) control_.push_back({d.x, d.y});
    }
    void endEntity() override { finish_chain(); }
    void endSequence() override { finish_chain(); }

    void finish_chain() {
        if (open_ == Open::none) return;
        if (open_ == Open::spline && chain_.points.empty()) chain_.points = control_;
        if (chain_.points.size() >= 2) {
            if (open_ == Open::polyline) {
                add_polyline_curves();
            } else {
                std::vector<Vec2> pts = chain_.points;
                if (chain_.closed) pts.push_back(pts.front());
                drawing.curves.emplace_back(fit_open_spline(pts));
            }
            drawing.chains.push_back(chain_);
        }
        open_ = Open::none;
        chain_ = {};
    }

private:
    enum class Open { none, polyline, spline };

    // A bulge b on the vertex from p to q is tan(θ/4) of the arc's included angle θ (> 0 ccw).
    void add_polyline_curves() {
        const std::size_t n = chain_.points.size();
        const std::size_t count = chain_.closed ? n : n - 1;
        for (std::size_t i = 0; i < count; ++i) {
            const Vec2 p = chain_.points[i];
            const Vec2 q = chain_.points[(i + 1) % n];
            const double b = bulges_[i];
            if (std::abs(b) < 1e-12 || length(q - p) < 1e-12) {
                drawing.curves.emplace_back(Segment{p, q});
                continue;
            }
            const double theta = 4.0 * std::atan(b);
            const double chord = length(q - p);
            const double radius = chord / (2.0 * std::sin(std::abs(theta) / 2.0));
            const Vec2 mid = 0.5 * (p + q);
            const Vec2 dir = (1.0 / chord) * (q - p);
            const Vec2 left{-dir.y, dir.x};
            // Centre on the left of p→q for a ccw arc of less than half a turn.
            const double offset = radius * std::cos(theta / 2.0) * (b > 0 ? 1.0 : -1.0);
            const Vec2 centre = mid + offset * left;
            const Vec2 r = p - centre;
            drawing.curves.emplace_back(
                ArcCurve{centre, radius, std::atan2(r.y, r.x) * rad_to_deg, theta * rad_to_deg});
        }
    }

    bool in_block_ = false;
    Open open_ = Open::none;
    DxfChain chain_;
    std::vector<double> bulges_;
    std::vector<Vec2> control_;
};

}  // namespace

Result<DxfDrawing> load_dxf_drawing(const std::filesystem::path& path) {
    auto file = std::make_shared<const std::string>(path.string());
    SourceLocation at{file, 1, 1};
    if (!std::ifstream(path)) return error_at(SourceLocation{file, 0, 0}, "config-io", "cannot read the DXF file");
    Collector collector;
    DL_Dxf dxf;
    if (!dxf.in(path.string(), &collector)) return error_at(at, "dxf", "dxflib cannot read this file as DXF");
    collector.finish_chain();
    if (collector.drawing.curves.empty()) {
        return error_at(at, "dxf", "the drawing has no LINE, ARC, CIRCLE, POLYLINE or SPLINE outside blocks");
    }
    return std::move(collector.drawing);
}

}  // namespace nckit::pattern
