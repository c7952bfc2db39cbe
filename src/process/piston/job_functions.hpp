#pragma once
// Private to nckit_cam: reading the drawing functions of a piston job (D, E, E4 as tables,
// formulas or formula intervals) with a located diagnostic for every problem.
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "nckit/cam/drawing_function.hpp"
#include "nckit/cam/formula.hpp"
#include "nckit/core/toml_table_reader.hpp"

namespace nckit::piston_detail {

// The piston job is written in the cam's vocabulary (drawings, formulas, profiles).
using namespace nckit::cam;

using nckit::core_detail::ConfigSink;
using nckit::core_detail::Need;
using nckit::core_detail::Sign;
using nckit::core_detail::TableReader;

//! The file position of byte `position` of the formula string `node`: exact for a one-line
//! string without escapes (the usual case), else the string's start.
[[nodiscard]] toml::source_region formula_region(const toml::node& node, std::size_t position);

//! The string `node` compiled with `variables`; a syntax error is reported at its column.
[[nodiscard]] std::optional<Formula> read_formula(const toml::node& node, std::string_view key,
                                                  std::vector<std::string> variables, ConfigSink& sink);

//! One [[piston.segment]] as read: a Z interval and formulas for some of the functions.
struct SegmentEntry {
    double z_from_mm = 0;
    double z_to_mm = 0;
    toml::source_region from_region;  //!< where z_from_mm is written
    toml::source_region to_region;
    const toml::table* table = nullptr;  //!< the formulas are compiled per function from here
    bool valid = false;                  //!< both ends read and z_to > z_from
};

//! Every [[piston.segment]] under `piston`, checked on its own (ends, unknown keys).
[[nodiscard]] std::vector<SegmentEntry> read_segments(TableReader& piston, ConfigSink& sink);

//! One drawing function as read, and where the drawing gives it (for later, cross-key errors).
struct FunctionEntry {
    std::optional<DrawingFunction> function;
    toml::source_region where;  //!< the key's value in [piston], or the first segment's
    bool given = false;         //!< the job gives the function at all (even if wrongly)
    //! The values at the stations were each checked where written (a table): the check on
    //! the fine Z grid then only reports the spline's bulges between them.
    const toml::array* table = nullptr;
    std::vector<double> breaks_mm;  //!< interval ends of a segmented function
};

//! The function under `key`: a number (constant), an array of numbers (a table at `stations`),
//! a formula string in Z, or formulas in the [[piston.segment]] intervals, which must cover
//! the stations end to end without gap or overlap and agree where they meet.
[[nodiscard]] FunctionEntry read_function(TableReader& piston, std::string_view key, std::span<const double> stations,
                                          std::span<const SegmentEntry> segments, ConfigSink& sink);

//! The keys a segment may give formulas for.
inline constexpr std::string_view segment_function_keys[] = {"major_diameter_mm", "ovality_mm", "e4_mm"};

}  // namespace nckit::piston_detail
