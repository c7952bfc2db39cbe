#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace nckit::cam {

//! A slaved axis position in mm as a function of spindle angle θ (deg) and Z (mm). Periodic
//! in θ with period 360°.
using CamFunction = std::function<double(double theta_deg, double z_mm)>;

struct CamTableOptions {
    double z_from_mm = 0;  //!< mm, first Z the table covers (outside, the end row holds)
    double z_to_mm = 0;    //!< mm, last Z; equal to z_from_mm for a function of θ alone
    //! mm, the interpolation error the table is refined to: 1 nm, a fifteenth of a 16-bit DAC
    //! step over 1 mm, so the table adds nothing a servo could show.
    double tolerance_mm = 1e-6;
    //! Cells around the turn to start from; rounded up to a power of two (the turn wraps
    //! with a mask, no division).
    std::size_t min_theta_cells = 64;
    //! Z cells to start from. Set it so the nodes fall on the drawing's stations where they
    //! are evenly spaced: a spline's pieces then fit cells exactly. Doubled while refining.
    std::size_t min_z_cells = 1;
    //! Refinement stops at this many cells (128 bytes each) even if the tolerance is not met
    //! (a kink or jump in the function); error_bound_mm() then says what was reached.
    std::size_t max_cells = std::size_t{1} << 17;
};

//! The cam engine: f(θ, z) precomputed as bicubic Hermite patches on a uniform grid, periodic
//! in θ, from the function's values and derivatives at the grid nodes (derivatives by
//! differences with steps a thousandth of a cell; in Z one-sided from inside each cell, so a
//! bend of the drawing on a node is followed exactly). An evaluation is a few index operations
//! and 15 multiply-adds on one 128-byte patch, with no branch a cut can mispredict.
//!
//! The stated error bound: after building, the table is compared with the function at 3 × 3
//! points inside every cell (t, s ∈ {1/4, 1/2, 3/4}) and at 5 points along every cell edge. A
//! cubic Hermite piece's error is f⁽⁴⁾ h⁴ t²(1 − t)² / 24, largest at the cell's middle, which
//! is sampled; error_bound_mm() is the largest difference seen times 1.5 (for the change of
//! f⁽⁴⁾ within a cell) plus 1e-12 mm for rounding. Tests check it on random points.
class CamTable {
public:
    //! Tabulates `f` over the turn and [z_from_mm, z_to_mm], doubling the cells in θ and in z
    //! until the stated bound is within the tolerance, or max_cells. A direction is doubled
    //! while its edge error exceeds a quarter of the tolerance (the error falls 16-fold per
    //! doubling), so a smooth f meets it with room to spare.
    //! Throws std::invalid_argument for a non-finite or reversed z range or a tolerance <= 0,
    //! std::domain_error when f is not finite at a node (inputs are validated before this).
    [[nodiscard]] static CamTable build(const CamFunction& f, const CamTableOptions& options);

    //! mm, the tabulated f(θ, z). Any finite θ (wrapped to the turn); z outside the table's
    //! range is clamped to it.
    [[nodiscard]] double operator()(double theta_deg, double z_mm) const {
        const double u = theta_deg * theta_cells_per_deg_;
        auto cell = static_cast<std::int64_t>(u);  // truncates towards zero
        double t = u - static_cast<double>(cell);
        const bool below = t < 0.0;  // negative angles: step back one cell, branch-free
        cell -= static_cast<std::int64_t>(below);
        t += static_cast<double>(below);
        return at_cell(static_cast<std::size_t>(cell) & theta_mask_, t, z_mm);
    }

