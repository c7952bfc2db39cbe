#include "nckit/process/piston/piston_job.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "job_checks.hpp"
#include "job_functions.hpp"
#include "nckit/cam/cam_table_csv.hpp"
#include "nckit/cam/piston_cam.hpp"
#include "nckit/core/toml_file.hpp"

namespace nckit::cam {

namespace {

using piston_detail::ConfigSink;
using piston_detail::FunctionEntry;
using piston_detail::Need;
using piston_detail::SegmentEntry;
using piston_detail::Sign;
using piston_detail::TableReader;

// Beyond these a value is a typing slip, not a piston or a spindle.
constexpr double max_rpm = 100000;
constexpr double max_z_mm = 10000;

//! A number under `key` with `sign`, and at most `max`.
std::optional<double> bounded(TableReader& reader, std::string_view key, Need need, Sign sign, double max,
                              ConfigSink& sink) {
    std::optional<double> value = reader.number(key, need, sign);
    if (value && *value > max) {
        sink.error(reader.region_of(key), "config-value",
                   fmt::format("'{}' must be at most {}, not {}", key, max, *value));
        return std::nullopt;
    }
    return value;
}

std::optional<int> bounded_int(TableReader& reader, std::string_view key, Need need, int min, int max,
                               ConfigSink& sink) {
    std::optional<int> value = reader.integer(key, need);
    if (value && (*value < min || *value > max)) {
        sink.error(reader.region_of(key), "config-value",
                   fmt::format("'{}' must be from {} to {}, not {}", key, min, max, *value));
        return std::nullopt;
    }
    return value;
}

//! The stations: at least two finite numbers, strictly increasing; empty after an error.
std::vector<double> read_stations(TableReader& reader, ConfigSink& sink) {
    const toml::array* values = reader.array("z_mm", Need::required);
    if (values == nullptr) return {};
    std::vector<double> z;
    bool ok = true;
    for (const toml::node& value : *values) {
        std::optional<double> number = nckit::core_detail::to_number(value, "each entry of 'z_mm'", Sign::any, sink);
        if (number && std::abs(*number) > max_z_mm) {
            sink.error(value.source(), "config-value",
                       fmt::format("'z_mm' entries must lie within ±{} mm, not {}", max_z_mm, *number));
            number.reset();
        }
        if (number && !z.empty() && ok && !(*number > z.back())) {
            sink.error(value.source(), "config-value",
                       fmt::format("'z_mm' must increase strictly: {} follows {}", *number, z.back()));
            number.reset();
        }
        ok = ok && number.has_value();
        if (number) z.push_back(*number);
    }
    if (ok && z.size() < 2) {
        sink.error(values->source(), "config-value", fmt::format("'z_mm' needs at least 2 stations, not {}", z.size()));
        ok = false;
    }
    return ok ? z : std::vector<double>{};
}

std::optional<FastServoSpec> read_servo(const toml::table& table, ConfigSink& sink) {
    TableReader reader(table, "[servo]", sink);
    FastServoSpec servo;
    const std::size_t errors = sink.diagnostics.size();
    auto take = [](std::optional<double> value, double& out) {
        if (value) out = *value;
    };
    take(bounded(reader, "natural_frequency_hz", Need::required, Sign::positive, 1e5, sink),
         servo.natural_frequency_hz);
    take(bounded(reader, "damping", Need::required, Sign::non_negative, 100, sink), servo.damping);
    if (auto bits = bounded_int(reader, "dac_bits", Need::optional, 1, 32, sink)) {
        servo.dac_bits = *bits;
    }
    take(bounded(reader, "stroke_mm", Need::required, Sign::positive, 100, sink), servo.stroke_mm);
    take(bounded(reader, "model_error", Need::optional, Sign::non_negative, 0.9, sink), servo.model_error);
    take(bounded(reader, "max_acceleration_g", Need::optional, Sign::positive, 10000, sink), servo.max_acceleration_g);
    reader.reject_unknown_keys();
    if (sink.diagnostics.size() != errors) return std::nullopt;
    return servo;
}

//! The shape: exactly one of `shape` and `shape_formula`; `e4_mm` with ellipse4 only.
std::optional<SectionShape> read_shape(TableReader& reader, const FunctionEntry& e4, toml::source_region& where,
                                       ConfigSink& sink) {
    // Both keys are looked up, so neither is "unknown" when a job gives both.
    const bool named = reader.node("shape", Need::optional) != nullptr;
    const bool formula = reader.node("shape_formula", Need::optional) != nullptr;
    where = reader.region_of(formula && !named ? "shape_formula" : "shape");
    if (named && formula) {
        sink.error(reader.region_of("shape_formula"), "config-value", "give 'shape' or 'shape_formula', not both");
        return std::nullopt;
    }
    if (formula) {
        const toml::node* node = reader.node("shape_formula", Need::required);
        if (e4.given) {
            sink.error(e4.where, "config-value", "'e4_mm' is used only by shape 'ellipse4'");
        }
        std::optional<Formula> drop =
            piston_detail::read_formula(*node, "shape_formula", shape_formula_variables(), sink);
        if (!drop) return std::nullopt;
        return SectionShape::formula(std::move(*drop));
    }
    const std::optional<std::size_t> choice =
        reader.choice("shape", Need::optional, "shape", {"ellipse2", "ellipse4", "ellipse"});
    if (!named) {
        sink.error(reader.region(), "config-missing-key", "missing key 'shape' (or 'shape_formula') in [piston]");
    }
    if (!choice) return std::nullopt;
    constexpr std::array kinds{ShapeKind::ellipse2, ShapeKind::ellipse4, ShapeKind::ellipse};
    const ShapeKind kind = kinds[*choice];
    if (kind == ShapeKind::ellipse4 && !e4.given) {
        sink.error(where, "config-missing-key", "shape 'ellipse4' needs 'e4_mm' in [piston]");
        return std::nullopt;
    }
    if (kind != ShapeKind::ellipse4 && e4.given) {
        sink.error(e4.where, "config-value", "'e4_mm' is used only by shape 'ellipse4'");
        return std::nullopt;
    }
    if (kind == ShapeKind::ellipse2) return SectionShape::ellipse2();
    if (kind == ShapeKind::ellipse) return SectionShape::ellipse();
    if (!e4.function) return std::nullopt;
    return SectionShape::ellipse4(*e4.function);
}

//! The table under a top-level key; a missing or mistyped one is reported.
const toml::table* section(TableReader& root, std::string_view key, ConfigSink& sink) {
    const toml::table* table = root.table(key, Need::optional);
    if (table == nullptr && !root.has(key)) {
        sink.error(root.region(), "config-missing-key", fmt::format("missing table [{}]", key));
    }
    return table;
}

//! A drawing function the job must give, in [piston] or in its segments.
FunctionEntry required_function(TableReader& reader, std::string_view key, std::span<const double> stations,
                                std::span<const SegmentEntry> segments, ConfigSink& sink) {
    FunctionEntry entry = piston_detail::read_function(reader, key, stations, segments, sink);
    if (!entry.given) {
        sink.error(reader.region(), "config-missing-key",
                   fmt::format("missing key '{}' in [piston] (or in [[piston.segment]])", key));
    }
    return entry;
}

//! Stations and formula interval ends within the stations, sorted, near-duplicates merged.
std::vector<double> breaks(std::span<const double> stations, std::initializer_list<const FunctionEntry*> functions) {
    std::vector<double> z(stations.begin(), stations.end());
    for (const FunctionEntry* f : functions) {
        for (double b : f->breaks_mm) {
            if (b > stations.front() && b < stations.back()) z.push_back(b);
        }
    }
    std::sort(z.begin(), z.end());
    const double slack = 1e-9 * std::max(stations.back() - stations.front(), 1.0);
    z.erase(std::unique(z.begin(), z.end(), [&](double a, double b) { return b - a <= slack; }), z.end());
    return z;
}

//! The job, or nothing when a diagnostic has been reported.
std::optional<PistonJob> read_document(const toml::table& document, ConfigSink& sink) {
    TableReader root(document, "", sink);
    const toml::table* piston = section(root, "piston", sink);
    const toml::table* servo_table = section(root, "servo", sink);
    root.reject_unknown_keys();
    const std::optional<FastServoSpec> servo = servo_table != nullptr ? read_servo(*servo_table, sink) : std::nullopt;
    if (piston == nullptr) return std::nullopt;

    TableReader reader(*piston, "[piston]", sink);
    const std::optional<double> rpm = bounded(reader, "rpm", Need::required, Sign::positive, max_rpm, sink);
    const std::vector<double> stations = read_stations(reader, sink);
    const std::vector<SegmentEntry> segments = piston_detail::read_segments(reader, sink);
    const FunctionEntry d = required_function(reader, "major_diameter_mm", stations, segments, sink);
    const FunctionEntry e = required_function(reader, "ovality_mm", stations, segments, sink);
    const FunctionEntry e4 = piston_detail::read_function(reader, "e4_mm", stations, segments, sink);
    toml::source_region shape_where;
    const std::optional<SectionShape> shape = read_shape(reader, e4, shape_where, sink);
    PistonJob job{
        .rpm = rpm.value_or(0),
        .z_mm = stations,
        .z_breaks_mm = {},
        .profile = PistonProfile(DrawingFunction::constant(0), DrawingFunction::constant(0), SectionShape::ellipse2()),
        .feed_mm_rev = 0.1,
        .encoder_counts = 360,
        .spindle_ripple = 0,
        .servo = servo.value_or(FastServoSpec{}),
        .demand = {},
        .source = {}};
    if (auto feed = bounded(reader, "feed_mm_rev", Need::optional, Sign::positive, 10, sink)) {
        job.feed_mm_rev = *feed;
    }
    if (auto counts = bounded_int(reader, "encoder_counts", Need::optional, 1, 10'000'000, sink)) {
        job.encoder_counts = *counts;
    }
    if (auto ripple = bounded(reader, "spindle_ripple", Need::optional, Sign::non_negative, 0.5, sink)) {
        job.spindle_ripple = *ripple;
    }
    job.source.encoder_counts = sink.at(reader.region_of("encoder_counts"));
    job.source.ripple_given = reader.has("spindle_ripple");
    if (servo_table != nullptr) {
        job.source.servo = sink.at(servo_table->source());
        const toml::node* stroke = servo_table->get("stroke_mm");
        job.source.stroke = sink.at(stroke != nullptr ? stroke->source() : servo_table->source());
    }
    reader.reject_unknown_keys();
    if (!sink.diagnostics.empty()) return std::nullopt;

    // Values, then the section, then what the section asks of the servo: each needs the last.
    const std::vector<double> grid = demand_z_grid(stations, DemandGrid{}.z_subdivisions);
    if (!piston_detail::check_drawing_values(d, e, e4, stations, grid, sink)) return std::nullopt;
    job.profile = PistonProfile(*d.function, *e.function, *shape);
    if (!piston_detail::check_section(job.profile, grid, shape_where, sink)) return std::nullopt;
    job.demand = measure_demand(std::cref(job.profile), stations);
    piston_detail::check_servo_demand(job.demand, job.rpm, job.servo, e.where, reader.region_of("rpm"), sink);
    if (!sink.diagnostics.empty()) return std::nullopt;
    job.z_breaks_mm = breaks(stations, {&d, &e, &e4});
    return job;
}

}  // namespace

namespace {

Result<PistonJob> read_file(Result<nckit::core_detail::TomlFile> file) {
    if (!file) return file.diagnostics();
    ConfigSink sink{file->name, {}};
    std::optional<PistonJob> job = read_document(file->document, sink);
    if (job && sink.diagnostics.empty()) return std::move(*job);
    nckit::core_detail::sort_by_position(sink.diagnostics);
    return std::move(sink.diagnostics);
}

}  // namespace

Result<PistonJob> parse_piston_job(std::string_view toml_text, const std::string& file_name) {
    return read_file(nckit::core_detail::parse_toml_text(toml_text, file_name));
}

Result<PistonJob> load_piston_job(const std::filesystem::path& path) {
    return read_file(nckit::core_detail::load_toml_file(path, "piston job"));
}

CamTable build_cam_table(const PistonJob& job, double tolerance_mm) {
    return build_piston_cam_table(job.profile, piston_cam_options(job.z_breaks_mm, tolerance_mm));
}

void write_cam_table_csv(std::ostream& out, const PistonJob& job) {
    write_cam_table_csv(out, std::cref(job.profile), job.z_mm);
}

}  // namespace nckit::cam
