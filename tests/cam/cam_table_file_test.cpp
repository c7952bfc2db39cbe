#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "nckit/cam/cam_table_csv.hpp"
#include "nckit/cam/cam_table_file.hpp"
#include "nckit/process/piston/piston_job.hpp"

namespace nckit::cam {
namespace {

std::string temp_file(const std::string& name, const std::string& text) {
    const std::filesystem::path path = std::filesystem::temp_directory_path() / ("nckit_cam_file_" + name);
    std::ofstream(path) << text;
    return path.string();
}

PistonJob example_job() {
    Result<PistonJob> job = load_piston_job(std::string(NCKIT_SOURCE_DIR) + "/examples/piston/piston.toml");
    EXPECT_TRUE(job.ok());
    return std::move(job).value();
}

TEST(CamTableFile, ReadsBackWhatPistonWrites) {
    const PistonJob job = example_job();
    std::ostringstream csv;
    write_cam_table_csv(csv, job);
    const Result<CamTableFile> file = read_cam_table_csv(temp_file("piston.csv", csv.str()));
    ASSERT_TRUE(file.ok()) << format_diagnostic(file.diagnostics().front());
    EXPECT_EQ(file->kind(), CamFileKind::radius_by_z);
    ASSERT_EQ(file->z_mm().size(), job.z_mm.size());
    // On the rows the spline gives the file's numbers; between them the drawing to the file's
    // rounding (1e-6 mm, a little more where the spline spreads it).
    for (std::size_t j = 0; j < job.z_mm.size(); ++j) {
        for (int degree = 0; degree < 360; degree += 7) {
            EXPECT_NEAR(file->value_mm(degree, job.z_mm[j]), file->value_at_station(j, degree), 1e-12);
        }
    }
    for (double z = -3.0; z <= 53.0; z += 0.37) {
        for (double theta = -30.0; theta < 400.0; theta += 3.3) {
            const double zc = std::clamp(z, 0.0, 50.0);
            EXPECT_NEAR(file->value_mm(theta, zc), job.profile(theta, zc), 2e-6) << theta << " " << z;
        }
    }
    const CamTable table = build_cam_table(*file);
    EXPECT_TRUE(table.meets_tolerance());
    for (double z = 0.0; z <= 50.0; z += 0.91) {
        for (double theta = 0.0; theta < 360.0; theta += 0.77) {
            ASSERT_NEAR(table(theta, z), file->value_mm(theta, z), table.error_bound_mm());
        }
    }
}

TEST(CamTableFile, ReadsTheEccentricTableAsAFunctionOfTheAngle) {
    std::string text = "theta_deg,x_diameter_mm\n";
    for (int d = 0; d < 360; ++d)
        text += std::to_string(d) + "," + std::to_string(40.0 + 2.0 * std::cos(d * std::numbers::pi / 180)) + "\n";
    const Result<CamTableFile> file = read_cam_table_csv(temp_file("eccentric.csv", text));
    ASSERT_TRUE(file.ok());
    EXPECT_EQ(file->kind(), CamFileKind::diameter_by_theta);
    const CamTable table = build_cam_table(*file);
    EXPECT_EQ(table.z_from_mm(), table.z_to_mm());
    EXPECT_NEAR(table(45.5, 123.0), 40.0 + 2.0 * std::cos(45.5 * std::numbers::pi / 180), 2e-6);
}

struct BadFile {
    std::string text;
    std::string message;  // FILE:LINE:COL: error: ... after the file name
};

TEST(CamTableFile, RefusesBadFilesAtTheirPlace) {
    auto station = [](double z, int from = 0, int to = 360) {
        std::string s;
        for (int d = from; d < to; ++d) s += std::to_string(z) + "," + std::to_string(d) + ",44.9\n";
        return s;
    };
    const std::string header = "z_mm,phi_deg,radius_mm\n";
    const BadFile cases[] = {
        {"", ":1:1: error: the cam table file is empty"},
        {"x,y\n", ":1:1: error: unknown cam table header 'x,y'"},
        {header, ":1:0: error: the cam table has a header but no rows"},
        {header + "0,0,44.9\n0,1\n", ":3:1: error: expected 3 fields, found 2"},
        {header + "0,0,44.9\n0,1,4x\n", ":3:5: error: '4x' is not a finite number"},
        {header + "0,0,nan\n", ":2:5: error: 'nan' is not a finite number"},
        {header + "0,0,44.9\n0,2,44.9\n", ":3:3: error: angle 2 where degree 1 is due"},
        {header + "0,0,44.9\n1,1,44.9\n", ":3:1: error: z 1 mm changes within the station at 0 mm"},
        {header + station(5) + station(5), ":362:1: error: station z 5 mm does not follow 5 mm upwards"},
        {header + station(0) + station(1, 0, 10),
         ":371:0: error: the last station (z 1 mm) ends after 10 of its 360 rows"},
    };
    int n = 0;
    for (const BadFile& bad : cases) {
        const std::string path = temp_file("bad" + std::to_string(n++) + ".csv", bad.text);
        const Result<CamTableFile> file = read_cam_table_csv(path);
        ASSERT_FALSE(file.ok()) << bad.message;
        EXPECT_NE(format_diagnostic(file.diagnostics().front()).find(path + bad.message), std::string::npos)
            << format_diagnostic(file.diagnostics().front());
    }
    const Result<CamTableFile> missing = read_cam_table_csv("/nonexistent/cam.csv");
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(format_diagnostic(missing.diagnostics().front()),
              "/nonexistent/cam.csv:0:0: error: cannot open the cam table file");
}

}  // namespace
}  // namespace nckit::cam
