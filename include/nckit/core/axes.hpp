#pragma once
#include <array>
#include <cstddef>
#include <optional>
#include <string_view>

namespace nckit {

//! The nine RS-274 axes in their canonical order. Linear axes are in mm, rotary axes in deg.
enum class Axis : std::size_t { X, Y, Z, A, B, C, U, V, W };
inline constexpr std::size_t axis_count = 9;
inline constexpr std::string_view axis_letters = "XYZABCUVW";

[[nodiscard]] constexpr std::size_t index(Axis axis) {
    return static_cast<std::size_t>(axis);
}
[[nodiscard]] constexpr char letter(Axis axis) {
    return axis_letters[index(axis)];
}

//! The axis a word letter names (either case), or nothing.
[[nodiscard]] constexpr std::optional<Axis> axis_from_letter(char c) {
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
    for (std::size_t i = 0; i < axis_count; ++i) {
        if (axis_letters[i] == c) return static_cast<Axis>(i);
    }
    return std::nullopt;
}

//! A value for every axis: a position (mm, deg), an offset, a velocity...
struct AxisVector {
    std::array<double, axis_count> value{};

    [[nodiscard]] constexpr double& operator[](Axis a) { return value[index(a)]; }
    [[nodiscard]] constexpr double operator[](Axis a) const { return value[index(a)]; }
    [[nodiscard]] constexpr double& operator[](std::size_t i) { return value[i]; }
    [[nodiscard]] constexpr double operator[](std::size_t i) const { return value[i]; }

    friend constexpr AxisVector operator+(AxisVector l, const AxisVector& r) {
        for (std::size_t i = 0; i < axis_count; ++i) l.value[i] += r.value[i];
        return l;
    }
    friend constexpr AxisVector operator-(AxisVector l, const AxisVector& r) {
        for (std::size_t i = 0; i < axis_count; ++i) l.value[i] -= r.value[i];
        return l;
    }
    friend constexpr bool operator==(const AxisVector&, const AxisVector&) = default;
};

//! A set of axes, e.g. the axes a machine has or the axes a block names.
class AxisSet {
public:
    constexpr void insert(Axis a) { bits_ |= bit(a); }
    [[nodiscard]] constexpr bool contains(Axis a) const { return (bits_ & bit(a)) != 0; }
    [[nodiscard]] constexpr bool empty() const { return bits_ == 0; }
    friend constexpr bool operator==(AxisSet, AxisSet) = default;

private:
    static constexpr unsigned bit(Axis a) { return 1U << index(a); }
    unsigned bits_ = 0;
};

[[nodiscard]] constexpr bool is_rotary(Axis a) {
    return a == Axis::A || a == Axis::B || a == Axis::C;
}

}  // namespace nckit
