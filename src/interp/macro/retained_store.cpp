#include "retained_store.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include <fmt/format.h>

#include "nckit/core/output_file.hpp"

namespace nckit::interp {

namespace {

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
    return s;
}

}  // namespace

Result<RetainedValues> load_retained(const std::filesystem::path& path) {
    RetainedValues values{};
    std::ifstream in(path);
    if (!in) return values;  // first run: nothing retained yet
    auto file = std::make_shared<const std::string>(path.string());
    std::string line;
    std::uint32_t number = 0;
    while (std::getline(in, line)) {
        ++number;
        std::string_view text = trim(line);
        if (text.empty() || text.front() == ';') continue;
        auto bad = [&](const std::string& why) {
            return Result<RetainedValues>(error_at(make_location(file, number, 1), "retained-file", why));
        };
        std::size_t equals = text.find('=');
        if (text.front() != '#' || equals == std::string_view::npos) return bad("expected '#NNN = value'");
        std::string_view name = trim(text.substr(1, equals - 1));
        std::string_view value_text = trim(text.substr(equals + 1));
        int variable = 0;
        double value = 0;
        auto [name_end, name_error] = std::from_chars(name.data(), name.data() + name.size(), variable);
        if (name_error != std::errc{} || name_end != name.data() + name.size() || variable < first_retained ||
            variable > last_retained) {
            return bad(fmt::format("'{}' is not a retained variable (#500 to #999)", name));
        }
        auto [value_end, value_error] =
            std::from_chars(value_text.data(), value_text.data() + value_text.size(), value);
        // from_chars also reads "nan" and "inf", which no macro variable can hold.
        bool whole_text = value_end == value_text.data() + value_text.size();
        if (value_error != std::errc{} || !whole_text || !std::isfinite(value)) {
            return bad(fmt::format("'{}' is not a number", value_text));
        }
        values[static_cast<std::size_t>(variable - first_retained)] = MacroValue::of(value);
    }
    return values;
}

std::optional<Diagnostic> save_retained(const std::filesystem::path& path, const RetainedValues& values) {
    std::string text = "; nckit retained macro variables #500-#999 (vacant ones are left out)\n";
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (!values[i].vacant)
            text += fmt::format("#{} = {}\n", first_retained + static_cast<int>(i), values[i].number);
    }
    // Written as FILE.partial, fsync'd and renamed: a crash leaves the old or the new file.
    if (auto error = write_file_atomically(path, text)) {
        return error_at(make_location(std::make_shared<const std::string>(path.string()), 0, 0), "retained-file",
                        fmt::format("cannot write retained variables: {}{}", error->reason,
                                    error->detail.empty() ? std::string{} : " (" + error->detail + ")"));
    }
    return std::nullopt;
}

}  // namespace nckit::interp
