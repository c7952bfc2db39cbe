#include "nckit/cam/cam_table_csv.hpp"

#include <iterator>
#include <string>

#include <fmt/format.h>

namespace nckit::cam {

void write_cam_table_csv(std::ostream& out, const CamFunction& radius_mm, std::span<const double> z_mm) {
    std::string text = "z_mm,phi_deg,radius_mm\n";
    for (double z : z_mm) {
        for (int phi = 0; phi < 360; ++phi) {
            fmt::format_to(std::back_inserter(text), "{:.{}f},{},{:.{}f}\n", z, cam_csv_decimals, phi,
                           radius_mm(phi, z), cam_csv_decimals);
        }
        out.write(text.data(), static_cast<std::streamsize>(text.size()));
        text.clear();
    }
    if (!text.empty()) out.write(text.data(), static_cast<std::streamsize>(text.size()));
}

}  // namespace nckit::cam
