// 04: an electronic cam table.
//
// A drawing gives the slaved axis's position r as a function of spindle angle θ (deg) and Z
// (mm). CamTable tabulates it once as bicubic patches refined until a stated error bound holds,
// so the servo loop evaluates it at every encoder count with a few multiply-adds. Here the
// drawing is a formula, as a piston job gives it: an oval of 0.1 mm that grows 2 µm per mm of Z.
#include <array>
#include <cstdio>
#include <variant>

#include "nckit/cam/cam_table.hpp"
#include "nckit/cam/formula.hpp"

int main() {
    // A formula that does not compile is a value saying where, not an exception.
    auto bad = nckit::cam::Formula::compile("0.1*cosd(2*PHI", {"PHI", "Z"});
    if (const auto* error = std::get_if<nckit::cam::FormulaError>(&bad)) {
        std::printf("formula error at byte %zu: %s\n", error->position, error->message.c_str());
    }

    auto compiled = nckit::cam::Formula::compile("0.1*cosd(2*PHI) + 0.002*Z", {"PHI", "Z"});
    if (!std::holds_alternative<nckit::cam::Formula>(compiled)) return 2;
    const nckit::cam::Formula drawing = std::get<nckit::cam::Formula>(std::move(compiled));

    nckit::cam::CamTableOptions options;
    options.z_from_mm = 0;
    options.z_to_mm = 20;
    options.tolerance_mm = 1e-6;  // 1 nm
    const nckit::cam::CamTable table = nckit::cam::CamTable::build(
        [&](double theta_deg, double z_mm) {
            return drawing.evaluate(std::array{theta_deg, z_mm});
        },
        options);

    std::printf("cells: %zu x %zu, %zu bytes, error bound %.3g mm, tolerance met: %s\n", table.theta_cells(),
                table.z_cells(), table.memory_bytes(), table.error_bound_mm(), table.meets_tolerance() ? "yes" : "no");
    // Any angle works (it wraps around the turn); Z outside the table holds its end row.
    std::printf("theta_deg,z_mm,r_mm\n");
    for (double theta : {0.0, 30.0, 45.0, 90.0, 135.0, 400.0, -30.0}) {
        for (double z : {0.0, 7.5, 20.0, 25.0}) std::printf("%g,%g,%.9f\n", theta, z, table(theta, z));
    }
    return 0;
}
