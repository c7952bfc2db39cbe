#include "progress.hpp"

#include <cmath>
#include <filesystem>

#include <unistd.h>

#include <fmt/format.h>

namespace nckit::cli {

namespace {
using Clock = std::chrono::steady_clock;
constexpr auto first_draw_after = std::chrono::seconds(1);
constexpr auto redraw_every = std::chrono::milliseconds(250);

std::string grouped(std::int64_t n) {
    std::string digits = fmt::format("{}", n < 0 ? -n : n);
    std::string out;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return n < 0 ? "-" + out : out;
}
}  // namespace

Progress::Progress(std::string what, std::string unit, bool quiet)
    : what_(std::move(what)),
      unit_(std::move(unit)),
      enabled_(!quiet && ::isatty(STDERR_FILENO) == 1),
      start_(Clock::now()),
      last_draw_(start_) {}

void Progress::redraw(std::int64_t count, double fraction_done) {
    const Clock::time_point now = Clock::now();
    if (now - start_ < first_draw_after || now - last_draw_ < redraw_every) return;
    last_draw_ = now;
    const double elapsed_s = std::chrono::duration<double>(now - start_).count();
    std::string line = fmt::format("{}: {} {}, {} {}/s", what_, grouped(count), unit_,
                                   grouped(std::llround(static_cast<double>(count) / elapsed_s)), unit_);
    if (fraction_done > 0 && fraction_done <= 1) {
        const double left_s = elapsed_s * (1.0 - fraction_done) / fraction_done;
        line += fmt::format(", {:.0f} %, {:.0f} s left", 100.0 * fraction_done, std::ceil(left_s));
    }
    // \r and clear-to-end-of-line: one line, redrawn in place.
    fmt::print(stderr, "\r{}\x1b[K", line);
    std::fflush(stderr);
    drawn_ = true;
}

void Progress::finish() {
    if (!drawn_) return;
    fmt::print(stderr, "\r\x1b[K");
    std::fflush(stderr);
    drawn_ = false;
}

void add_quiet_flag(CLI::App& verb, bool& quiet) {
    verb.add_flag("-q,--quiet", quiet, "no progress on stderr (shown only on a terminal, after 1 s)");
}

std::uint64_t regular_file_bytes(const std::string& path) {
    std::error_code ec;
    if (path == "-" || !std::filesystem::is_regular_file(path, ec)) return 0;
    const std::uintmax_t bytes = std::filesystem::file_size(path, ec);
    return ec ? 0 : static_cast<std::uint64_t>(bytes);
}

}  // namespace nckit::cli
