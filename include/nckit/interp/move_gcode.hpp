#pragma once
// Writes a move stream back as a plain RS-274 program: one move per block, absolute machine
// coordinates in mm, no variables, loops or calls. What `nckit expand` prints; LinuxCNC's rs274
// and nckit itself read it back to the same motions.
#include <string>

#include "nckit/core/machine.hpp"
#include "nckit/interp/move.hpp"
#include "nckit/interp/transform_view.hpp"

namespace nckit {

//! The G-code that selects `mode` on `machine`: G94/G95, or G98/G99 in lathe G-code system A,
//! where G94 is the facing cycle.
[[nodiscard]] const char* feed_mode_code(FeedMode mode, const MachineConfig& machine);

//! The frame written coordinates are in: program = unmap(machine − origin) / factor on every
//! linear axis (rotary axes: unmap(machine − origin)), where unmap undoes the mirror, scaling
//! and rotation in force; X doubled in diameter mode; incremental: each axis word is the
//! distance from the last point written. The default is the machine frame, absolute, in mm.
struct GcodeFrame {
    AxisVector origin_mm;           //!< machine coordinates of the program's zero
    double length_factor_mm = 1.0;  //!< mm per program length unit: 25.4 under G20
    bool incremental = false;       //!< G91
    bool diameter = false;          //!< X words are diameters (arc centre offsets stay radii)
    TransformView transform;        //!< G51.1 / G51 / G68 the reader has in force
};

class GcodeWriter {
public:
    explicit GcodeWriter(const MachineConfig& machine) : machine_(machine) {}

    //! Coordinates (end points, arc centre offsets) rounded to `decimals` places for a control
    //! that reads fewer; negative (the default): as many decimals as it takes to read back the
    //! very same doubles. Feeds, leads, speeds and times are always written exactly.
    void round_to_decimals(int decimals) { decimals_ = decimals; }
    //! The largest distance between a coordinate written and its exact value so far, mm / deg
    //! (0 unless rounding).
    [[nodiscard]] double worst_deviation_mm() const { return worst_deviation_mm_; }

    //! The opening blocks: units, distance mode, plane, offsets cleared, radius mode.
    void append_header(std::string& out, const std::string& source_name) const;

    //! The modes blocks written by hand before the next move left in force (a restart program's
    //! preamble), so that the next move writes only what differs from them.
    void assume_modes(Plane plane, FeedMode feed_mode, double feed, PathControl path) {
        plane_ = plane;
        feed_mode_ = feed_mode;
        feed_ = feed;
        path_ = path;
    }

    //! Writes the moves from here on in `frame` (feeds and leads in its length unit too); the
    //! tool stands at `position` (machine coordinates), where incremental words start from.
    void use_frame(const GcodeFrame& frame, const AxisVector& position) {
        frame_ = frame;
        last_ = position;
    }
    //! One block for the move, ending in a comment that names its source file and line.
    void append(std::string& out, const Move& move);

    //! M30 unless the stream already ended with M2 or M30.
    void append_footer(std::string& out) const;

private:
    //! `value` in program units; `scale_mm` mm per unit, for the deviation of a rounding.
    void number(std::string& out, char letter, double value, double scale_mm = 1.0);
    [[nodiscard]] double length_factor(Axis axis) const;
    //! A machine point in the frame's program coordinates (before units and diameter).
    [[nodiscard]] AxisVector to_program(const AxisVector& machine) const;
    void append_axes(std::string& out, const AxisVector& position);
    void append_feed(std::string& out, const Feed& feed);
    //! G61 or G64 P before a move whose path control differs from the last one written; a G9
    //! block becomes G61 for that one move, since LinuxCNC has no G9.
    void append_path(std::string& out, const PathControl& path);

    const MachineConfig& machine_;
    Plane plane_ = Plane::xy;
    FeedMode feed_mode_ = FeedMode::per_minute;
    double feed_ = -1;  // the F last written, in its mode's unit
    PathControl path_;  // G64 with no tolerance, as the header sets
    bool ended_ = false;
    int decimals_ = -1;
    double worst_deviation_mm_ = 0;
    GcodeFrame frame_;
    AxisVector last_;  // machine coordinates of the last point written (incremental frames)
};

}  // namespace nckit
