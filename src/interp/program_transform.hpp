#pragma once
// Fanuc's programmable coordinate transforms: G51.1/G50.1 mirror, G51/G50 scaling (a factor per
// axis; a negative factor mirrors) and G68/G69 rotation in the plane. They act on the programmed
// point in work coordinates in the order mirror → scale → rotate, before the work offsets are
// added back; an odd number of mirrored axes in an arc's plane turns G2 into G3 and back.
#include <array>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "block_words.hpp"
#include "nckit/interp/arc_geometry.hpp"
#include "nckit/core/axes.hpp"
#include "nckit/interp/move.hpp"

namespace nckit::interp {

class ProgramTransform {
public:
    //! The block sets or cancels a transform (G51, G51.1, G50.1, G68, G69, or G50 alone);
    //! its axis words and I J K P R then belong to it.
    [[nodiscard]] static bool sets_transform(const BlockWords& words);

    //! Reads the block's transform codes. `values` gives an axis word in mm / deg (after units),
    //! `offset` an I J K word as a plain number; `programmed` is the current programmed point in
    //! work coordinates (the default centre). An error names the offending column and message.
    struct Error {
        std::uint32_t column;
        std::string message;
    };
    template <class AxisValue>
    [[nodiscard]] std::optional<Error> apply(const BlockWords& words, Plane plane, const AxisVector& programmed_work,
                                             AxisValue&& axis_value);

    [[nodiscard]] bool active() const { return mirror_on_ || scale_on_ || rotate_on_; }
    //! Work coordinates → transformed work coordinates.
    [[nodiscard]] AxisVector map(const AxisVector& work) const;
    //! Factor of a length in the plane (arcs): nothing when the plane's axes scale unequally.
    [[nodiscard]] std::optional<double> plane_scale(Plane plane) const;
    //! An odd number of the plane's axes mirrored (by G51.1 or a negative scale).
    [[nodiscard]] bool reverses(Plane plane) const;

private:
    std::array<bool, axis_count> mirrored_{};
    AxisVector mirror_at_;
    bool mirror_on_ = false;
    AxisVector scale_center_;
    std::array<double, axis_count> scale_{};
    bool scale_on_ = false;
    Plane rotate_plane_ = Plane::xy;
    double rotate_first_ = 0, rotate_second_ = 0;  //!< centre on the plane's two axes
    double rotate_deg_ = 0;
    bool rotate_on_ = false;
};

template <class AxisValue>
std::optional<ProgramTransform::Error> ProgramTransform::apply(const BlockWords& words, Plane plane,
                                                               const AxisVector& programmed_work,
                                                               AxisValue&& axis_value) {
    const GCode scaling = words.group(ModalGroup::scaling);
    const GCode mirror = words.group(ModalGroup::mirror);
    const GCode rotation = words.group(ModalGroup::rotation);
    auto each_axis = [&](auto&& f) {
        for (std::size_t i = 0; i < axis_count; ++i) {
            const Axis a = static_cast<Axis>(i);
            if (const Word* w = words.word(letter(a))) f(a, axis_value(a, *w));
        }
    };
    if (mirror == g(51, 1)) {
        each_axis([&](Axis a, double v) {
            mirrored_[index(a)] = true;
            mirror_at_[a] = v;
        });
    } else if (mirror == g(50, 1)) {
        bool any = false;
        each_axis([&](Axis a, double) {
            mirrored_[index(a)] = false;
            any = true;
        });
        if (!any) mirrored_.fill(false);
    }
    mirror_on_ = false;
    for (bool m : mirrored_) mirror_on_ = mirror_on_ || m;
    if (scaling == g(51)) {
        scale_center_ = programmed_work;
        each_axis([&](Axis a, double v) { scale_center_[a] = v; });
        const Word* p = words.word('P');
        const bool per_axis = words.has('I') || words.has('J') || words.has('K');
        if ((p == nullptr) == !per_axis) {
            return Error{words.group_column(ModalGroup::scaling),
                         "G51 needs P (one factor) or I J K (a factor per axis X Y Z), not both"};
        }
        scale_.fill(1.0);
        if (p != nullptr) {
            if (p->value <= 0) return Error{p->column, "G51 P must be positive (a negative factor needs I J K)"};
            for (std::size_t i = 0; i < 3; ++i) scale_[i] = p->value;  // X Y Z
        } else {
            for (char c : {'I', 'J', 'K'}) {
                const Word* w = words.word(c);
                if (w == nullptr) continue;
                if (w->value == 0) return Error{w->column, fmt::format("G51 {} is a factor of 0", c)};
                scale_[static_cast<std::size_t>(c - 'I')] = w->value;
            }
        }
        scale_on_ = true;
    } else if (words.group(ModalGroup::non_modal) == g(50) && sets_transform(words)) {
        scale_on_ = false;
    }
    if (rotation == g(68)) {
        const PlaneAxes axes = plane_axes(plane);
        rotate_plane_ = plane;
        rotate_first_ = programmed_work[axes.first];
        rotate_second_ = programmed_work[axes.second];
        each_axis([&](Axis a, double v) {
            if (a == axes.first) rotate_first_ = v;
            if (a == axes.second) rotate_second_ = v;
        });
        const Word* r = words.word('R');
        if (r == nullptr) return Error{words.group_column(ModalGroup::rotation), "G68 needs R (the angle, deg)"};
        rotate_deg_ = r->value;
        rotate_on_ = true;
    } else if (rotation == g(69)) {
        rotate_on_ = false;
    }
    return std::nullopt;
}

}  // namespace nckit::interp
