#pragma once
// The pattern job file: the sole outline, the border, the motif and its lattice, groove depths
// per region, the size series and the cutting data. Tables [pattern], [motif], [lattice],
// [[region]], [series] with [[series.size]]; every key checked where it stands.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "nckit/core/result.hpp"
#include "nckit/core/source_location.hpp"
#include "nckit/process/pattern/plane_curve.hpp"

namespace nckit::pattern {

//! A band across the sole's length with its own groove depth: grooves are split where they
//! cross a band's edge, each part cut at the depth of the first band that holds its midpoint.
//! Positions in percent of the outline's length (along X, from its low end).
struct DepthRegion {
    double from_pct = 0;
    double to_pct = 100;
    double depth_mm = 0;
};

//! One size of the series: the outline's length and width increments against the base size
//! (mm), or one scale factor for both.
struct SeriesSize {
    double size = 0;
    std::optional<double> scale;
    double length_mm = 0;
    double width_mm = 0;
    SourceLocation where;
};

enum class MotifGrading { keep, scale };

struct PatternJob {
    std::filesystem::path outline;  //!< CSV or DXF, relative paths against the job's folder
    SourceLocation outline_at;
    double smoothing_tolerance_mm = 0;  //!< 0: the spline passes through every point
    double border_width_mm = 0;
    SourceLocation border_at;
    Vec2 reference_hole_mm;                 //!< the reference hole in the outline's frame
    double tool_diameter_mm = 1.0;          //!< groove width (drawn in the SVG)
    double depth_mm = 1.0;                  //!< groove depth where no region says otherwise
    double feed_mm_min = 300;               //!< cutting feed
    double plunge_feed_mm_min = 100;        //!< Z feed into the plate
    double clearance_mm = 2.0;              //!< Z of the air moves above the plate surface
    double approach_mm = 0.5;               //!< Z where the rapid down ends and the plunge feed starts
    double spindle_rpm = 0;                 //!< 0: no spindle words
    double min_cut_mm = 0.2;                //!< clipped pieces shorter than this are not cut
    std::optional<double> reversal_cost_s;  //!< default: the machine's backlash take-up time

    std::vector<PlaneCurve> motif;  //!< in the motif's own frame
    SourceLocation motif_at;
    Box motif_box;

    Vec2 lattice_spacing_mm;   //!< along a row, between rows
    double row_offset_mm = 0;  //!< shift of each row along it
    double lattice_angle_deg = 0;
    std::optional<Vec2> lattice_origin_mm;  //!< default: the outline's box centre
    SourceLocation lattice_at;

    std::vector<DepthRegion> regions;

    double base_size = 0;
    std::vector<SeriesSize> sizes;  //!< empty: no series, the outline as it is
    MotifGrading motif_grading = MotifGrading::keep;
    SourceLocation series_at;

    std::shared_ptr<const std::string> file;
};

[[nodiscard]] Result<PatternJob> load_pattern_job(const std::filesystem::path& path);
[[nodiscard]] Result<PatternJob> parse_pattern_job(std::string_view toml_text, const std::string& file_name);

}  // namespace nckit::pattern
