#pragma once
// A cam table file read back into the cam engine: the CSV `nckit piston --cam-table` writes
// (`z_mm,phi_deg,radius_mm`: 360 rows, one per whole degree, at each station) or the one
// `nckit eccentric --cam-table` writes (`theta_deg,x_diameter_mm`: 360 rows). A machine that
// follows the spindle with it (the HAL component in hal/) loads it once, at start, through this
// reader; nothing here runs in a servo tick.
#include <cstddef>
#include <string>
#include <vector>

#include "nckit/cam/cam_table.hpp"
#include "nckit/cam/natural_spline.hpp"
#include "nckit/core/result.hpp"

namespace nckit::cam {

//! Rows per station: one per whole degree.
inline constexpr int cam_file_degrees = 360;

//! What the file holds: the radius by Z and angle (piston) or the X diameter by angle alone
//! (eccentric).
enum class CamFileKind { radius_by_z, diameter_by_theta };

//! The file's numbers and the function they define: at each station a periodic cubic spline
//! through the 360 values of the turn, and between stations the natural cubic spline through
//! the stations' values (continued by straight lines beyond the end stations), the rule nckit's
//! drawings use for tables of points. Both are linear in the data, so the value at (θ, z) is
//! Σ_j w_j(z) s_j(θ): w_j the natural spline through the unit vector at station j, s_j station
//! j's periodic spline.
class CamTableFile {
public:
    //! `values_mm[j]` holds station j's 360 values, degree by degree; `z_mm` is strictly
    //! increasing (one station for a θ-only file). Throws std::invalid_argument otherwise (the
    //! reader checks all of it first).
    CamTableFile(CamFileKind kind, std::vector<double> z_mm, std::vector<std::vector<double>> values_mm);

    //! mm, the file's function at `theta_deg` (any finite angle) and `z_mm`.
    [[nodiscard]] double value_mm(double theta_deg, double z_mm) const;
    //! The function as a CamFunction (keeps a reference to this object).
    [[nodiscard]] CamFunction function() const;

    [[nodiscard]] CamFileKind kind() const { return kind_; }
    [[nodiscard]] const std::vector<double>& z_mm() const { return z_mm_; }
    [[nodiscard]] double z_from_mm() const { return z_mm_.front(); }
    [[nodiscard]] double z_to_mm() const { return z_mm_.back(); }
    //! Station j's value at whole degree `degree` (0 .. 359), as read.
    [[nodiscard]] double value_at_station(std::size_t j, int degree) const;

private:
    [[nodiscard]] double station_value(std::size_t j, double theta_deg) const;

    CamFileKind kind_;
    std::vector<double> z_mm_;
    std::vector<std::vector<double>> values_mm_;
    std::vector<std::vector<double>> curvature_;  //!< d²/dθ² (per degree²) at each row
    std::vector<NaturalSpline> z_weights_;        //!< w_j: empty for a single station
};

//! Reads a cam table CSV. Every problem is reported at its place (FILE:LINE:COL), code
//! "cam-file": a missing file, an unknown header, a row with the wrong number of fields, a
//! number that does not parse or is not finite, angles not 0, 1, ..., 359 in order, Z changing
//! within a station, stations not strictly increasing, a last station cut short, no rows, more
//! than max_cam_file_stations stations.
[[nodiscard]] Result<CamTableFile> read_cam_table_csv(const std::string& path);

//! Stations a file may hold (a 50 mm piston at one station per 0.01 mm is 5001).
inline constexpr std::size_t max_cam_file_stations = 100000;

//! The cam engine for the file's function: Z nodes on the stations where they are evenly
//! spaced, refined to `tolerance_mm` (see CamTable). A θ-only file gives a table flat in Z.
[[nodiscard]] CamTable build_cam_table(const CamTableFile& file, double tolerance_mm = 1e-6);

}  // namespace nckit::cam
