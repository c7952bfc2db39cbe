#include "job_functions.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <variant>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace nckit::piston_detail {

namespace {

//! mm two formula intervals may disagree where they meet: the cam table's tolerance, since a
//! step in the drawing is a slip, and the table could only follow it with endless cells.
constexpr double joint_tolerance_mm = 1e-6;

//! Slack when comparing interval ends, for values written with a few decimals.
double z_slack(double range_mm) {
    return 1e-9 * std::max(range_mm, 1.0);
}

std::optional<DrawingFunction> read_table(const toml::array& values, std::string_view key,
                                          std::span<const double> stations, ConfigSink& sink) {
    const std::string what = fmt::format("each entry of '{}'", key);
    std::vector<double> y;
    bool ok = true;
    for (const toml::node& value : values) {
        const std::optional<double> number = nckit::core_detail::to_number(value, what, Sign::any, sink);
        ok = ok && number.has_value();
        if (number) y.push_back(*number);
    }
    if (!stations.empty() && values.size() != stations.size()) {
        sink.error(
            values.source(), "config-value",
            fmt::format("'{}' has {} values for the {} stations of 'z_mm'", key, values.size(), stations.size()));
        return std::nullopt;
    }
    if (!ok || stations.empty()) return std::nullopt;
    return DrawingFunction(NaturalSpline({stations.begin(), stations.end()}, std::move(y)));
}

//! A segment's formula for `key` paired with its interval, in Z order.
struct Piece {
    const SegmentEntry* segment;
    Formula formula;
};

//! Checks that `pieces` (sorted) cover the stations end to end and agree where they meet.
bool check_pieces(std::string_view key, const std::vector<Piece>& pieces, std::span<const double> stations,
                  ConfigSink& sink) {
    bool ok = true;
    const double slack = z_slack(stations.empty() ? 0.0 : stations.back() - stations.front());
    for (std::size_t k = 1; k < pieces.size(); ++k) {
        const SegmentEntry& before = *pieces[k - 1].segment;
        const SegmentEntry& after = *pieces[k].segment;
        if (after.z_from_mm > before.z_to_mm + slack) {
            sink.error(after.from_region, "segment-gap",
                       fmt::format("'{}' is not given between Z {} and {} mm: a gap between "
                                   "[[piston.segment]] intervals",
                                   key, before.z_to_mm, after.z_from_mm));
            ok = false;
        } else if (after.z_from_mm < before.z_to_mm - slack) {
            sink.error(after.from_region, "segment-overlap",
                       fmt::format("'{}' intervals overlap between Z {} and {} mm", key, after.z_from_mm,
                                   std::min(before.z_to_mm, after.z_to_mm)));
            ok = false;
        } else {
            const std::array<double, 1> z{before.z_to_mm};
            const double jump = pieces[k].formula.evaluate(z) - pieces[k - 1].formula.evaluate(z);
            if (!(std::abs(jump) <= joint_tolerance_mm)) {
                sink.error(after.from_region, "segment-jump",
                           fmt::format("'{}' jumps by {:.6g} mm at Z {} mm where two intervals "
                                       "meet; the formulas must agree there within {} mm",
                                       key, jump, before.z_to_mm, joint_tolerance_mm));
                ok = false;
            }
        }
    }
    if (!stations.empty()) {
        const SegmentEntry& first = *pieces.front().segment;
        const SegmentEntry& last = *pieces.back().segment;
        if (first.z_from_mm > stations.front() + slack) {
            sink.error(first.from_region, "segment-gap",
                       fmt::format("'{}' is not given from the first station Z {} mm to {} mm", key, stations.front(),
                                   first.z_from_mm));
            ok = false;
        }
        if (last.z_to_mm < stations.back() - slack) {
            sink.error(last.to_region, "segment-gap",
                       fmt::format("'{}' is not given from {} mm to the last station Z {} mm", key, last.z_to_mm,
                                   stations.back()));
            ok = false;
        }
    }
    return ok;
}

FunctionEntry read_segmented(std::string_view key, std::span<const double> stations,
                             std::span<const SegmentEntry> segments, ConfigSink& sink) {
    FunctionEntry entry;
    std::vector<Piece> pieces;
    bool ok = true;
    for (const SegmentEntry& segment : segments) {
        const toml::node* node = segment.table->get(key);
        if (node == nullptr) continue;
        if (!entry.given) entry.where = node->source();
        entry.given = true;
        std::optional<Formula> formula = read_formula(*node, key, {"Z"}, sink);
        ok = ok && formula.has_value() && segment.valid;
        if (formula && segment.valid) pieces.push_back(Piece{&segment, std::move(*formula)});
    }
    if (!ok || pieces.empty()) return entry;
    std::stable_sort(pieces.begin(), pieces.end(),
                     [](const Piece& a, const Piece& b) { return a.segment->z_from_mm < b.segment->z_from_mm; });
    if (!check_pieces(key, pieces, stations, sink)) return entry;
    std::vector<FormulaSegment> list;
    for (Piece& piece : pieces) {
        entry.breaks_mm.push_back(piece.segment->z_from_mm);
        entry.breaks_mm.push_back(piece.segment->z_to_mm);
        list.push_back(FormulaSegment{piece.segment->z_from_mm, piece.segment->z_to_mm, std::move(piece.formula)});
    }
    entry.function.emplace(std::move(list));
    return entry;
}

}  // namespace

