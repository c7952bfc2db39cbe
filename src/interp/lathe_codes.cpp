#include "lathe_codes.hpp"

#include <array>

#include <fmt/format.h>

namespace nckit::interp {

namespace {

//! One function and its number in each system; -1 where the system has no code for it.
struct CodeRow {
    GCode internal;
    std::array<GCode, 3> written;  // A, B, C
};

// Fanuc's table of lathe G codes, where the systems differ (docs/gcode-lathe.md).
constexpr std::array rows{
    CodeRow{lathe_turning_cycle, {g(90), g(77), g(20)}},
    CodeRow{lathe_threading_cycle, {g(92), g(78), g(21)}},
    CodeRow{lathe_facing_cycle, {g(94), g(79), g(24)}},
    CodeRow{lathe_finish, {g(70), g(70), g(72)}},
    CodeRow{lathe_rough_turning, {g(71), g(71), g(73)}},
    CodeRow{lathe_rough_facing, {g(72), g(72), g(74)}},
    CodeRow{lathe_pattern_repeat, {g(73), g(73), g(75)}},
    CodeRow{lathe_face_grooving, {g(74), g(74), g(76)}},
    CodeRow{lathe_od_grooving, {g(75), g(75), g(77)}},
    CodeRow{lathe_thread_repeat, {g(76), g(76), g(78)}},
    CodeRow{g(94), {g(98), g(94), g(94)}},  // feed per minute
    CodeRow{g(95), {g(99), g(95), g(95)}},  // feed per revolution
    CodeRow{g(50), {g(50), g(92), g(92)}},  // coordinate setting, spindle clamp
    CodeRow{g(90), {-1, g(90), g(90)}},     // absolute (system A: X Z)
    CodeRow{g(91), {-1, g(91), g(91)}},     // incremental (system A: U W)
    CodeRow{g(98), {-1, g(98), g(98)}},     // drilling: back to the initial level
    CodeRow{g(99), {-1, g(99), g(99)}},     // drilling: back to the R level
    CodeRow{g(20), {g(20), g(20), g(70)}},  // inch
    CodeRow{g(21), {g(21), g(21), g(71)}},  // metric
};

std::size_t column_of(GCodeSystem system) {
    return system == GCodeSystem::a ? 0 : system == GCodeSystem::b ? 1 : 2;
}

char system_letter(GCodeSystem system) {
    return "ABC"[column_of(system)];
}

std::string plain_name(GCode code) {
    return code % 10 == 0 ? fmt::format("G{}", code / 10) : fmt::format("G{}.{}", code / 10, code % 10);
}

}  // namespace

LatheCode read_lathe_code(GCodeSystem system, GCode written) {
    if (system == GCodeSystem::none) return LatheCode{written, {}};
    const std::size_t column = column_of(system);
    for (const CodeRow& row : rows) {
        if (row.written[column] == written) return LatheCode{row.internal, {}};
    }
    // A number the table gives another function in some system and none in this one.
    for (const CodeRow& row : rows) {
        for (GCode other : row.written) {
            if (other != written) continue;
            std::string hint;
            if (system == GCodeSystem::a && (written == g(90) || written == g(91))) {
                hint = ": X Z are absolute, U W incremental";
            } else if (system == GCodeSystem::a && (written == g(95))) {
                hint = ": G99 is feed per revolution, G98 feed per minute";
            }
            return LatheCode{-1, fmt::format("{} does not exist in lathe G-code system {}{}", plain_name(written),
                                             system_letter(system), hint)};
        }
    }
    return LatheCode{written, {}};
}

std::string lathe_code_name(GCodeSystem system, GCode internal) {
    if (system != GCodeSystem::none) {
        for (const CodeRow& row : rows) {
            if (row.internal == internal && row.written[column_of(system)] >= 0) {
                return plain_name(row.written[column_of(system)]);
            }
        }
    }
    return plain_name(internal);
}

}  // namespace nckit::interp
