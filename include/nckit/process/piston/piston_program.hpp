#pragma once
// The slide's share of the piston cut as a Fanuc lathe program (`nckit piston --program`).
#include <string>

#include "nckit/process/piston/piston_job.hpp"

namespace nckit {

//! What the program needs beyond the job.
struct PistonProgramOptions {
    int air_turns = 20;  //!< turns the slide waits at the start, as the simulation's air turns
    std::string title;   //!< named in the program's comment (the job file); parentheses dropped
};

//! A Fanuc lathe program in G-code system A (docs/gcode-lathe.md) that moves the slide along the
//! stroke reference (nckit/process/fts/stroke_reference.hpp) from the crown to the skirt at the
//! job's feed per revolution: X the reference's diameter, Z = -(station Z), since the crown faces
//! away from the chuck. The fast tool servo cuts the oval about that path from the cam table.
[[nodiscard]] std::string piston_program(const cam::PistonJob& job, const PistonProgramOptions& options);

}  // namespace nckit
