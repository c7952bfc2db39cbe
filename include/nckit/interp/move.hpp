#pragma once
#include <cstdint>
#include <variant>

#include "nckit/core/axes.hpp"
#include "nckit/core/source_location.hpp"

namespace nckit {

enum class FeedMode { per_minute, per_revolution };  // G94, G95

//! The programmed feed of a cutting move, converted once from the program's units.
struct Feed {
    FeedMode mode = FeedMode::per_minute;
    double mm_per_min = 0;  //!< mm/min; for G95, mm_per_rev × the commanded rpm (0 if unknown)
    double mm_per_rev = 0;  //!< mm/rev; G95 only
};

//! How the path may pass the end of a move (G61, G64 P, G9).
struct PathControl {
    bool exact_stop = false;  //!< axes come to rest at the end point
    double tolerance_mm = 0;  //!< G64 P: largest allowed distance from the corner; 0 = none given
};

//! G0 (rapid = true) or G1.
struct Line {
    AxisVector from;  //!< machine coordinates, mm / deg
    AxisVector to;
    Feed feed;  //!< unused for rapids
    bool rapid = false;
    PathControl path;
};

enum class Plane { xy, zx, yz };                          // G17, G18, G19
enum class ArcDirection { clockwise, counterclockwise };  // G2, G3

//! G2/G3, including helices (the axis normal to the plane and any other axis move linearly).
struct Arc {
    AxisVector from;
    AxisVector to;
    AxisVector center;  //!< plane axes: centre; other axes: equal to `from`
    Plane plane = Plane::xy;
    ArcDirection direction = ArcDirection::clockwise;
    int full_turns = 0;  //!< extra full turns before reaching `to` (0 for an ordinary arc)
    Feed feed;
    PathControl path;
};

//! G32/G33: a move locked to spindle rotation, `feed.mm_per_rev` is the lead.
struct SyncMove {
    AxisVector from;
    AxisVector to;
    Feed feed;
    //! deg past the spindle's index pulse, in its turning sense, at which the cut starts
    //! (Fanuc's Q: the starts of a multi-start thread lie 360/n apart); [0, 360)
    double start_angle_deg = 0;
};

struct Dwell {
    double seconds = 0;
};

enum class IoKind {
    mcode,          //!< M<number>
    spindle_speed,  //!< S word: new spindle speed (rpm, or m/min under G96)
    tool_select     //!< T word
};

//! An event for the machine's I/O: M-functions, spindle, coolant, laser.
struct Io {
    IoKind kind = IoKind::mcode;
    int number = 0;                       //!< M or T number
    double value = 0;                     //!< rpm for spindle_speed and for M3/M4; m/min under G96
    bool constant_surface_speed = false;  //!< spindle_speed under G96
    double rpm_clamp = 0;                 //!< G50 S limit under G96, rpm; 0 = none
    bool waits = false;                   //!< axes must be at rest before it (exact-stop M-codes, M0/M1/M2/M30)
};

//! One element of the interpreter's output stream, with the block that made it.
struct Move {
    std::variant<Line, Arc, SyncMove, Dwell, Io> what;
    SourceLocation where;
    std::int64_t sequence_number = -1;  //!< the block's N number, -1 when it has none
};

}  // namespace nckit
