#pragma once
// What a controller running the interpreter shows beside the moves: the frame the program writes
// its coordinates in (units, work offsets) and its active modes. Moves carry machine coordinates
// in mm; with this view a host can hand them on as the program wrote them (LinuxCNC's canonical
// calls take program coordinates and the offsets separately).
#include <array>
#include <cstddef>

#include "nckit/core/axes.hpp"
#include "nckit/interp/move.hpp"
#include "nckit/interp/transform_view.hpp"

namespace nckit {

struct ModalView {
    double length_factor_mm = 1.0;             //!< mm per program length unit: 25.4 under G20
    std::size_t work_system = 0;               //!< 0..5 for G54..G59
    AxisVector work_offset;                    //!< origin of the active G54..G59 system, machine mm / deg
    std::array<AxisVector, 6> work_offsets{};  //!< all of G54..G59, machine mm / deg
    AxisVector g92_offset;                     //!< G92 / G50 coordinate shift, mm / deg
    AxisVector g52_offset;                     //!< G52 local shift, mm / deg
    Plane plane = Plane::xy;
    bool incremental = false;           //!< G91
    bool arc_centers_absolute = false;  //!< G90.1: I J K name the centre, not its offset
    FeedMode feed_mode = FeedMode::per_minute;
    bool diameter_mode = false;           //!< G7: X words are diameters
    int motion_code = 0;                  //!< active motion G code x 10 (G1 = 10, G33 = 330, G80 = 800)
    PathControl path;                     //!< G61 / G64 P
    double feed = 0;                      //!< mm/min (G94) or mm/rev (G95)
    double spindle_rpm = 0;               //!< commanded rpm under G97
    int spindle_direction = 0;            //!< 1 = M3, -1 = M4, 0 = stopped
    bool constant_surface_speed = false;  //!< G96
    double surface_speed_m_min = 0;       //!< G96 S, m/min
    int tool = 0;                         //!< last T word
    int tool_in_spindle = 0;              //!< the tool M6 put in
    int length_offset_h = 0;              //!< modal H number
    int length_offset_code = 490;         //!< G43 = 430, G44 = 440, G43.1 = 431, G49 = 490
    AxisVector tool_offset;               //!< tool length offset in force, machine mm
    bool cutter_compensation = false;     //!< G41/G42 engaged: a move's end depends on the next
    bool transform_active = false;        //!< G51.1 mirror, G51 scaling or G68 rotation in force
    TransformView transform;              //!< what they are
};

}  // namespace nckit
