// Reading a run journal back with the torn-tail rule (docs/restart.md#the-run-journal).
#include <algorithm>
#include <charconv>
#include <fstream>
#include <map>

#include <fmt/format.h>

#include "nckit/interp/run_journal.hpp"

namespace nckit {

namespace {

constexpr std::size_t max_record_bytes = 1 << 16;  // a header with all 500 retained values is ~15 kB

//! The payload of a record whose checksum holds; none for a damaged one.
std::optional<std::string_view> checked_payload(std::string_view line) {
    const std::size_t star = line.rfind(" *");
    if (star == std::string_view::npos || line.size() - star != 10) return std::nullopt;
    std::uint32_t crc = 0;
    const char* begin = line.data() + star + 2;
    auto [end, error] = std::from_chars(begin, line.data() + line.size(), crc, 16);
    if (error != std::errc{} || end != line.data() + line.size()) return std::nullopt;
    const std::string_view payload = line.substr(0, star);
    if (crc32(payload) != crc) return std::nullopt;
    return payload;
}

std::vector<std::string_view> words_of(std::string_view text) {
    std::vector<std::string_view> words;
    std::size_t i = 0;
    while (i < text.size()) {
        const std::size_t next = std::min(text.find(' ', i), text.size());
        if (next > i) words.push_back(text.substr(i, next - i));
        i = next + 1;
    }
    return words;
}

template <typename T>
bool parse_number(std::string_view text, T& value) {
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    return error == std::errc{} && end == text.data() + text.size();
}

//! "#500=1.25" or "#500=-" (vacant); "#5221=10" in the LinuxCNC dialect.
bool parse_retained(std::string_view word, int& number, std::optional<double>& value) {
    const std::size_t eq = word.find('=');
    if (word.size() < 4 || word[0] != '#' || eq == std::string_view::npos) return false;
    // #500-#999, or in the LinuxCNC dialect its persistent parameters (#1-#5601).
    if (!parse_number(word.substr(1, eq - 1), number) || number < 1 || number > 5601) return false;
    const std::string_view text = word.substr(eq + 1);
    if (text == "-") {
        value.reset();
        return true;
    }
    double v = 0;
    if (!parse_number(text, v)) return false;
    value = v;
    return true;
}

std::optional<JournalHeader> parse_header(std::string_view payload) {
    const std::vector<std::string_view> w = words_of(payload);
    JournalHeader h;
    int version = 0;
    if (w.size() < 5 || w[0] != "nckit-journal" || !parse_number(w[1], version) || version != journal_format_version ||
        !parse_number(w[2], h.program_bytes)) {
        return std::nullopt;
    }
    auto [end, error] = std::from_chars(w[3].data(), w[3].data() + w[3].size(), h.program_crc, 16);
    if (error != std::errc{} || end != w[3].data() + w[3].size()) return std::nullopt;
    h.axes = std::string(w[4]);
    for (std::size_t i = 5; i < w.size(); ++i) {
        int number = 0;
        std::optional<double> value;
        if (!parse_retained(w[i], number, value) || !value) return std::nullopt;
        h.retained_start.push_back({number, *value});
    }
    return h;
}

std::optional<JournalBlock> parse_block(std::string_view payload, const std::string& axes) {
    const std::vector<std::string_view> w = words_of(payload);
    JournalBlock b;
    if (w.size() < 5 || w[0] != "B" || !parse_number(w[1], b.block) || !parse_number(w[2], b.line) ||
        !parse_number(w[3], b.sequence_number)) {
        return std::nullopt;
    }
    std::size_t i = 4;
    if (w[i] == "-") {
        ++i;
    } else {
        std::vector<double> at;
        for (char axis : axes) {
            if (i >= w.size() || w[i].size() < 3 || w[i][0] != axis || w[i][1] != '=') return std::nullopt;
            double v = 0;
            if (!parse_number(w[i].substr(2), v)) return std::nullopt;
            at.push_back(v);
            ++i;
        }
        b.position = std::move(at);
    }
    for (; i < w.size(); ++i) {
        int number = 0;
        std::optional<double> value;
        if (!parse_retained(w[i], number, value)) return std::nullopt;
        b.retained_changes.emplace_back(number, value);
    }
    return b;
}

}  // namespace

Result<JournalContents> read_journal(const std::filesystem::path& path) {
    auto unreadable = [&](const std::string& why) {
        return Result<JournalContents>(error_at(make_location(std::make_shared<const std::string>(path.string()), 1, 1),
                                                "journal-unreadable", why));
    };
    std::ifstream in(path, std::ios::binary);
    if (!in) return unreadable("cannot open the run journal");
    JournalContents contents;
    std::map<int, double> retained;
    std::string line;
    std::uint64_t offset = 0;
    bool have_header = false;
    char ch = 0;
    // One record at a time, each at most max_record_bytes: a damaged tail cannot fill memory.
    for (;;) {
        line.clear();
        bool ended = false;
        while (in.get(ch)) {
            if (ch == '\n') {
                ended = true;
                break;
            }
            if (line.size() == max_record_bytes) break;
            line += ch;
        }
        if (!ended) break;  // torn, overlong or the end of the file
        const std::optional<std::string_view> payload = checked_payload(line);
        if (!payload) break;
        if (!have_header) {
            std::optional<JournalHeader> header = parse_header(*payload);
            if (!header) break;
            contents.header = std::move(*header);
            for (const RetainedVariable& v : contents.header.retained_start) retained[v.number] = v.value;
            have_header = true;
        } else {
            std::optional<JournalBlock> block = parse_block(*payload, contents.header.axes);
            if (!block || block->block != contents.records + 1) break;
            for (const auto& [number, value] : block->retained_changes) {
                if (value) {
                    retained[number] = *value;
                } else {
                    retained.erase(number);
                }
            }
            contents.last = std::move(*block);
            ++contents.records;
        }
        offset += line.size() + 1;
    }
    if (!have_header) return unreadable("the run journal has no complete first record: the run had not begun");
    std::error_code error;
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    contents.ignored_bytes = !error && size > offset ? size - offset : 0;
    for (const auto& [number, value] : retained) contents.retained_at_last.push_back({number, value});
    return contents;
}

}  // namespace nckit
