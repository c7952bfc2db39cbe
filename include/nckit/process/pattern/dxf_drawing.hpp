#pragma once
// The entities of a DXF drawing that a sole outline or a motif can be made of, read with
// dxflib (Debian's libdxflib-dev): LINE, ARC, CIRCLE, POLYLINE/LWPOLYLINE (bulges become arcs)
// and SPLINE (through its fit points, or its control points when it has none). Entities inside
// BLOCK definitions are not drawn and are skipped.
#include <filesystem>
#include <vector>

#include "nckit/core/result.hpp"
#include "nckit/process/pattern/plane_curve.hpp"

namespace nckit::pattern {

//! A chain of points as the drawing lists them (polyline vertices, spline fit points).
struct DxfChain {
    std::vector<Vec2> points;
    bool closed = false;
};

struct DxfDrawing {
    std::vector<PlaneCurve> curves;  //!< every entity as curves (an open spline: natural cubic)
    std::vector<DxfChain> chains;    //!< polylines and splines as their points (outlines)
};

//! Reads `path`; a file dxflib cannot read, or one with nothing usable, is an error at FILE:1:1.
[[nodiscard]] Result<DxfDrawing> load_dxf_drawing(const std::filesystem::path& path);

}  // namespace nckit::pattern