    //! The same at θ cell `theta_cell` (< theta_cells()) and fraction `t` in [0, 1] through it:
    //! for callers that step through the turn themselves (EncoderCam).
    [[nodiscard]] double at_cell(std::size_t theta_cell, double t, double z_mm) const {
        // Signed conversions and min/max: no branch but the clamp at the table's first row,
        // which a cut inside the drawing never takes, so it is always predicted.
        const double raw = (z_mm - z_from_mm_) * z_cells_per_mm_;
        const double v = std::max(0.0, std::min(raw, z_top_));
        const std::int64_t row = std::min(static_cast<std::int64_t>(v), z_last_);
        const double s = v - static_cast<double>(row);
        const std::size_t cell = static_cast<std::size_t>(row) * theta_cells_ + theta_cell;
        const double* c = &coefficients_[cell * patch_size];
        // Horner in t for the four powers of s side by side (they pack into vector registers),
        // then in s.
        double r[4];
        for (int j = 0; j < 4; ++j) r[j] = c[12 + j];
        for (int j = 0; j < 4; ++j) r[j] = r[j] * t + c[8 + j];
        for (int j = 0; j < 4; ++j) r[j] = r[j] * t + c[4 + j];
        for (int j = 0; j < 4; ++j) r[j] = r[j] * t + c[j];
        return ((r[3] * s + r[2]) * s + r[1]) * s + r[0];
    }

    //! mm: |table − f| stays below this everywhere in the table's range (see the class note).
    [[nodiscard]] double error_bound_mm() const { return error_bound_mm_; }
    //! mm: the largest |table − f| seen on the check points.
    [[nodiscard]] double checked_error_mm() const { return checked_error_mm_; }
    //! mm: the tolerance the table was built for.
    [[nodiscard]] double tolerance_mm() const { return tolerance_mm_; }
    //! Whether the error bound is within the tolerance (false when max_cells stopped it).
    [[nodiscard]] bool meets_tolerance() const { return error_bound_mm_ <= tolerance_mm_; }

    //! Cells around the turn (a power of two).
    [[nodiscard]] std::size_t theta_cells() const { return theta_cells_; }
    //! Cells along Z.
    [[nodiscard]] std::size_t z_cells() const { return z_cells_; }
    [[nodiscard]] double theta_step_deg() const { return 360.0 / static_cast<double>(theta_cells_); }
    [[nodiscard]] double z_from_mm() const { return z_from_mm_; }
    [[nodiscard]] double z_to_mm() const { return z_to_mm_; }
    //! Bytes of patch coefficients.
    [[nodiscard]] std::size_t memory_bytes() const { return coefficients_.size() * sizeof(double); }

    //! Doubles per patch: c[4 i + j] multiplies t^i s^j.
    static constexpr std::size_t patch_size = 16;

private:
    CamTable() = default;
    void tabulate(const CamFunction& f);
    //! Largest |table − f| at 5 points along each θ edge, each Z edge and at 3 × 3 points
    //! inside each cell, kept apart so refinement knows which direction needs cells.
    struct Check {
        double along_theta_mm = 0;  //!< on Z node rows: the θ interpolation alone
        double along_z_mm = 0;      //!< on θ node columns: the Z interpolation alone
        double interior_mm = 0;     //!< inside the cells
    };
    [[nodiscard]] Check check(const CamFunction& f) const;

    std::vector<double> coefficients_;  //!< patch_size per cell, Z row by Z row
    std::size_t theta_cells_ = 0;
    std::size_t theta_mask_ = 0;  //!< theta_cells_ − 1
    std::size_t z_cells_ = 0;
    double theta_cells_per_deg_ = 0;  //!< cells / deg
    double z_cells_per_mm_ = 0;       //!< cells / mm
    double z_top_ = 0;                //!< z_cells_ as a double: the clamp's upper end
    std::int64_t z_last_ = 0;         //!< z_cells_ − 1: the last row
    double z_from_mm_ = 0;            //!< mm
    double z_to_mm_ = 0;              //!< mm
    double tolerance_mm_ = 0;         //!< mm
    double error_bound_mm_ = 0;       //!< mm
    double checked_error_mm_ = 0;     //!< mm
};

}  // namespace nckit::cam
