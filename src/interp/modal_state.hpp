#pragma once
// The interpreter's memory between blocks: modal codes, offsets, spindle, position.
#include <array>

#include "block_words.hpp"
#include "nckit/core/axes.hpp"
#include "nckit/interp/move.hpp"

namespace nckit::interp {

struct SpindleState {
    double rpm = 0;                  //!< commanded speed under G97, rpm
    int direction = 0;               //!< 1 = M3 (cw), -1 = M4 (ccw), 0 = stopped
    bool constant_surface_speed = false;  //!< G96
    double surface_speed_m_min = 0;  //!< G96 S, m/min
    double rpm_clamp = 0;            //!< G50 S, rpm; 0 = none
};

struct ModalState {
    GCode motion = g(0);            //!< active group-1 code; g(80) = no motion mode
    Plane plane = Plane::xy;
    bool incremental = false;       //!< G91
    FeedMode feed_mode = FeedMode::per_minute;
    double length_factor_mm = 1.0;  //!< mm per program length unit: 25.4 under G20
    std::size_t work_system = 0;    //!< 0..5 for G54..G59
    PathControl path;               //!< G61 / G64 P
    bool diameter_mode = false;     //!< G7 (X words are diameters) / G8
    double feed = 0;                //!< mm/min (G94) or mm/rev (G95), converted to mm
    bool feed_set = false;
    SpindleState spindle;
    int tool = 0;
};

//! Every offset between machine and program coordinates, all in mm / deg.
struct Offsets {
    std::array<AxisVector, 6> work{};  //!< G54..G59, set by G10 L2/L20
    AxisVector g92;                    //!< G92 / G50 coordinate setting
    AxisVector g52;                    //!< G52 local coordinate system

    [[nodiscard]] AxisVector total(std::size_t work_system) const {
        return work[work_system] + g92 + g52;
    }
};

}  // namespace nckit::interp
