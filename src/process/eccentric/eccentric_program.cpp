// nckit eccentric --program: the electronic cam written out as blocks a Fanuc lathe reads. A
// control cannot slave X to every encoder count from a program, but G99 feeds a block in a fixed
// share of a turn: with F = (path length of the block) × 360 / Δθ mm/rev the block lasts Δθ of
// spindle rotation, so block k ends at θ = k·Δθ when the pass starts on the index. The G32
// lead-in gives that start: a threading move waits for the index and its two whole turns end at
// θ = 0 (the macro of examples/eccentric does the same in 5° blocks).
#include "nckit/process/eccentric/eccentric_program.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <fmt/format.h>

#include "nckit/core/format_exact.hpp"

namespace nckit {

namespace {

//! A coordinate as written: 5 decimals (0.01 µm), no "-0.00000".
double written(double value) {
    const double rounded = std::round(value * 1e5) / 1e5;
    return rounded == 0.0 ? 0.0 : rounded;
}

//! A feed as written: the plain decimal that reads back as the same double (no exponent).
std::string feed_text(double value) {
    std::string text;
    append_exact(text, value);
    return text;
}

}  // namespace

Result<std::string> eccentric_program(const EccentricJob& job, const std::string& title) {
    const double length_mm = std::abs(job.z_end_mm - job.z_start_mm);
    const double turns = length_mm / job.feed_mm_rev;
    // A length of whole turns computed a hair over (1.1 / 0.1 = 11.000000000000002) is whole turns.
    const double blocks = std::ceil(turns * eccentric_program_blocks_per_turn - 1e-6);
    if (blocks > eccentric_program_max_blocks) {
        return error_at(job.feed_at, "config-value",
                        fmt::format("--program: {:.0f} turns at {} blocks a turn is {:.0f} blocks, more than {:.0f}",
                                    turns, eccentric_program_blocks_per_turn, blocks, eccentric_program_max_blocks));
    }
    if (written(2.0 * job.feed_mm_rev) == 0.0) {
        return error_at(job.feed_at, "config-value",
                        fmt::format("--program: two turns at {} mm/rev, the lead-in from the spindle index, are "
                                    "shorter than the program's 0.00001 mm",
                                    feed_text(job.feed_mm_rev)));
    }
    const auto count = static_cast<long>(blocks);
    const double direction = job.z_end_mm < job.z_start_mm ? -1.0 : 1.0;
    const double step_deg = 360.0 / eccentric_program_blocks_per_turn;
    const double clear_x = job.blank_diameter_mm + 4.0;
    const auto x_at = [&](double theta_deg) {
        return written(2.0 * eccentric_cam(job, theta_deg * std::numbers::pi / 180.0).radius_mm);
    };

    std::string out = "%\nO1000 (ECCENTRIC SHAFT: X FOLLOWS THE SPINDLE ANGLE, ONE BLOCK A DEGREE)\n";
    out += fmt::format("(nckit eccentric {} --program: e {:g}, r {:g}, nose radius {:g} mm, one pass)\n",
                       comment_text(title), job.eccentricity_mm, job.eccentric_radius_mm, job.nose_radius_mm);
    out += "G18 G21 G40 G97 G99\nT0101\n";
    const double lead_in_z = written(job.z_start_mm - direction * 2.0 * job.feed_mm_rev);
    out += fmt::format("G00 X{:.5f} Z{:.5f}\n", clear_x, lead_in_z);
    out += fmt::format("S{:.0f} M03\n", job.rpm);  // S is a whole number on a Fanuc
    double x = x_at(0.0);
    double z = written(job.z_start_mm);
    out += fmt::format("G00 X{:.5f}\n", x);
    out +=
        fmt::format("G32 Z{:.5f} F{} (two turns from the index: theta 0 at Z start)\n", z, feed_text(job.feed_mm_rev));
    bool first = true;
    double written_deg = 0.0;  // the angle where the last written block ends
    for (long k = 1; k <= count; ++k) {
        // The last block ends at Z end, part of a degree when the length is not whole turns.
        const double theta_deg = k == count ? turns * 360.0 : static_cast<double>(k) * step_deg;
        const double next_x = x_at(std::fmod(theta_deg, 360.0));
        const double next_z = k == count ? written(job.z_end_mm)
                                         : written(job.z_start_mm + direction * job.feed_mm_rev * theta_deg / 360.0);
        // The path of the block in machine terms (X as a radius), from the values as written, so
        // the block lasts its share of the turn as the control reads it. A block the 5 decimals
        // leave in place (a feed of a few nm a turn) joins the next one, and its degree with it.
        const double path_mm = std::hypot((next_x - x) / 2.0, next_z - z);
        if (path_mm == 0.0) continue;
        const double share = (theta_deg - written_deg) / 360.0;
        if (first) out += "G01 ";
        first = false;
        out += fmt::format("X{:.5f} Z{:.5f} F{}\n", next_x, next_z, feed_text(path_mm / share));
        x = next_x;
        z = next_z;
        written_deg = theta_deg;
    }
    out += fmt::format("G00 X{:.5f}\nM05\nM30\n%\n", clear_x);
    return out;
}

}  // namespace nckit
