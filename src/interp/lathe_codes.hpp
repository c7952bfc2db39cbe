#pragma once
// Fanuc's lathe G-code systems A, B and C: the same functions under different numbers. Each code
// a lathe program writes is read here into one internal code per function, so the executor sees
// one set whatever the system: feed per minute / revolution are G94 / G95, coordinate setting
// and the spindle clamp G50, and the lathe cycles codes of their own (above any written number).
#include <optional>
#include <string>

#include "block_words.hpp"
#include "nckit/core/machine.hpp"

namespace nckit::interp {

// The lathe cycles, by function. Written G numbers stop below 1000, so these cannot be written.
inline constexpr GCode lathe_turning_cycle = g(1090);    // A G90, B G77, C G20
inline constexpr GCode lathe_threading_cycle = g(1092);  // A G92, B G78, C G21
inline constexpr GCode lathe_facing_cycle = g(1094);     // A G94, B G79, C G24
inline constexpr GCode lathe_finish = g(1070);           // A/B G70, C G72
inline constexpr GCode lathe_rough_turning = g(1071);    // A/B G71, C G73
inline constexpr GCode lathe_rough_facing = g(1072);     // A/B G72, C G74
inline constexpr GCode lathe_pattern_repeat = g(1073);   // A/B G73, C G75
inline constexpr GCode lathe_face_grooving = g(1074);    // A/B G74, C G76
inline constexpr GCode lathe_od_grooving = g(1075);      // A/B G75, C G77
inline constexpr GCode lathe_thread_repeat = g(1076);    // A/B G76, C G78

[[nodiscard]] constexpr bool is_lathe_single_cycle(GCode code) {
    return code == lathe_turning_cycle || code == lathe_threading_cycle || code == lathe_facing_cycle;
}
[[nodiscard]] constexpr bool is_lathe_repetitive_cycle(GCode code) {
    return code >= lathe_finish && code <= lathe_thread_repeat;
}

//! What a written code means in `system`: the internal code, or an error message when the
//! system has no such code (G91 in system A).
struct LatheCode {
    GCode code = -1;
    std::string refusal;  //!< non-empty: the code does not exist in this system
};
[[nodiscard]] LatheCode read_lathe_code(GCodeSystem system, GCode written);

//! The code as the program writes it in `system` (for messages): "G90" for the turning cycle in A.
[[nodiscard]] std::string lathe_code_name(GCodeSystem system, GCode internal);

}  // namespace nckit::interp
