#pragma once
// The interpreter's memory between blocks: modal codes, offsets, spindle, position.
#include <array>

#include "block_words.hpp"
#include "lathe_state.hpp"
#include "nckit/core/axes.hpp"
#include "nckit/interp/move.hpp"

namespace nckit::interp {

struct SpindleState {
    double rpm = 0;                       //!< commanded speed under G97, rpm
    int direction = 0;                    //!< 1 = M3 (cw), -1 = M4 (ccw), 0 = stopped
    bool constant_surface_speed = false;  //!< G96
    double surface_speed_m_min = 0;       //!< G96 S, m/min
    double rpm_clamp = 0;                 //!< G50 S, rpm; 0 = none
};

//! Tool selection and the offsets applied from the tool table.
struct ToolState {
    int selected = 0;           //!< last T word (#4120)
    int in_spindle = 0;         //!< tool put in by M6
    int h_number = 0;           //!< modal H (#4111)
    int d_number = 0;           //!< modal D (#4107)
    GCode length_mode = g(49);  //!< G43, G44, G43.1 or G49
};

//! The modal words of a drilling cycle (G73-G89): kept until G80 or another group-1 code.
struct CycleState {
    bool return_to_initial = true;  //!< G98 (initial level) / G99 (R level)
    bool r_set = false;
    double r_word = 0;  //!< R as programmed, program units converted to mm
    bool z_set = false;
    double z_word = 0;        //!< Z as programmed (converted to mm; incremental or absolute)
    double q_mm = 0;          //!< G73/G83 peck depth, G76/G87 shift
    double p_s = 0;           //!< dwell at the bottom, s
    double initial_z_mm = 0;  //!< machine Z when the cycle started (G98 level)
    bool active = false;      //!< a cycle has run since the last group-1 change
};

struct ModalState {
    GCode motion = g(0);  //!< active group-1 code; g(80) = no motion mode
    //! Fanuc dialect: the group-01 code that was modal when a drilling cycle began; G80 (group 09
    //! there) makes it modal again. The LinuxCNC dialect's G80 is a motion mode of its own.
    GCode motion_before_cycle = g(0);
    Plane plane = Plane::xy;
    bool incremental = false;  //!< G91
    FeedMode feed_mode = FeedMode::per_minute;
    double length_factor_mm = 1.0;  //!< mm per program length unit: 25.4 under G20
    std::size_t work_system = 0;    //!< 0..5 for G54..G59
    PathControl path;               //!< G61 / G64 P
    bool diameter_mode = false;     //!< G7 (X words are diameters) / G8
    double feed = 0;                //!< mm/min (G94) or mm/rev (G95), converted to mm
    bool feed_set = false;
    SpindleState spindle;
    ToolState tool;
    CycleState cycle;
    AxisVector tool_offset;             //!< G43/G44/G43.1 length offset in machine coordinates, mm
    bool arc_centers_absolute = false;  //!< G90.1: I J K are absolute centre coordinates
    int cutter_comp = 0;                //!< 0 = G40, 41 = G41 / G41.1, 42 = G42 / G42.1
    LatheState lathe;                   //!< lathe cycles' modal words (lathe_state.hpp)
};

//! Every offset between machine and program coordinates, all in mm / deg.
struct Offsets {
    std::array<AxisVector, 6> work{};  //!< G54..G59, set by G10 L2/L20
    AxisVector g92;                    //!< G92 / G50 coordinate setting
    AxisVector g52;                    //!< G52 local coordinate system

    [[nodiscard]] AxisVector total(std::size_t work_system) const { return work[work_system] + g92 + g52; }
};

}  // namespace nckit::interp
