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
#include "nckit/interp/transform_view.hpp"

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

    [[nodiscard]] bool active() const { return state_.active(); }
    //! Work coordinates → transformed work coordinates.
    [[nodiscard]] AxisVector map(const AxisVector& work) const { return state_.map(work); }
    //! Factor of a length in the plane (arcs): nothing when the plane's axes scale unequally.
    [[nodiscard]] std::optional<double> plane_scale(Plane plane) const { return state_.plane_scale(plane); }
    //! An odd number of the plane's axes mirrored (by G51.1 or a negative scale).
    [[nodiscard]] bool reverses(Plane plane) const { return state_.reverses(plane); }
    //! The transforms in force, for the modal view.
    [[nodiscard]] const TransformView& view() const { return state_; }

private:
    TransformView state_;
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
            state_.mirrored[index(a)] = true;
            state_.mirror_at[a] = v;
        });
    } else if (mirror == g(50, 1)) {
        bool any = false;
        each_axis([&](Axis a, double) {
            state_.mirrored[index(a)] = false;
            any = true;
        });
        if (!any) state_.mirrored.fill(false);
    }
    if (scaling == g(51)) {
        state_.scale_center = programmed_work;
        each_axis([&](Axis a, double v) { state_.scale_center[a] = v; });
        const Word* p = words.word('P');
        const bool per_axis = words.has('I') || words.has('J') || words.has('K');
        if ((p == nullptr) == !per_axis) {
            return Error{words.group_column(ModalGroup::scaling),
                         "G51 needs P (one factor) or I J K (a factor per axis X Y Z), not both"};
        }
        state_.scale.fill(1.0);
        if (p != nullptr) {
            if (p->value <= 0) return Error{p->column, "G51 P must be positive (a negative factor needs I J K)"};
            for (std::size_t i = 0; i < 3; ++i) state_.scale[i] = p->value;  // X Y Z
        } else {
            for (char c : {'I', 'J', 'K'}) {
                const Word* w = words.word(c);
                if (w == nullptr) continue;
                if (w->value == 0) return Error{w->column, fmt::format("G51 {} is a factor of 0", c)};
                state_.scale[static_cast<std::size_t>(c - 'I')] = w->value;
            }
        }
        state_.scale_on = true;
    } else if (words.group(ModalGroup::non_modal) == g(50) && sets_transform(words)) {
        state_.scale_on = false;
    }
    if (rotation == g(68)) {
        const PlaneAxes axes = plane_axes(plane);
        state_.rotate_plane = plane;
        state_.rotate_first = programmed_work[axes.first];
        state_.rotate_second = programmed_work[axes.second];
        each_axis([&](Axis a, double v) {
            if (a == axes.first) state_.rotate_first = v;
            if (a == axes.second) state_.rotate_second = v;
        });
        const Word* r = words.word('R');
        if (r == nullptr) return Error{words.group_column(ModalGroup::rotation), "G68 needs R (the angle, deg)"};
        state_.rotate_deg = r->value;
        state_.rotate_on = true;
    } else if (rotation == g(69)) {
        state_.rotate_on = false;
    }
    return std::nullopt;
}

}  // namespace nckit::interp
