// The pattern job file reader.
#include "nckit/process/pattern/pattern_job.hpp"

#include <fmt/format.h>

#include "nckit/core/toml_file.hpp"
#include "nckit/core/toml_table_reader.hpp"
#include "nckit/process/pattern/dxf_drawing.hpp"
#include "nckit/process/pattern/spline_fit.hpp"

namespace nckit::pattern {

namespace {

using core_detail::ConfigSink;
using core_detail::Need;
using core_detail::Sign;
using core_detail::TableReader;

constexpr std::size_t max_motif_curves = 10000;

// A fixed-length array of numbers; reported at the node when it is not one.
std::optional<std::vector<double>> numbers(const toml::node& node, std::size_t count, std::string_view what,
                                           ConfigSink& sink) {
    const toml::array* array = node.as_array();
    if (array == nullptr || (count != 0 && array->size() != count)) {
        sink.error(node.source(), "config-type",
                   count != 0 ? fmt::format("{} must be an array of {} numbers", what, count)
                              : fmt::format("{} must be an array of numbers", what));
        return std::nullopt;
    }
    std::vector<double> out;
    for (const toml::node& item : *array) {
        std::optional<double> v = core_detail::to_number(item, what, Sign::any, sink);
        if (!v) return std::nullopt;
        out.push_back(*v);
    }
    return out;
}

std::optional<Vec2> point(const toml::node& node, std::string_view what, ConfigSink& sink) {
    auto v = numbers(node, 2, what, sink);
    if (!v) return std::nullopt;
    return Vec2{(*v)[0], (*v)[1]};
}

void read_pattern(TableReader& reader, PatternJob& job, ConfigSink& sink, const std::filesystem::path& folder) {
    if (auto outline = reader.text("outline", Need::required)) job.outline = folder / *outline;
    job.outline_at = sink.at(reader.region_of("outline"));
    reader.number_into("smoothing_tolerance_mm", Need::optional, Sign::non_negative, job.smoothing_tolerance_mm);
    reader.number_into("border_width_mm", Need::required, Sign::non_negative, job.border_width_mm);
    job.border_at = sink.at(reader.region_of("border_width_mm"));
    if (const toml::node* hole = reader.node("reference_hole_mm", Need::required)) {
        if (auto p = point(*hole, "'reference_hole_mm'", sink)) job.reference_hole_mm = *p;
    }
    reader.number_into("tool_diameter_mm", Need::optional, Sign::positive, job.tool_diameter_mm);
    reader.number_into("depth_mm", Need::required, Sign::positive, job.depth_mm);
    reader.number_into("feed_mm_min", Need::required, Sign::positive, job.feed_mm_min);
    reader.number_into("plunge_feed_mm_min", Need::optional, Sign::positive, job.plunge_feed_mm_min);
    reader.number_into("clearance_mm", Need::optional, Sign::positive, job.clearance_mm);
    reader.number_into("approach_mm", Need::optional, Sign::non_negative, job.approach_mm);
    if (job.approach_mm > job.clearance_mm) {
        sink.error(reader.region_of("approach_mm"), "config-value", "'approach_mm' must not be above 'clearance_mm'");
    }
    reader.number_into("spindle_rpm", Need::optional, Sign::non_negative, job.spindle_rpm);
    reader.number_into("min_cut_mm", Need::optional, Sign::non_negative, job.min_cut_mm);
    if (auto cost = reader.number("reversal_cost_s", Need::optional, Sign::non_negative)) job.reversal_cost_s = *cost;
    reader.reject_unknown_keys();
}

void read_motif(TableReader& reader, PatternJob& job, ConfigSink& sink, const std::filesystem::path& folder) {
    job.motif_at = sink.at(reader.region());
    if (const toml::array* lines = reader.array("lines", Need::optional)) {
        for (const toml::node& line : *lines) {
            if (auto v = numbers(line, 4, "a motif line [x0, y0, x1, y1]", sink)) {
                job.motif.emplace_back(Segment{{(*v)[0], (*v)[1]}, {(*v)[2], (*v)[3]}});
            }
        }
    }
    if (const toml::array* arcs = reader.array("arcs", Need::optional)) {
        for (const toml::node& arc : *arcs) {
            auto v = numbers(arc, 5, "a motif arc [cx, cy, radius, start_deg, sweep_deg]", sink);
            if (!v) continue;
            if ((*v)[2] <= 0 || (*v)[4] == 0 || std::abs((*v)[4]) > 360) {
                sink.error(arc.source(), "config-value",
                           "an arc needs a positive radius and a sweep of 0 < |sweep| <= 360 deg");
                continue;
            }
            job.motif.emplace_back(ArcCurve{{(*v)[0], (*v)[1]}, (*v)[2], (*v)[3], (*v)[4]});
        }
    }
    if (const toml::array* splines = reader.array("splines", Need::optional)) {
        for (const toml::node& spline : *splines) {
            const toml::array* pts = spline.as_array();
            std::vector<Vec2> points;
            bool ok = pts != nullptr && pts->size() >= 2 && pts->size() <= 1000;
            if (ok) {
                for (const toml::node& p : *pts) {
                    auto q = point(p, "a spline point [x, y]", sink);
                    if (!q) {
                        ok = false;
                        break;
                    }
                    points.push_back(*q);
                }
            } else {
                sink.error(spline.source(), "config-type", "a motif spline is an array of 2 to 1000 points [x, y]");
            }
            if (ok) job.motif.emplace_back(fit_open_spline(points));
        }
    }
    if (auto dxf = reader.text("dxf", Need::optional)) {
        Result<DxfDrawing> drawing = load_dxf_drawing(folder / *dxf);
        if (!drawing) {
            for (const Diagnostic& d : drawing.diagnostics()) sink.diagnostics.push_back(d);
        } else {
            for (PlaneCurve& c : drawing->curves) job.motif.push_back(std::move(c));
        }
    }
    reader.reject_unknown_keys();
    if (job.motif.empty() && sink.diagnostics.empty()) {
        sink.error(reader.region(), "config-value", "the motif has no curves (lines, arcs, splines or dxf)");
    }
    if (job.motif.size() > max_motif_curves) {
        sink.error(reader.region(), "config-value", fmt::format("more than {} motif curves", max_motif_curves));
    }
    for (const PlaneCurve& c : job.motif) {
        const Box b = bounding_box(c);
        job.motif_box.add(b.low);
        job.motif_box.add(b.high);
    }
}

void read_lattice(TableReader& reader, PatternJob& job, ConfigSink& sink) {
    job.lattice_at = sink.at(reader.region());
    if (const toml::node* spacing = reader.node("spacing_mm", Need::required)) {
        if (auto p = point(*spacing, "'spacing_mm' [along a row, between rows]", sink)) {
            if (p->x <= 0 || p->y <= 0) {
                sink.error(spacing->source(), "config-value", "both lattice spacings must be positive");
            } else {
                job.lattice_spacing_mm = *p;
            }
        }
    }
    reader.number_into("row_offset_mm", Need::optional, Sign::any, job.row_offset_mm);
    reader.number_into("angle_deg", Need::optional, Sign::any, job.lattice_angle_deg);
    if (const toml::node* origin = reader.node("origin_mm", Need::optional)) {
        if (auto p = point(*origin, "'origin_mm'", sink)) job.lattice_origin_mm = *p;
    }
    reader.reject_unknown_keys();
}

void read_regions(const toml::array& regions, PatternJob& job, ConfigSink& sink) {
    for (const toml::node& node : regions) {
        const toml::table* table = node.as_table();
        if (table == nullptr) {
            sink.error(node.source(), "config-type", "[[region]] must be a table");
            continue;
        }
        TableReader reader(*table, "[[region]]", sink);
        DepthRegion region;
        reader.number_into("from_pct", Need::required, Sign::non_negative, region.from_pct);
        reader.number_into("to_pct", Need::required, Sign::non_negative, region.to_pct);
        reader.number_into("depth_mm", Need::required, Sign::positive, region.depth_mm);
        reader.reject_unknown_keys();
        if (region.from_pct >= region.to_pct || region.to_pct > 100) {
            sink.error(reader.region(), "config-value", "a region needs 0 <= from_pct < to_pct <= 100");
        }
        job.regions.push_back(region);
    }
}

void read_series(TableReader& reader, PatternJob& job, ConfigSink& sink) {
    job.series_at = sink.at(reader.region());
    reader.number_into("base_size", Need::required, Sign::positive, job.base_size);
    if (auto grading = reader.choice("motifs", Need::optional, "motif grading", {"keep", "scale"})) {
        job.motif_grading = *grading == 0 ? MotifGrading::keep : MotifGrading::scale;
    }
    if (const toml::array* sizes = reader.array("size", Need::required)) {
        for (const toml::node& node : *sizes) {
            const toml::table* table = node.as_table();
            if (table == nullptr) {
                sink.error(node.source(), "config-type", "[[series.size]] must be a table");
                continue;
            }
            TableReader size_reader(*table, "[[series.size]]", sink);
            SeriesSize size;
            size.where = sink.at(node.source());
            size_reader.number_into("size", Need::required, Sign::positive, size.size);
            if (auto scale = size_reader.number("scale", Need::optional, Sign::positive)) size.scale = *scale;
            const bool has_length = size_reader.number_into("length_mm", Need::optional, Sign::any, size.length_mm);
            const bool has_width = size_reader.number_into("width_mm", Need::optional, Sign::any, size.width_mm);
            size_reader.reject_unknown_keys();
            if (!size.scale && !has_length && !has_width && size.size != job.base_size) {
                sink.error(node.source(), "series-size",
                           fmt::format("size {} has no factor: give 'scale' or 'length_mm' and 'width_mm'", size.size));
            }
            if (size.scale && (has_length || has_width)) {
                sink.error(node.source(), "series-size",
                           fmt::format("size {} gives both 'scale' and length/width increments", size.size));
            }
            for (const SeriesSize& other : job.sizes) {
                if (other.size == size.size) {
                    sink.error(node.source(), "series-size", fmt::format("size {} is listed twice", size.size));
                }
            }
            job.sizes.push_back(size);
        }
        if (job.sizes.size() > 100) sink.error(reader.region_of("size"), "series-size", "more than 100 sizes");
    }
    reader.reject_unknown_keys();
}

Result<PatternJob> read_job(const core_detail::TomlFile& file, const std::filesystem::path& folder) {
    ConfigSink sink{file.name, {}};
    PatternJob job;
    job.file = file.name;
    TableReader root(file.document, "", sink);
    if (const toml::table* t = root.table("pattern", Need::required)) {
        TableReader reader(*t, "[pattern]", sink);
        read_pattern(reader, job, sink, folder);
    }
    if (const toml::table* t = root.table("motif", Need::required)) {
        TableReader reader(*t, "[motif]", sink);
        read_motif(reader, job, sink, folder);
    }
    if (const toml::table* t = root.table("lattice", Need::required)) {
        TableReader reader(*t, "[lattice]", sink);
        read_lattice(reader, job, sink);
    }
    if (const toml::array* regions = root.array("region", Need::optional)) read_regions(*regions, job, sink);
    if (const toml::table* t = root.table("series", Need::optional)) {
        TableReader reader(*t, "[series]", sink);
        read_series(reader, job, sink);
    }
    root.reject_unknown_keys();
    if (!sink.diagnostics.empty()) {
        core_detail::sort_by_position(sink.diagnostics);
        return std::move(sink.diagnostics);
    }
    return job;
}

}  // namespace

Result<PatternJob> parse_pattern_job(std::string_view toml_text, const std::string& file_name) {
    Result<core_detail::TomlFile> file = core_detail::parse_toml_text(toml_text, file_name);
    if (!file) return file.diagnostics();
    return read_job(*file, std::filesystem::path(file_name).parent_path());
}

Result<PatternJob> load_pattern_job(const std::filesystem::path& path) {
    Result<core_detail::TomlFile> file = core_detail::load_toml_file(path, "pattern job");
    if (!file) return file.diagnostics();
    return read_job(*file, path.parent_path());
}

}  // namespace nckit::pattern
