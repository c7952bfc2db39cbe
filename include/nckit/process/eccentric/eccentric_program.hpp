#pragma once
// The eccentric cam as a Fanuc lathe program (`nckit eccentric --program`).
#include <string>

#include "nckit/core/result.hpp"
#include "nckit/process/eccentric/eccentric.hpp"

namespace nckit {

//! Blocks a spindle turn in the program: one a degree. X is linear in the angle over a block, so
//! it leaves the cam by at most max|a''|·Δθ²/8 (e(1 + e/r)·Δθ²/8: 0.13 µm for e 3, r 20).
inline constexpr int eccentric_program_blocks_per_turn = 360;

//! Most blocks a program may have (about 80 MB of text); more is an error at `feed_mm_rev`.
inline constexpr double eccentric_program_max_blocks = 2e6;

//! A Fanuc lathe program in G-code system A (docs/gcode-lathe.md) that turns the job's eccentric
//! in one pass at its rpm and feed: a G32 lead-in of two turns starts the pass on the spindle
//! index (θ = 0 at Z start, as the cam is measured), then G99 G01 blocks every degree with X the
//! cam's diameter X(θ) (the nose radius compensated as in `eccentric_cam`) and the feed per
//! revolution that makes each block last its degree of the turn. `title` is named in a comment.
[[nodiscard]] Result<std::string> eccentric_program(const EccentricJob& job, const std::string& title);

}  // namespace nckit
