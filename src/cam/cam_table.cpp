#include "nckit/cam/cam_table.hpp"

#include <array>
#include <bit>
#include <cmath>
#include <stdexcept>

namespace nckit::cam {

namespace {

// Difference steps in cell units: small enough that the truncation error (step² times the
// third derivative) is far below a nanometre, large enough that rounding of values near 100 mm,
// divided by the step, stays there too. The cross derivative divides by a product of two steps,
// so it takes the larger one.
constexpr double slope_step = 1e-3;
constexpr double twist_step = 1e-2;

//! Where the table is checked along a cell edge, and inside a cell in each direction.
constexpr std::array<double, 5> edge_points{1.0 / 6, 2.0 / 6, 3.0 / 6, 4.0 / 6, 5.0 / 6};
constexpr std::array<double, 3> interior_points{0.25, 0.5, 0.75};

//! Margin for the change of the fourth derivative within a cell (the error's peak is sampled
//! at the cell's middle) and the rounding floor of an evaluation near 100 mm.
constexpr double bound_factor = 1.5;
constexpr double rounding_mm = 1e-12;

//! f and its derivatives in cell units (d/dt = h_θ d/dθ, d/ds = h_z d/dz) at one node. Z
//! derivatives are taken one-sided, from the cell below and from the cell above, each by a
//! second-order difference that stays inside that cell: a drawing given by formulas on Z
//! intervals may bend at an interval end, which the table puts on a node; each cell then
//! sees only its own formula, and the table never evaluates f outside its Z range.
struct NodeData {
    double f = 0, ft = 0;
    double fs_below = 0, fts_below = 0;  //!< d/ds and d²/dt ds from the cell below
    double fs_above = 0, fts_above = 0;  //!< from the cell above
};

//! Corner data of one cell: its value, θ slope, and the Z slopes seen from inside the cell.
struct Corner {
    double f = 0, ft = 0, fs = 0, fts = 0;
};

Corner bottom_corner(const NodeData& n) {
    return {n.f, n.ft, n.fs_above, n.fts_above};
}
Corner top_corner(const NodeData& n) {
    return {n.f, n.ft, n.fs_below, n.fts_below};
}

//! The bicubic whose corner values and cell-unit derivatives are the nodes' (Hermite data):
//! C = M G Mᵀ, M the cubic Hermite matrix, G the 4 × 4 corner data.
void patch(const Corner& n00, const Corner& n10, const Corner& n01, const Corner& n11, double* out) {
    // Rows: θ data (value at t=0, at t=1, slope at t=0, at t=1); columns the same for s.
    const double g[4][4] = {{n00.f, n01.f, n00.fs, n01.fs},
                            {n10.f, n11.f, n10.fs, n11.fs},
                            {n00.ft, n01.ft, n00.fts, n01.fts},
                            {n10.ft, n11.ft, n10.fts, n11.fts}};
    constexpr double m[4][4] = {{1, 0, 0, 0}, {0, 0, 1, 0}, {-3, 3, -2, -1}, {2, -2, 1, 1}};
    double mg[4][4] = {};
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            for (int k = 0; k < 4; ++k) mg[i][j] += m[i][k] * g[k][j];
        }
    }
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
            double c = 0;
            for (int k = 0; k < 4; ++k) c += mg[i][k] * m[j][k];
            out[4 * i + j] = c;  // multiplies t^i s^j
        }
    }
}

}  // namespace

CamTable CamTable::build(const CamFunction& f, const CamTableOptions& options) {
    if (!std::isfinite(options.z_from_mm) || !std::isfinite(options.z_to_mm) || options.z_to_mm < options.z_from_mm) {
        throw std::invalid_argument("CamTable needs a finite z range with z_to >= z_from");
    }
    if (!(options.tolerance_mm > 0)) throw std::invalid_argument("CamTable tolerance must be > 0");
    CamTable table;
    table.z_from_mm_ = options.z_from_mm;
    table.z_to_mm_ = options.z_to_mm;
    table.tolerance_mm_ = options.tolerance_mm;
    const bool flat_z = options.z_to_mm == options.z_from_mm;
    std::size_t theta_cells = std::bit_ceil(std::max<std::size_t>(options.min_theta_cells, 4));
    std::size_t z_cells = flat_z ? 1 : std::max<std::size_t>(options.min_z_cells, 1);
    const std::size_t max_cells = std::max(options.max_cells, theta_cells * z_cells);
    while (true) {
        table.theta_cells_ = theta_cells;
        table.theta_mask_ = theta_cells - 1;
        table.z_cells_ = z_cells;
        table.theta_cells_per_deg_ = static_cast<double>(theta_cells) / 360.0;
        table.z_cells_per_mm_ = flat_z ? 0.0 : static_cast<double>(z_cells) / (options.z_to_mm - options.z_from_mm);
        table.z_top_ = static_cast<double>(z_cells);
        table.z_last_ = static_cast<std::int64_t>(z_cells) - 1;
        table.tabulate(f);
        const Check seen = table.check(f);
        table.checked_error_mm_ = std::max({seen.along_theta_mm, seen.along_z_mm, seen.interior_mm});
        table.error_bound_mm_ = bound_factor * table.checked_error_mm_ + rounding_mm;
        if (table.meets_tolerance()) break;
        // A direction whose edges are already well inside the tolerance keeps its cells; if
        // only the inside of the cells is off, refine the direction with the larger edge error.
        const double quarter = options.tolerance_mm / 4;
        bool more_theta = seen.along_theta_mm > quarter;
        bool more_z = !flat_z && seen.along_z_mm > quarter;
        if (!more_theta && !more_z) {
            more_theta = flat_z || seen.along_theta_mm >= seen.along_z_mm;
            more_z = !more_theta;
        }
        if (more_theta && more_z && 4 * theta_cells * z_cells > max_cells) {
            more_theta = seen.along_theta_mm >= seen.along_z_mm;
            more_z = !more_theta;
        }
        const std::size_t next_theta = more_theta ? 2 * theta_cells : theta_cells;
        const std::size_t next_z = more_z ? 2 * z_cells : z_cells;
        if (next_theta * next_z > max_cells) break;
        theta_cells = next_theta;
        z_cells = next_z;
    }
    return table;
}

