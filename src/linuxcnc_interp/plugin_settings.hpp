#pragma once
// The plug-in's settings, read from the [NCKIT] section of LinuxCNC's INI file.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace nckit::lcnc {

struct PluginSettings {
    std::filesystem::path machine_file;    //!< MACHINE: nckit machine TOML; empty: built-in mill
    std::filesystem::path library_dir;     //!< LIBRARY: called programs, one file per O number
    std::filesystem::path retained_file;   //!< RETAINED: keeps #500-#999 between runs; empty: none
    std::int64_t max_blocks = 10'000'000;  //!< MAX_BLOCKS: runaway budget of loops and calls
    //! G64_TOLERANCE: largest distance from the programmed corner, mm, when the program says G64
    //! without P (LinuxCNC's own G64 without P keeps no bound). 0: no bound.
    double g64_tolerance_mm = 0;
    //! EXACT_PATH = 1: G64 blocks run in LinuxCNC's exact path mode (its G61): no corner blended.
    bool exact_path = false;
    //! TOOL_TABLE, else LinuxCNC's own [EMCIO] TOOL_TABLE: the table H and D words read (and the
    //! lathe's tool offsets); empty: the nckit machine file's tools, if any.
    std::filesystem::path tool_table_file;
    //! [TRAJ] LINEAR_UNITS is inch: LinuxCNC's tool table then holds inches.
    bool tool_table_inch = false;
    //! LINE_COMMENTS = 1: a COMMENT("nckit-line N") before the motions of each source line.
    bool line_comments = false;
    //! JOURNAL: the run journal of each program run (docs/restart.md); empty: none.
    std::filesystem::path journal_file;
    //! JOURNAL_FSYNC_MS: the longest time between a journal record and its fsync, ms.
    std::int64_t journal_fsync_ms = 250;
};

//! The settings from `ini_path`, or an error message naming the file, line and key at fault.
//! Relative paths are taken from the INI file's folder. Without an [NCKIT] section every
//! setting keeps its default.
[[nodiscard]] std::optional<std::string> read_plugin_settings(const std::filesystem::path& ini_path,
                                                              PluginSettings& settings);

}  // namespace nckit::lcnc
