#pragma once
// The programmable transforms in force (Fanuc G51.1 mirror, G51 scaling, G68 rotation) as a plain
// value: what the interpreter applies to each programmed point, and what a writer of programs
// needs to take a machine point back into the program's own, untransformed coordinates.
#include <array>
#include <optional>

#include "nckit/core/axes.hpp"
#include "nckit/interp/move.hpp"

namespace nckit {

struct TransformView {
    std::array<bool, axis_count> mirrored{};  //!< G51.1: the axis is mirrored about mirror_at
    AxisVector mirror_at;                     //!< work coordinates, mm / deg
    bool scale_on = false;                    //!< G51
    AxisVector scale_center;                  //!< work coordinates, mm / deg
    std::array<double, axis_count> scale{};   //!< factor per axis (X Y Z from P or I J K; others 1)
    bool rotate_on = false;                   //!< G68
    Plane rotate_plane = Plane::xy;
    double rotate_first = 0, rotate_second = 0;  //!< centre on the plane's first and second axis, mm
    double rotate_deg = 0;

    [[nodiscard]] bool mirror_on() const;
    [[nodiscard]] bool active() const { return mirror_on() || scale_on || rotate_on; }
    //! Work coordinates → transformed work coordinates: mirror, then scale, then rotate.
    [[nodiscard]] AxisVector map(const AxisVector& work) const;
    //! The inverse of map(): transformed work coordinates → the programmed point.
    [[nodiscard]] AxisVector unmap(const AxisVector& transformed) const;
    //! Factor of a length in the plane (arcs): nothing when the plane's axes scale unequally.
    [[nodiscard]] std::optional<double> plane_scale(Plane plane) const;
    //! An odd number of the plane's axes mirrored (by G51.1 or a negative scale): G2 ↔ G3.
    [[nodiscard]] bool reverses(Plane plane) const;
};

}  // namespace nckit
