#pragma once
// Writes a move stream back as a plain RS-274 program: one move per block, absolute machine
// coordinates in mm, no variables, loops or calls. What `nckit expand` prints; LinuxCNC's rs274
// and nckit itself read it back to the same motions.
#include <string>

#include "nckit/core/machine.hpp"
#include "nckit/interp/move.hpp"

namespace nckit {

class GcodeWriter {
public:
    explicit GcodeWriter(const MachineConfig& machine) : machine_(machine) {}

    //! End points with up to 10 decimals instead of 4: a point placed on an oblique line (a
    //! notch's run-up) stays on it within 5e-11 mm instead of bending the line by up to 5e-5 mm.
    void write_precise_positions(bool precise) { precise_positions_ = precise; }

    //! The opening blocks: units, distance mode, plane, offsets cleared, radius mode.
    void append_header(std::string& out, const std::string& source_name) const;

    //! One block for the move, ending in a comment that names its source file and line.
    void append(std::string& out, const Move& move);

    //! M30 unless the stream already ended with M2 or M30.
    void append_footer(std::string& out) const;

private:
    void append_axes(std::string& out, const AxisVector& position) const;
    void append_feed(std::string& out, const Feed& feed);
    //! G61 or G64 P before a move whose path control differs from the last one written; a G9
    //! block becomes G61 for that one move, since LinuxCNC has no G9.
    void append_path(std::string& out, const PathControl& path);

    const MachineConfig& machine_;
    Plane plane_ = Plane::xy;
    FeedMode feed_mode_ = FeedMode::per_minute;
    double feed_ = -1;         // the F last written, in its mode's unit
    PathControl path_;         // G64 with no tolerance, as the header sets
    bool ended_ = false;
    bool precise_positions_ = false;
};

}  // namespace nckit
