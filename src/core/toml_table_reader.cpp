#include "nckit/core/toml_table_reader.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace nckit::core_detail {

namespace {

// Shared by floats and integers so both spell the rule the same way.
template <class T>
bool check_sign(const toml::node& node, std::string_view what, Sign sign, T value, ConfigSink& sink) {
    if (sign == Sign::positive && !(value > 0)) {
        sink.error(node.source(), "config-value", fmt::format("{} must be positive, not {}", what, value));
        return false;
    }
    if (sign == Sign::non_negative && value < 0) {
        sink.error(node.source(), "config-value", fmt::format("{} must be zero or more, not {}", what, value));
        return false;
    }
    return true;
}

std::string quoted(std::string_view key) {
    return fmt::format("'{}'", key);
}

}  // namespace

SourceLocation ConfigSink::at(const toml::source_region& region) const {
    return make_location(file, region.begin.line, region.begin.column);
}

void ConfigSink::error(const toml::source_region& region, std::string code, std::string message) {
    diagnostics.push_back(error_at(at(region), std::move(code), std::move(message)));
}

std::string_view type_name(toml::node_type type) {
    switch (type) {
        case toml::node_type::none:
            return "nothing";
        case toml::node_type::table:
            return "a table";
        case toml::node_type::array:
            return "an array";
        case toml::node_type::string:
            return "a string";
        case toml::node_type::integer:
            return "an integer";
        case toml::node_type::floating_point:
            return "a floating-point number";
        case toml::node_type::boolean:
            return "a boolean";
        case toml::node_type::date:
            return "a date";
        case toml::node_type::time:
            return "a time";
        case toml::node_type::date_time:
            return "a date-time";
    }
    return "an unknown value";
}

std::optional<double> to_number(const toml::node& node, std::string_view what, Sign sign, ConfigSink& sink) {
    std::optional<double> value;
    if (const auto* f = node.as_floating_point()) value = f->get();
    if (const auto* i = node.as_integer()) value = static_cast<double>(i->get());
    if (!value) {
        sink.error(node.source(), "config-type",
                   fmt::format("{} must be a number, not {}", what, type_name(node.type())));
        return std::nullopt;
    }
    // TOML allows inf and nan; neither is a usable limit or travel.
    if (!std::isfinite(*value)) {
        sink.error(node.source(), "config-value", fmt::format("{} must be a finite number, not {}", what, *value));
        return std::nullopt;
    }
    if (!check_sign(node, what, sign, *value, sink)) return std::nullopt;
    return value;
}

std::optional<int> to_int(const toml::node& node, std::string_view what, Sign sign, ConfigSink& sink) {
    const auto* i = node.as_integer();
    if (i == nullptr) {
        sink.error(node.source(), "config-type",
                   fmt::format("{} must be an integer, not {}", what, type_name(node.type())));
        return std::nullopt;
    }
    const std::int64_t value = i->get();
    if (!check_sign(node, what, sign, value, sink)) return std::nullopt;
    if (value < std::numeric_limits<int>::min() || value > std::numeric_limits<int>::max()) {
        sink.error(node.source(), "config-value", fmt::format("{} is out of range: {}", what, value));
        return std::nullopt;
    }
    return static_cast<int>(value);
}

TableReader::TableReader(const toml::table& table, std::string label, ConfigSink& sink)
    : table_(table), label_(std::move(label)), sink_(sink) {}

std::string TableReader::in_label() const {
    return label_.empty() ? std::string("at top level") : "in " + label_;
}

const toml::node* TableReader::node(std::string_view key, Need need) {
    known_keys_.emplace_back(key);
    const toml::node* found = table_.get(key);
    if (found == nullptr && need == Need::required) {
        sink_.error(table_.source(), "config-missing-key", fmt::format("missing key '{}' {}", key, in_label()));
    }
    return found;
}

void TableReader::wrong_type(std::string_view key, const toml::node& found, std::string_view expected) {
    sink_.error(found.source(), "config-type",
                fmt::format("'{}' must be {}, not {}", key, expected, type_name(found.type())));
}

std::optional<double> TableReader::number(std::string_view key, Need need, Sign sign) {
    const toml::node* found = node(key, need);
    if (found == nullptr) return std::nullopt;
    return to_number(*found, quoted(key), sign, sink_);
}

std::optional<int> TableReader::integer(std::string_view key, Need need, Sign sign) {
    const toml::node* found = node(key, need);
    if (found == nullptr) return std::nullopt;
    return to_int(*found, quoted(key), sign, sink_);
}

std::optional<std::string> TableReader::text(std::string_view key, Need need) {
    const toml::node* found = node(key, need);
    if (found == nullptr) return std::nullopt;
    if (const auto* s = found->as_string()) return s->get();
    wrong_type(key, *found, "a string");
    return std::nullopt;
}

std::optional<bool> TableReader::flag(std::string_view key, Need need) {
    const toml::node* found = node(key, need);
    if (found == nullptr) return std::nullopt;
    if (const auto* b = found->as_boolean()) return b->get();
    wrong_type(key, *found, "true or false");
    return std::nullopt;
}

const toml::array* TableReader::array(std::string_view key, Need need) {
    const toml::node* found = node(key, need);
    if (found == nullptr) return nullptr;
    if (const auto* a = found->as_array()) return a;
    wrong_type(key, *found, "an array");
    return nullptr;
}

const toml::table* TableReader::table(std::string_view key, Need need) {
    const toml::node* found = node(key, need);
    if (found == nullptr) return nullptr;
    if (const toml::table* sub = found->as_table()) return sub;
    sink_.error(found->source(), "config-type",
                fmt::format("'{}' must be a table ([{}]), not {}", key, key, type_name(found->type())));
    return nullptr;
}

std::optional<std::size_t> TableReader::choice(std::string_view key, Need need, std::string_view noun,
                                               std::initializer_list<std::string_view> choices) {
    const std::optional<std::string> value = text(key, need);
    if (!value) return std::nullopt;
    const auto* hit = std::find(choices.begin(), choices.end(), *value);
    if (hit != choices.end()) return static_cast<std::size_t>(hit - choices.begin());
    sink_.error(region_of(key), "config-value",
                fmt::format("{} '{}' is not one of {}", noun, *value, fmt::join(choices, " ")));
    return std::nullopt;
}

const toml::source_region& TableReader::region_of(std::string_view key) const {
    const toml::node* found = table_.get(key);
    return found != nullptr ? found->source() : table_.source();
}

void TableReader::reject_unknown_keys() {
    for (auto&& [key, value] : table_) {
        if (std::find(known_keys_.begin(), known_keys_.end(), key.str()) != known_keys_.end()) {
            continue;
        }
        std::string message = fmt::format("unknown key '{}' {}", key.str(), in_label());
        // At the root an unknown key is usually a whole section; say so in TOML's own words.
        if (label_.empty() && value.is_table()) {
            message = fmt::format("unknown table [{}]", key.str());
        } else if (label_.empty() && value.is_array_of_tables()) {
            message = fmt::format("unknown table [[{}]]", key.str());
        }
        sink_.error(key.source(), "config-unknown-key", std::move(message));
    }
}

}  // namespace nckit::core_detail
