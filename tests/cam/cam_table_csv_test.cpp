#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "nckit/cam/cam_table_csv.hpp"
#include "nckit/process/piston/piston_job.hpp"

namespace nckit::cam {
namespace {

std::vector<std::string> split(const std::string& text, char separator) {
    std::vector<std::string> parts;
    std::string part;
    std::istringstream in(text);
    while (std::getline(in, part, separator)) parts.push_back(part);
    return parts;
}

TEST(CamTableCsv, StationsByWholeDegrees) {
    const Result<PistonJob> job = load_piston_job(std::string(NCKIT_SOURCE_DIR) + "/examples/piston/piston.toml");
    ASSERT_TRUE(job.ok());
    std::ostringstream out;
    write_cam_table_csv(out, *job);
    const std::vector<std::string> lines = split(out.str(), '\n');
    ASSERT_EQ(lines.size(), 1 + 6 * 360u);
    EXPECT_EQ(lines[0], "z_mm,phi_deg,radius_mm");
    EXPECT_EQ(lines[1], "0.000000,0,44.900000");    // D 89.80 / 2 on the major axis
    EXPECT_EQ(lines[91], "0.000000,90,44.700000");  // minus E/2 = 0.2 on the minor axis
    EXPECT_EQ(lines[2160], "50.000000,359,44.959878");
    for (std::size_t i = 1; i < lines.size(); ++i) {
        const std::vector<std::string> cells = split(lines[i], ',');
        ASSERT_EQ(cells.size(), 3u) << lines[i];
        const std::size_t row = i - 1;
        EXPECT_EQ(std::stod(cells[0]), job->z_mm[row / 360]);
        EXPECT_EQ(cells[1], std::to_string(row % 360));
        // Six decimals: the text is the exact radius rounded to 1 nm.
        ASSERT_EQ(cells[2].size() - cells[2].find('.'), 7u) << lines[i];
        EXPECT_NEAR(std::stod(cells[2]), job->profile.radius_mm(static_cast<double>(row % 360), job->z_mm[row / 360]),
                    0.5e-6 + 1e-12);
    }
    EXPECT_EQ(out.str().back(), '\n');
}

TEST(CamTableCsv, AnyFunctionAndStations) {
    std::ostringstream out;
    const std::vector<double> z{-1.5};
    write_cam_table_csv(
        out, [](double phi, double zz) { return phi + zz; }, z);
    const std::vector<std::string> lines = split(out.str(), '\n');
    ASSERT_EQ(lines.size(), 361u);
    EXPECT_EQ(lines[1], "-1.500000,0,-1.500000");
    EXPECT_EQ(lines[360], "-1.500000,359,357.500000");
}

}  // namespace
}  // namespace nckit::cam
