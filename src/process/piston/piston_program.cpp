// nckit piston --program: the slide's path as a Fanuc lathe program. The fast tool servo cuts the
// oval about the stroke reference, the middle of each turn's radial range, so the slide carries
// the servo along that reference while Z feeds from the crown to the skirt. The program is written
// for the example lathe (examples/machines/lathe.toml): system A, X a diameter, G99 feed per
// revolution, G04 X in seconds, no G90 (system A's turning cycle).
#include "nckit/process/piston/piston_program.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <string>

#include <fmt/format.h>

#include "nckit/core/format_exact.hpp"

#include "nckit/process/fts/stroke_reference.hpp"

namespace nckit {

namespace {

//! mm of Z between the program's points: the stroke reference's own spacing (its spline is
//! within far less than a DAC step of the chord over half a millimetre).
constexpr double point_spacing_mm = 0.5;

//! mm the slide starts before the crown and retracts past the largest diameter.
constexpr double clearance_mm = 1.0;

//! A value as the program writes it: 5 decimals (0.01 um), a decimal point always, no "-0".
std::string number(double value) {
    std::string text;
    append_rounded(text, value, 5);
    return text;
}

}  // namespace

std::string piston_program(const cam::PistonJob& job, const PistonProgramOptions& options) {
    const cam::CamTable table = cam::build_cam_table(job);
    const StrokeReference reference(table, stroke_reference_points(table));
    const double z_from = table.z_from_mm();
    const double z_to = table.z_to_mm();
    // Equal steps of at most point_spacing_mm; the job reader keeps the stations within ±10 m,
    // so there are at most 40,000.
    const auto steps = static_cast<std::size_t>(std::max(1.0, std::ceil((z_to - z_from) / point_spacing_mm - 1e-9)));
    const auto diameter_at = [&](double z) { return 2.0 * reference.radius_mm(z); };
    double largest = 0.0;
    for (std::size_t k = 0; k <= steps; ++k) {
        const double z =
            k == steps ? z_to : z_from + (z_to - z_from) * static_cast<double>(k) / static_cast<double>(steps);
        largest = std::max(largest, diameter_at(z));
    }

    std::string out = "%\nO1000 (OVAL PISTON: THE SLIDE ALONG THE FAST TOOL SERVO'S MID-STROKE)\n";
    out += fmt::format("(nckit piston {} --program: X is the mid-stroke diameter, the servo cuts)\n",
                       comment_text(options.title));
    out += "(the oval about it from the cam table. Z0 is the crown, the skirt towards the chuck.)\n";
    out += "G18 G21 G40 G97 G99\nT0101\n";
    out += fmt::format("G00 X{} Z{}\n", number(largest + 2.0 * clearance_mm), number(clearance_mm - z_from));
    out += fmt::format("G00 X{}\n", number(diameter_at(z_from)));
    out += fmt::format("S{:.0f} M03\n", job.rpm);  // S is a whole number on a Fanuc
    const double settle_s = 60.0 * options.air_turns / job.rpm;
    out += fmt::format("G04 X{:.4f} ({} turns: the servo settles on the oval before the cut)\n", settle_s,
                       options.air_turns);
    out += fmt::format("G01 Z{} F", number(-z_from));
    append_exact(out, job.feed_mm_rev);  // a plain decimal, never an exponent
    out += "\n";
    for (std::size_t k = 1; k <= steps; ++k) {
        const double z =
            k == steps ? z_to : z_from + (z_to - z_from) * static_cast<double>(k) / static_cast<double>(steps);
        out += fmt::format("X{} Z{}\n", number(diameter_at(z)), number(-z));
    }
    out +=
        fmt::format("G00 X{}\nZ{}\nM05\nM30\n%\n", number(largest + 2.0 * clearance_mm), number(clearance_mm - z_from));
    return out;
}

}  // namespace nckit