toml::source_region formula_region(const toml::node& node, std::size_t position) {
    toml::source_region region = node.source();
    const auto* text = node.as_string();
    // The quotes add two columns; more means escapes or a multi-line string, whose characters
    // do not map one to one onto columns.
    const bool plain = text != nullptr && region.begin.line == region.end.line &&
                       region.end.column - region.begin.column == text->get().size() + 2;
    if (plain) {
        region.begin.column += static_cast<toml::source_index>(1 + position);
        region.end = region.begin;
    }
    return region;
}

std::optional<Formula> read_formula(const toml::node& node, std::string_view key, std::vector<std::string> variables,
                                    ConfigSink& sink) {
    const auto* text = node.as_string();
    if (text == nullptr) {
        sink.error(
            node.source(), "config-type",
            fmt::format("'{}' must be a formula string, not {}", key, nckit::core_detail::type_name(node.type())));
        return std::nullopt;
    }
    std::variant<Formula, FormulaError> compiled = Formula::compile(text->get(), variables);
    if (auto* error = std::get_if<FormulaError>(&compiled)) {
        sink.error(
            formula_region(node, error->position), "formula-syntax",
            fmt::format("formula syntax in '{}': {} (variables: {})", key, error->message, fmt::join(variables, ", ")));
        return std::nullopt;
    }
    return std::get<Formula>(std::move(compiled));
}

std::vector<SegmentEntry> read_segments(TableReader& piston, ConfigSink& sink) {
    std::vector<SegmentEntry> segments;
    const toml::node* node = piston.node("segment", Need::optional);
    if (node == nullptr) return segments;
    const toml::array* list = node->as_array();
    if (list == nullptr || !list->is_array_of_tables()) {
        sink.error(node->source(), "config-type", "'segment' must be [[piston.segment]] tables of Z intervals");
        return segments;
    }
    for (const toml::node& element : *list) {
        const toml::table& table = *element.as_table();
        TableReader reader(table, "[[piston.segment]]", sink);
        SegmentEntry entry;
        entry.table = &table;
        const std::optional<double> from = reader.number("z_from_mm", Need::required);
        const std::optional<double> to = reader.number("z_to_mm", Need::required);
        entry.from_region = reader.region_of("z_from_mm");
        entry.to_region = reader.region_of("z_to_mm");
        bool gives_one = false;
        for (std::string_view key : segment_function_keys) {
            gives_one = reader.node(key, Need::optional) != nullptr || gives_one;
        }
        if (!gives_one) {
            sink.error(table.source(), "config-missing-key",
                       "a [[piston.segment]] gives none of 'major_diameter_mm', 'ovality_mm', "
                       "'e4_mm'");
        }
        reader.reject_unknown_keys();
        if (from && to) {
            entry.z_from_mm = *from;
            entry.z_to_mm = *to;
            entry.valid = *to > *from;
            if (!entry.valid) {
                sink.error(entry.to_region, "config-value",
                           fmt::format("'z_to_mm' must be greater than 'z_from_mm' ({}), not {}", *from, *to));
            }
        }
        segments.push_back(entry);
    }
    return segments;
}

FunctionEntry read_function(TableReader& piston, std::string_view key, std::span<const double> stations,
                            std::span<const SegmentEntry> segments, ConfigSink& sink) {
    const toml::node* node = piston.node(key, Need::optional);
    if (node == nullptr) return read_segmented(key, stations, segments, sink);
    FunctionEntry entry;
    entry.given = true;
    entry.where = node->source();
    for (const SegmentEntry& segment : segments) {
        if (const toml::node* twice = segment.table->get(key)) {
            sink.error(twice->source(), "config-value",
                       fmt::format("'{}' is given in [piston] (line {}) and again in a "
                                   "[[piston.segment]]",
                                   key, entry.where.begin.line));
            return entry;
        }
    }
    if (node->is_number()) {
        const std::string what = fmt::format("'{}'", key);
        if (auto value = nckit::core_detail::to_number(*node, what, Sign::any, sink)) {
            entry.function = DrawingFunction::constant(*value);
        }
    } else if (const toml::array* values = node->as_array()) {
        entry.table = values;
        entry.function = read_table(*values, key, stations, sink);
    } else if (node->is_string()) {
        if (std::optional<Formula> formula = read_formula(*node, key, {"Z"}, sink)) {
            entry.function.emplace(std::move(*formula));
        }
    } else {
        sink.error(node->source(), "config-type",
                   fmt::format("'{}' must be numbers at the stations, a formula string or a "
                               "number, not {}",
                               key, nckit::core_detail::type_name(node->type())));
    }
    return entry;
}

}  // namespace nckit::piston_detail
