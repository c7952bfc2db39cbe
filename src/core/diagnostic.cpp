#include "nckit/core/diagnostic.hpp"

#include <fmt/format.h>

namespace nckit {

namespace {
const std::string no_file = "<input>";

const char* severity_name(Severity severity) {
    switch (severity) {
        case Severity::error:
            return "error";
        case Severity::warning:
            return "warning";
        case Severity::note:
            return "note";
    }
    return "error";
}
}  // namespace

const std::string& SourceLocation::file_name() const {
    return file ? *file : no_file;
}

SourceLocation make_location(std::shared_ptr<const std::string> file, std::uint32_t line, std::uint32_t column) {
    return SourceLocation{std::move(file), line, column};
}

Diagnostic error_at(SourceLocation location, std::string code, std::string message) {
    return Diagnostic{std::move(location), Severity::error, std::move(code), std::move(message), 0};
}

std::string format_diagnostic(const Diagnostic& d) {
    std::string alarm = d.alarm != 0 ? fmt::format("alarm {}: ", d.alarm) : std::string{};
    return fmt::format("{}:{}:{}: {}: {}{}", d.location.file_name(), d.location.line, d.location.column,
                       severity_name(d.severity), alarm, d.message);
}

}  // namespace nckit
