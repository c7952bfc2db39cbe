#pragma once
// For the config and job loaders of every stage (machine files, process jobs): typed reads of
// one TOML table where every problem (missing key, wrong type, out-of-range value, unknown key)
// becomes a located Diagnostic instead of stopping. Loaders collect all their errors in one
// pass, so a user fixes a file in one round.
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "nckit/core/diagnostic.hpp"

namespace nckit::core_detail {

//! Collects the diagnostics of one config file and stamps them with its name.
struct ConfigSink {
    std::shared_ptr<const std::string> file;
    Diagnostics diagnostics;

    [[nodiscard]] SourceLocation at(const toml::source_region& region) const;
    void error(const toml::source_region& region, std::string code, std::string message);
};

enum class Need { required, optional };

//! The sign a number must have; checked here so each rule is written once.
enum class Sign { any, positive, non_negative };

//! "a string", "an integer": how messages name what the user wrote.
[[nodiscard]] std::string_view type_name(toml::node_type type);

//! `node` as a finite number (an integer is accepted where a float is expected); `what` names
//! it in messages, e.g. "'max_velocity'". Reports and returns nothing when it does not fit.
[[nodiscard]] std::optional<double> to_number(const toml::node& node, std::string_view what, Sign sign,
                                              ConfigSink& sink);
//! `node` as an integer that fits an `int`.
[[nodiscard]] std::optional<int> to_int(const toml::node& node, std::string_view what, Sign sign, ConfigSink& sink);

class TableReader {
public:
    //! `label` names the table in messages, e.g. "[machine]"; empty for the document root.
    TableReader(const toml::table& table, std::string label, ConfigSink& sink);

    //! The raw node under `key`, or null; a missing required key is reported.
    const toml::node* node(std::string_view key, Need need);

    std::optional<double> number(std::string_view key, Need need, Sign sign = Sign::any);
    //! number(), stored into `out` when present and valid (out keeps its default otherwise).
    bool number_into(std::string_view key, Need need, Sign sign, double& out) {
        const std::optional<double> value = number(key, need, sign);
        if (value) out = *value;
        return value.has_value();
    }
    std::optional<int> integer(std::string_view key, Need need, Sign sign = Sign::any);
    std::optional<std::string> text(std::string_view key, Need need);
    std::optional<bool> flag(std::string_view key, Need need);
    const toml::array* array(std::string_view key, Need need);
    //! The table under `key` (`[key]` in the file); anything else there is reported.
    const toml::table* table(std::string_view key, Need need);

    //! Which of `choices` the string under `key` is (its index). `noun` names the value in
    //! the message: "axis 'Q' is not one of X Y Z A B C U V W".
    std::optional<std::size_t> choice(std::string_view key, Need need, std::string_view noun,
                                      std::initializer_list<std::string_view> choices);

    [[nodiscard]] bool has(std::string_view key) const { return table_.contains(key); }

    //! The value's region, or the table's when the key is absent: where cross-key checks point.
    [[nodiscard]] const toml::source_region& region_of(std::string_view key) const;
    [[nodiscard]] const toml::source_region& region() const { return table_.source(); }

    //! Reports every key no read asked for: on a machine a misspelt key silently ignored
    //! (`max_acceleraton`) leaves a limit at a value nobody chose.
    void reject_unknown_keys();

private:
    void wrong_type(std::string_view key, const toml::node& node, std::string_view expected);
    [[nodiscard]] std::string in_label() const;

    const toml::table& table_;
    std::string label_;
    ConfigSink& sink_;
    std::vector<std::string> known_keys_;
};

}  // namespace nckit::core_detail
