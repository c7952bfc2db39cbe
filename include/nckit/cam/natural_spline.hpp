#pragma once
#include <cstddef>
#include <span>
#include <vector>

namespace nckit::cam {

//! The cubic spline through (x_i, y_i) with free (natural) ends, y'' = 0 at the first and last
//! point, continued beyond them by straight lines of the end slopes: the drawing rule for
//! tables of points (docs/processes/piston.md). Because y'' is already 0 at the ends, the straight
//! continuation joins with matching value, slope and curvature.
class NaturalSpline {
public:
    //! Throws std::invalid_argument for fewer than 2 points, sizes that differ, x not strictly
    //! increasing or values that are not finite: job readers check all of these first, so a
    //! bad table here is a program error.
    NaturalSpline(std::vector<double> x, std::vector<double> y);

    [[nodiscard]] double value(double x) const;
    //! dy/dx
    [[nodiscard]] double slope(double x) const;
    //! d²y/dx²; 0 on the straight continuations
    [[nodiscard]] double curvature(double x) const;

    [[nodiscard]] std::span<const double> x() const { return x_; }
    [[nodiscard]] std::span<const double> y() const { return y_; }
    //! y'' at each point (0 at both ends)
    [[nodiscard]] std::span<const double> second_derivatives() const { return m_; }

private:
    //! Index of the interval [x_k, x_k+1] holding x (0 or the last one outside the range).
    [[nodiscard]] std::size_t interval(double x) const;

    std::vector<double> x_;
    std::vector<double> y_;
    std::vector<double> m_;  //!< y'' at each point
};

}  // namespace nckit::cam
