#include "partial_file.hpp"

#include <utility>

#include <fmt/format.h>

namespace nckit::cli {

void print_output_error(const OutputError& error) {
    std::fflush(stdout);
    fmt::print(stderr, "{}\n", error.message());
}

std::optional<PartialFile> PartialFile::create(const std::string& name) {
    auto opened = OutputFile::open(name);
    if (const auto* error = std::get_if<OutputError>(&opened)) {
        print_output_error(*error);
        return std::nullopt;
    }
    return PartialFile(std::get<OutputFile>(std::move(opened)));
}

bool PartialFile::commit() {
    if (auto error = file_.commit()) {
        print_output_error(*error);
        return false;
    }
    return true;
}

}  // namespace nckit::cli
