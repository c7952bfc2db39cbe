#pragma once
// Progress of a long run on stderr: "nckit plan: 1,234,567 blocks, 412,000 blocks/s, 37 %, 3 s
// left". Shown only when stderr is a terminal, the run has taken more than a second and --quiet
// was not given; redrawn at most four times a second on one line, which finish() clears. Any
// verb that reads something big can use it: give it a count and, when known, the fraction done.
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>

#include <CLI/CLI.hpp>

namespace nckit::cli {

class Progress {
public:
    //! `what` names the run ("nckit steps"); `unit` what is counted ("blocks").
    Progress(std::string what, std::string unit, bool quiet);
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;
    ~Progress() { finish(); }

    //! Cheap enough to call for every block: it looks at the clock once every 1024 calls.
    //! `fraction_done` in [0, 1], or negative when the total is not known (a pipe).
    void update(std::int64_t count, double fraction_done = -1.0) {
        if (!enabled_ || (++calls_ & 1023u) != 0) return;
        redraw(count, fraction_done);
    }
    void finish();  //!< clears the line (idempotent)
    [[nodiscard]] bool enabled() const { return enabled_; }

private:
    void redraw(std::int64_t count, double fraction_done);
    std::string what_;
    std::string unit_;
    bool enabled_ = false;
    bool drawn_ = false;
    std::uint32_t calls_ = 0;
    std::chrono::steady_clock::time_point start_;
    std::chrono::steady_clock::time_point last_draw_;
};

//! Adds `--quiet` ("no progress on stderr") to a verb.
void add_quiet_flag(CLI::App& verb, bool& quiet);

//! The size of a regular file in bytes, 0 for "-", a pipe or a device (no fraction then).
[[nodiscard]] std::uint64_t regular_file_bytes(const std::string& path);

}  // namespace nckit::cli
