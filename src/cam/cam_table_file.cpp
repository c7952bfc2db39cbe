#include "nckit/cam/cam_table_file.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string_view>
#include <utility>

#include <fmt/format.h>

#include "nckit/cam/piston_cam.hpp"

namespace nckit::cam {

namespace {

//! Gauss-Seidel sweeps for the periodic spline's curvatures: the system's diagonal is twice
//! its off-diagonal sum, so each sweep at least halves the error: 80 sweeps reach 2^-80.
constexpr int spline_sweeps = 80;

//! Curvatures of the periodic cubic spline through `y` at unit spacing (one degree):
//! m[k-1] + 4 m[k] + m[k+1] = 6 (y[k-1] - 2 y[k] + y[k+1]), indices modulo the turn.
std::vector<double> periodic_curvatures(const std::vector<double>& y) {
    const std::size_t n = y.size();
    std::vector<double> rhs(n), m(n, 0.0);
    for (std::size_t k = 0; k < n; ++k) {
        rhs[k] = 6.0 * (y[(k + n - 1) % n] - 2.0 * y[k] + y[(k + 1) % n]);
    }
    for (int sweep = 0; sweep < spline_sweeps; ++sweep) {
        for (std::size_t k = 0; k < n; ++k) {
            m[k] = (rhs[k] - m[(k + n - 1) % n] - m[(k + 1) % n]) / 4.0;
        }
    }
    return m;
}

struct Reader {
    std::shared_ptr<const std::string> file;
    Diagnostics problems;

    void fail(std::uint32_t line, std::uint32_t column, std::string message) {
        problems.push_back(error_at(make_location(file, line, column), "cam-file", std::move(message)));
    }
};

//! The comma-separated fields of `line` with their 1-based columns.
struct Field {
    std::string_view text;
    std::uint32_t column = 1;
};

std::vector<Field> split(std::string_view line) {
    std::vector<Field> fields;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = line.find(',', start);
        const std::size_t end = comma == std::string_view::npos ? line.size() : comma;
        fields.push_back({line.substr(start, end - start), static_cast<std::uint32_t>(start + 1)});
        if (comma == std::string_view::npos) return fields;
        start = comma + 1;
    }
}

bool parse_number(std::string_view text, double& out) {
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, out);
    return ec == std::errc{} && ptr == end && std::isfinite(out);
}

}  // namespace

CamTableFile::CamTableFile(CamFileKind kind, std::vector<double> z_mm, std::vector<std::vector<double>> values_mm)
    : kind_(kind), z_mm_(std::move(z_mm)), values_mm_(std::move(values_mm)) {
    if (z_mm_.empty() || z_mm_.size() != values_mm_.size()) {
        throw std::invalid_argument("a cam file needs one row of values per station");
    }
    for (std::size_t j = 0; j < z_mm_.size(); ++j) {
        if (values_mm_[j].size() != cam_file_degrees) throw std::invalid_argument("a station needs 360 values");
        if (j > 0 && !(z_mm_[j] > z_mm_[j - 1])) throw std::invalid_argument("stations must increase");
        curvature_.push_back(periodic_curvatures(values_mm_[j]));
    }
    if (z_mm_.size() < 2) return;
    for (std::size_t j = 0; j < z_mm_.size(); ++j) {
        std::vector<double> unit(z_mm_.size(), 0.0);
        unit[j] = 1.0;
        z_weights_.emplace_back(z_mm_, std::move(unit));
    }
}

double CamTableFile::station_value(std::size_t j, double theta_deg) const {
    const double turns = theta_deg / cam_file_degrees;
    const double u = (turns - std::floor(turns)) * cam_file_degrees;
    const auto k = std::min(static_cast<std::size_t>(u), std::size_t{cam_file_degrees - 1});
    const std::size_t next = (k + 1) % cam_file_degrees;
    const double t = u - static_cast<double>(k);
    const double s = 1.0 - t;
    const std::vector<double>& y = values_mm_[j];
    const std::vector<double>& m = curvature_[j];
    return s * y[k] + t * y[next] + ((s * s * s - s) * m[k] + (t * t * t - t) * m[next]) / 6.0;
}

double CamTableFile::value_mm(double theta_deg, double z_mm) const {
    if (z_weights_.empty()) return station_value(0, theta_deg);
    double sum = 0.0;
    for (std::size_t j = 0; j < z_mm_.size(); ++j) sum += z_weights_[j].value(z_mm) * station_value(j, theta_deg);
    return sum;
}

