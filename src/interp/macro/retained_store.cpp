#include "retained_store.hpp"

#include <atomic>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>

#include <fcntl.h>
#include <unistd.h>

#include <fmt/format.h>

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
        auto [value_end, value_error] = std::from_chars(value_text.data(), value_text.data() + value_text.size(), value);
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
    auto fail = [&](const char* what) {
        return std::optional<Diagnostic>(error_at(make_location(std::make_shared<const std::string>(path.string()), 0, 0),
                                                  "retained-file", fmt::format("{}: {}", what, std::strerror(errno))));
    };
    std::string text = "; nckit retained macro variables #500-#999 (vacant ones are left out)\n";
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (!values[i].vacant) text += fmt::format("#{} = {}\n", first_retained + static_cast<int>(i), values[i].number);
    }
    // Unique per process and per call: two interpreters of one process may finish together.
    static std::atomic<unsigned> saves{0};
    std::filesystem::path temporary = path;
    temporary += fmt::format(".tmp{}.{}", ::getpid(), saves++);
    int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0) return fail("cannot write retained variables");
    std::size_t written = 0;
    while (written < text.size()) {
        ssize_t n = ::write(fd, text.data() + written, text.size() - written);
        if (n < 0) {
            ::close(fd);
            ::unlink(temporary.c_str());
            return fail("cannot write retained variables");
        }
        written += static_cast<std::size_t>(n);
    }
    // Data on disk before the rename makes it visible: a crash leaves the old or the new file.
    if (::fsync(fd) != 0 || ::close(fd) != 0) {
        ::unlink(temporary.c_str());
        return fail("cannot write retained variables");
    }
    if (std::rename(temporary.c_str(), path.c_str()) != 0) {
        ::unlink(temporary.c_str());
        return fail("cannot replace retained variables file");
    }
    return std::nullopt;
}

}  // namespace nckit::interp