void CamTable::tabulate(const CamFunction& f) {
    const std::size_t columns = theta_cells_;  // θ nodes: the turn wraps, node n is node 0
    const bool flat_z = !(z_cells_per_mm_ > 0);
    const std::size_t rows = flat_z ? 1 : z_cells_ + 1;
    const double h_theta = 360.0 / static_cast<double>(theta_cells_);
    const double h_z = flat_z ? 0.0 : 1.0 / z_cells_per_mm_;
    const double dt = slope_step * h_theta;
    const double tt = twist_step * h_theta;
    // d/ds by (−3 f(0) + 4 f(±δ) − f(±2δ)) / (±2δ); `sign` +1 looks up, −1 down.
    auto z_slope = [&](double theta, double z, double sign) {
        const double dz = sign * slope_step * h_z;
        return sign * (-3.0 * f(theta, z) + 4.0 * f(theta, z + dz) - f(theta, z + 2 * dz)) / (2 * slope_step);
    };
    auto twist = [&](double theta, double z, double sign) {
        const double tz = sign * twist_step * h_z;
        auto at = [&](double th) { return -3.0 * f(th, z) + 4.0 * f(th, z + tz) - f(th, z + 2 * tz); };
        return sign * (at(theta + tt) - at(theta - tt)) / (4 * twist_step * twist_step);
    };
    std::vector<NodeData> nodes(columns * rows);
    for (std::size_t j = 0; j < rows; ++j) {
        // The last row sits exactly on z_to (not z_from + n h, which may round past it).
        const double z = j + 1 == rows && !flat_z ? z_to_mm_ : z_from_mm_ + static_cast<double>(j) * h_z;
        for (std::size_t i = 0; i < columns; ++i) {
            const double theta = static_cast<double>(i) * h_theta;
            NodeData& n = nodes[j * columns + i];
            n.f = f(theta, z);
            if (!std::isfinite(n.f)) {
                throw std::domain_error("CamTable: the function is not finite on its range");
            }
            n.ft = (f(theta + dt, z) - f(theta - dt, z)) / (2 * slope_step);
            if (flat_z) continue;
            if (j > 0) {
                n.fs_below = z_slope(theta, z, -1.0);
                n.fts_below = twist(theta, z, -1.0);
            }
            if (j + 1 < rows) {
                n.fs_above = z_slope(theta, z, 1.0);
                n.fts_above = twist(theta, z, 1.0);
            }
        }
    }
    coefficients_.assign(theta_cells_ * z_cells_ * patch_size, 0.0);
    for (std::size_t j = 0; j < z_cells_; ++j) {
        // With no Z extent the one row of patches is flat in s: both edges are node row 0.
        const std::size_t upper = flat_z ? j : j + 1;
        for (std::size_t i = 0; i < theta_cells_; ++i) {
            const std::size_t next = (i + 1) & theta_mask_;
            patch(bottom_corner(nodes[j * columns + i]), bottom_corner(nodes[j * columns + next]),
                  top_corner(nodes[upper * columns + i]), top_corner(nodes[upper * columns + next]),
                  &coefficients_[(j * theta_cells_ + i) * patch_size]);
        }
    }
}

CamTable::Check CamTable::check(const CamFunction& f) const {
    Check seen;
    const double h_theta = 360.0 / static_cast<double>(theta_cells_);
    const double h_z = z_cells_per_mm_ > 0 ? 1.0 / z_cells_per_mm_ : 0.0;
    const std::size_t rows = h_z > 0 ? z_cells_ + 1 : 1;
    auto z_at = [&](std::size_t j, double s) {
        return std::min(z_from_mm_ + (static_cast<double>(j) + s) * h_z, z_to_mm_);
    };
    auto error = [&](std::size_t i, double t, double z) {
        return std::abs(at_cell(i, t, z) - f((static_cast<double>(i) + t) * h_theta, z));
    };
    for (std::size_t j = 0; j < rows; ++j) {
        const double z = j == z_cells_ ? z_to_mm_ : z_at(j, 0.0);
        for (std::size_t i = 0; i < theta_cells_; ++i) {
            for (double t : edge_points) {
                seen.along_theta_mm = std::max(seen.along_theta_mm, error(i, t, z));
            }
        }
    }
    if (h_z > 0) {
        for (std::size_t j = 0; j < z_cells_; ++j) {
            for (double s : edge_points) {
                const double z = z_at(j, s);
                for (std::size_t i = 0; i < theta_cells_; ++i) {
                    seen.along_z_mm = std::max(seen.along_z_mm, error(i, 0.0, z));
                }
            }
        }
    }
    for (std::size_t j = 0; j < z_cells_; ++j) {
        for (double s : interior_points) {
            const double z = h_z > 0 ? z_at(j, s) : z_from_mm_;
            for (std::size_t i = 0; i < theta_cells_; ++i) {
                for (double t : interior_points) {
                    seen.interior_mm = std::max(seen.interior_mm, error(i, t, z));
                }
            }
        }
    }
    return seen;
}

}  // namespace nckit::cam