CamFunction CamTableFile::function() const {
    return [this](double theta_deg, double z_mm) { return value_mm(theta_deg, z_mm); };
}

double CamTableFile::value_at_station(std::size_t j, int degree) const {
    return values_mm_.at(j).at(static_cast<std::size_t>(degree));
}

Result<CamTableFile> read_cam_table_csv(const std::string& path) {
    Reader reader{std::make_shared<const std::string>(path), {}};
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        reader.fail(0, 0, "cannot open the cam table file");
        return reader.problems;
    }
    std::string line;
    if (!std::getline(in, line)) {
        reader.fail(1, 1, "the cam table file is empty");
        return reader.problems;
    }
    if (!line.empty() && line.back() == '\r') line.pop_back();
    CamFileKind kind{};
    if (line == "z_mm,phi_deg,radius_mm") {
        kind = CamFileKind::radius_by_z;
    } else if (line == "theta_deg,x_diameter_mm") {
        kind = CamFileKind::diameter_by_theta;
    } else {
        reader.fail(1, 1,
                    fmt::format("unknown cam table header '{}': expected 'z_mm,phi_deg,radius_mm' "
                                "(nckit piston --cam-table) or 'theta_deg,x_diameter_mm' "
                                "(nckit eccentric --cam-table)",
                                line.substr(0, 80)));
        return reader.problems;
    }
    const std::size_t columns = kind == CamFileKind::radius_by_z ? 3 : 2;
    std::vector<double> stations;
    std::vector<std::vector<double>> values;
    std::uint32_t number = 1;
    while (std::getline(in, line)) {
        ++number;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty()) continue;
        const std::vector<Field> fields = split(line);
        if (fields.size() != columns) {
            reader.fail(number, 1, fmt::format("expected {} fields, found {}", columns, fields.size()));
            return reader.problems;
        }
        double numbers[3] = {0, 0, 0};
        for (std::size_t i = 0; i < columns; ++i) {
            if (!parse_number(fields[i].text, numbers[i])) {
                reader.fail(number, fields[i].column,
                            fmt::format("'{}' is not a finite number", fields[i].text.substr(0, 40)));
                return reader.problems;
            }
        }
        const double z = columns == 3 ? numbers[0] : 0.0;
        const Field& angle_field = fields[columns - 2];
        const double angle = numbers[columns - 2];
        const double value = numbers[columns - 1];
        const bool new_station = values.empty() || values.back().size() == cam_file_degrees;
        if (new_station) {
            if (kind == CamFileKind::diameter_by_theta && !values.empty()) {
                reader.fail(number, 1, "a theta_deg table holds one turn: 360 rows");
                return reader.problems;
            }
            if (!stations.empty() && !(z > stations.back())) {
                reader.fail(number, 1,
                            fmt::format("station z {} mm does not follow {} mm upwards", z, stations.back()));
                return reader.problems;
            }
            if (stations.size() == max_cam_file_stations) {
                reader.fail(number, 1, fmt::format("more than {} stations", max_cam_file_stations));
                return reader.problems;
            }
            stations.push_back(z);
            values.emplace_back();
            values.back().reserve(cam_file_degrees);
        } else if (z != stations.back()) {
            reader.fail(number, 1,
                        fmt::format("z {} mm changes within the station at {} mm (row {} of its 360)", z,
                                    stations.back(), values.back().size() + 1));
            return reader.problems;
        }
        const auto expected = static_cast<double>(values.back().size());
        if (angle != expected) {
            reader.fail(number, angle_field.column,
                        fmt::format("angle {} where degree {} is due (whole degrees 0 .. 359 in order)", angle,
                                    values.back().size()));
            return reader.problems;
        }
        values.back().push_back(value);
    }
    if (values.empty()) {
        reader.fail(number, 0, "the cam table has a header but no rows");
        return reader.problems;
    }
    if (values.back().size() != cam_file_degrees) {
        reader.fail(number, 0,
                    fmt::format("the last station (z {} mm) ends after {} of its 360 rows", stations.back(),
                                values.back().size()));
        return reader.problems;
    }
    return CamTableFile(kind, std::move(stations), std::move(values));
}

CamTable build_cam_table(const CamTableFile& file, double tolerance_mm) {
    CamTableOptions options = piston_cam_options(file.z_mm(), tolerance_mm);
    // A station per degree has 360 rows: the table starts at 256 cells around the turn.
    options.min_theta_cells = 256;
    return CamTable::build(file.function(), options);
}

}  // namespace nckit::cam
