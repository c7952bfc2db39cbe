#pragma once
// What one block says, sorted by address: its G codes by modal group, its M codes, and at most
// one value for every other letter. Conflicts (two words of one group, a letter twice) are found
// here, before anything in the block runs.
#include <array>
#include <optional>
#include <vector>

#include "nckit/core/diagnostic.hpp"
#include "nckit/core/machine.hpp"
#include "nckit/gcode/block.hpp"

namespace nckit::interp {

//! A G code as ten times its number, so G92.1 is 921 and G1 is 10.
using GCode = int;
constexpr GCode g(int major, int minor = 0) {
    return major * 10 + minor;
}

enum class ModalGroup {
    non_modal,     // G4 G10 G28 G30 G31 G50 G52 G53 G92 G92.1
    exact_stop,    // G9
    motion,        // G0 G1 G2 G3 G32 G33 G80, drilling cycles G73 G74 G76 G81-G89
    plane,         // G17 G18 G19
    distance,      // G90 G91
    feed_mode,     // G94 G95
    units,         // G20 G21
    cutter_comp,   // G40 G41 G42 G41.1 G42.1
    length_comp,   // G43 G44 G43.1 G49
    spindle_mode,  // G96 G97
    work_system,   // G54..G59
    path_control,  // G61 G64
    diameter,      // G7 G8
    scaling,       // G51 (G50 alone cancels it: see program_transform.hpp)
    mirror,        // G50.1 G51.1
    rotation,      // G68 G69
    return_mode,   // G98 G99: where a drilling cycle returns
    arc_distance,  // G90.1 G91.1: I J K absolute or incremental
    count
};
constexpr std::size_t group_count = static_cast<std::size_t>(ModalGroup::count);

enum class MGroup { stopping, tool_change, spindle, coolant, other, count };

struct GWord {
    GCode code = -1;
    std::uint32_t column = 0;
};

struct MWord {
    int code = -1;
    std::uint32_t column = 0;
};

//! Fanuc dialect: a G code of a block that another code of its group, written later, overrides.
struct OverriddenGCode {
    GCode ignored = -1;
    GCode valid = -1;
    std::uint32_t column = 0;  //!< the ignored code's column
};

struct BlockWords {
    std::array<GWord, group_count> gcodes{};  //!< code -1 where the group is absent
    //! Fanuc dialect: G80 was written (group 09 there), kept apart from the group-01 code so the
    //! motion mode that was modal before the cycle comes back. The LinuxCNC dialect keeps G80 in
    //! the motion slot, as its motion mode.
    bool cancels_cycle = false;
    //! Fanuc dialect: codes dropped because a later code of their group is valid (warnings).
    std::vector<OverriddenGCode> overridden;
    std::array<MWord, 5> mcodes{};  //!< in the order written
    std::size_t mcode_count = 0;
    std::array<const Word*, 26> letters{};  //!< every other letter; null where absent

    [[nodiscard]] GCode group(ModalGroup g) const { return gcodes[static_cast<std::size_t>(g)].code; }
    [[nodiscard]] std::uint32_t group_column(ModalGroup g) const { return gcodes[static_cast<std::size_t>(g)].column; }
    //! Lathe G-code system A: U and W are incremental X and Z, kept under X and Z with this flag.
    std::array<bool, 26> incremental_letter{};

    [[nodiscard]] const Word* word(char letter) const { return letters[letter - 'A']; }
    //! The axis letter a written letter stands for: X for U, Z for W under system A.
    [[nodiscard]] char reads_as(char written) const {
        if (!lathe_increments) return written;
        return written == 'U' ? 'X' : written == 'W' ? 'Z' : written;
    }
    bool lathe_increments = false;
    [[nodiscard]] bool has(char letter) const { return word(letter) != nullptr; }
    [[nodiscard]] bool has_m(int code) const;
};

//! G73, G74, G76, G81..G89: the drilling cycles.
[[nodiscard]] constexpr bool is_drilling_cycle(GCode code) {
    return code == g(73) || code == g(74) || code == g(76) || (code >= g(81) && code <= g(89) && code % 10 == 0);
}

[[nodiscard]] MGroup m_group_of(int code);

//! The modal group of a G code nckit knows, or nothing for an unknown code.
[[nodiscard]] std::optional<ModalGroup> group_of(GCode code);

//! Sorts the block's words; the error names the first offending word. Under a lathe G-code system
//! the G codes are read through its table (lathe_codes.hpp) and, in system A, U W as X Z.
//! Two G codes of one modal group: in the Fanuc dialect the last one written is valid (the
//! others land in `overridden`), in the LinuxCNC dialect it is an error; two one-shot codes
//! (G4 G10 G28 G92 ...) are an error in both (docs/gcode.md, "Several G codes of one group").
[[nodiscard]] std::optional<Diagnostic> collect_words(const Block& block, BlockWords& out,
                                                      GCodeSystem system = GCodeSystem::none,
                                                      Dialect dialect = Dialect::fanuc);

}  // namespace nckit::interp
