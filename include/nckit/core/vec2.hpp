#pragma once
// A point or direction in a plane, for the plane geometry of the stages above core (cutter
// radius compensation in the interpreter, the pattern process's curves). Units are the caller's
// (mm in nckit); "left" is counter-clockwise.
#include <cmath>

namespace nckit {

struct Vec2 {
    double x = 0;
    double y = 0;
    friend Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
    friend Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
    friend Vec2 operator*(double k, Vec2 a) { return {k * a.x, k * a.y}; }
    friend bool operator==(Vec2, Vec2) = default;
};

inline double dot(Vec2 a, Vec2 b) {
    return a.x * b.x + a.y * b.y;
}
//! The z component of the 3D cross product: positive when b turns left from a.
inline double cross(Vec2 a, Vec2 b) {
    return a.x * b.y - a.y * b.x;
}
inline double length(Vec2 a) {
    return std::hypot(a.x, a.y);
}
inline Vec2 left_normal(Vec2 a) {
    return {-a.y, a.x};
}
//! a scaled to length 1, or the zero vector for a zero a.
inline Vec2 unit(Vec2 a) {
    const double l = length(a);
    return l > 0 ? (1.0 / l) * a : Vec2{};
}

}  // namespace nckit
