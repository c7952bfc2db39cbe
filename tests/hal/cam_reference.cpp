// nckit's cam evaluation for the HAL tests: reads a cam table CSV as the component does and, for
// each sample line "COUNTS Z CAM" (halsampler's columns), evaluates the cam at the encoder count
// (angle 360 · (COUNTS mod N) / N) and Z held inside the table, by the cam engine (CamTable) and
// by the file's spline itself. Prints JSON: samples, the largest |CAM − engine| and
// |CAM − spline|, and where, and the least and greatest signed CAM − engine: given the servo's
// position in the CAM column, these bound the profile error and their difference is its peak to
// valley. With `centred` the cam is taken about the stroke reference at Z (cam − r(z), r as
// nckit's StrokeReference over the table: what nckit_cam's wanted pin holds, scale 1).
//   cam_reference TABLE.csv COUNTS_PER_REV SAMPLES.txt [centred]
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include "nckit/cam/cam_table_file.hpp"
#include "nckit/process/fts/stroke_reference.hpp"

int main(int argc, char** argv) {
    const bool centred = argc == 5 && std::string(argv[4]) == "centred";
    if (argc != 4 && !centred) {
        std::fprintf(stderr, "usage: cam_reference TABLE.csv COUNTS_PER_REV SAMPLES.txt [centred]\n");
        return 2;
    }
    const nckit::Result<nckit::cam::CamTableFile> file = nckit::cam::read_cam_table_csv(argv[1]);
    if (!file) {
        for (const auto& d : file.diagnostics()) std::fprintf(stderr, "%s\n", nckit::format_diagnostic(d).c_str());
        return 2;
    }
    const nckit::cam::CamTable table = nckit::cam::build_cam_table(*file);
    std::optional<nckit::StrokeReference> stroke;
    if (centred) stroke.emplace(table, nckit::stroke_reference_points(table));
    const std::int64_t n = std::stoll(argv[2]);
    std::ifstream in(argv[3]);
    std::string line;
    long samples = 0;
    double worst_engine = 0.0, worst_spline = 0.0, worst_count = 0.0, worst_z = 0.0;
    double least_signed = 0.0, greatest_signed = 0.0;
    while (std::getline(in, line)) {
        std::istringstream fields(line);
        long long counts = 0;
        double z = 0.0, cam = 0.0;
        if (!(fields >> counts >> z >> cam)) continue;
        const std::int64_t k = ((counts % n) + n) % n;
        const double theta = 360.0 * static_cast<double>(k) / static_cast<double>(n);
        const double held = std::clamp(z, table.z_from_mm(), table.z_to_mm());
        const double reference = stroke ? stroke->radius_mm(held) : 0.0;
        const double signed_engine = cam - (table(theta, held) - reference);
        const double engine = std::abs(signed_engine);
        least_signed = samples == 0 ? signed_engine : std::min(least_signed, signed_engine);
        greatest_signed = samples == 0 ? signed_engine : std::max(greatest_signed, signed_engine);
        const double spline = std::abs(cam - (file->value_mm(theta, held) - reference));
        if (engine > worst_engine) {
            worst_engine = engine;
            worst_count = static_cast<double>(counts);
            worst_z = z;
        }
        worst_spline = std::max(worst_spline, spline);
        ++samples;
    }
    std::printf(
        "{\"samples\":%ld,\"max_engine_error_mm\":%.9g,\"max_spline_error_mm\":%.9g,"
        "\"at_counts\":%.0f,\"at_z_mm\":%.9g,\"min_signed_engine_mm\":%.9g,"
        "\"max_signed_engine_mm\":%.9g}\n",
        samples, worst_engine, worst_spline, worst_count, worst_z, least_signed, greatest_signed);
    return 0;
}
