#include "program_library.hpp"

#include <cctype>

namespace nckit::interp {

namespace {

std::size_t skip_blanks(std::string_view s, std::size_t i) {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
    return i;
}

//! Digits (blanks allowed between them, as everywhere in G-code) from `i` on; at most 8.
std::optional<std::int64_t> number_at(std::string_view s, std::size_t i) {
    std::int64_t value = 0;
    int digits = 0;
    for (; i < s.size(); ++i) {
        char c = s[i];
        if (c == ' ' || c == '\t') continue;
        if (c < '0' || c > '9') break;
        value = value * 10 + (c - '0');
        if (++digits > 8) return std::nullopt;
    }
    if (digits == 0) return std::nullopt;
    return value;
}

std::optional<std::int64_t> lettered_number(std::string_view line, char letter, bool allow_slash) {
    std::size_t i = skip_blanks(line, 0);
    if (allow_slash && i < line.size() && line[i] == '/') i = skip_blanks(line, i + 1);
    if (i >= line.size() || std::toupper(static_cast<unsigned char>(line[i])) != letter) return std::nullopt;
    return number_at(line, i + 1);
}

//! Library file names: `O1234`, `o1234.nc`, `1234.ngc`.
std::optional<std::int64_t> number_of_file(const std::filesystem::path& path) {
    std::string stem = path.stem().string();
    if (!stem.empty() && (stem[0] == 'O' || stem[0] == 'o')) stem.erase(0, 1);
    if (stem.empty() || stem.size() > 8) return std::nullopt;
    for (char c : stem) {
        if (c < '0' || c > '9') return std::nullopt;
    }
    return std::stoll(stem);
}

}  // namespace

std::optional<std::int64_t> program_number_of(std::string_view line) {
    return lettered_number(line, 'O', false);
}

std::optional<std::int64_t> sequence_number_of(std::string_view line) {
    return lettered_number(line, 'N', true);
}

ProgramLibrary::ProgramLibrary(std::filesystem::path library_dir) : library_dir_(std::move(library_dir)) {}

std::optional<Diagnostic> ProgramLibrary::index_main_file(const ProgramSource& main) {
    main_indexed_ = true;
    auto reader = main.reopen();
    if (!reader) return reader.diagnostics().front();
    for (;;) {
        auto line = reader->next();
        if (!line) return line.diagnostics().front();
        if (!line.value()) return std::nullopt;
        const ProgramSource::Line& text = **line;
        if (auto number = program_number_of(text.text)) {
            // The first program of a number wins, as a control refuses to store a second.
            main_programs_.try_emplace(*number, ProgramLocation{*main.file(), true, text.offset, text.number});
        }
    }
}

void ProgramLibrary::index_library() {
    library_indexed_ = true;
    std::error_code ec;
    if (library_dir_.empty() || !std::filesystem::is_directory(library_dir_, ec)) return;
    for (const auto& entry : std::filesystem::directory_iterator(library_dir_, ec)) {
        if (!entry.is_regular_file(ec)) continue;
        if (auto number = number_of_file(entry.path())) library_programs_.try_emplace(*number, entry.path());
    }
}

Result<std::optional<ProgramLocation>> ProgramLibrary::find(std::int64_t number, const ProgramSource& main) {
    if (!main_indexed_) {
        if (auto error = index_main_file(main)) return *error;
    }
    if (auto it = main_programs_.find(number); it != main_programs_.end()) {
        return std::optional<ProgramLocation>(it->second);
    }
    if (!library_indexed_) index_library();
    if (auto it = library_programs_.find(number); it != library_programs_.end()) {
        return std::optional<ProgramLocation>(ProgramLocation{it->second.string(), false, 0, 1});
    }
    return std::optional<ProgramLocation>{};
}

}  // namespace nckit::interp
