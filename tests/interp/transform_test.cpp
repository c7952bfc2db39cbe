// Fanuc G51.1/G50.1 mirror, G51/G50 scaling and G68/G69 rotation: the moves of a transformed
// drawing equal the drawing's moves with the transform applied (mirror → scale → rotate), arcs
// turning direction under an odd number of mirrors.
#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "interp_support.hpp"

namespace nckit {
namespace {

using test::error_of;
using test::moves_of;

// A drawing with lines and arcs of both directions, as a subprogram (called by M98 P100).
const std::string drawing = "G1 X20 Y5 F500\nG3 X30 Y15 I0 J10\nG1 X25 Y30\nG2 X10 Y25 R9\nG1 X10 Y12 Z-1\n";

std::string program(const std::string& setup, const std::string& cancel) {
    return "G90 G17 G21\nG0 X0 Y0 Z0\n" + setup + "\nM98 P100\n" + cancel + "\nG0 X0 Y0\nM30\nO100\n" + drawing +
           "M99\n";
}

struct Point {
    double x, y;
};
using Map = Point (*)(Point);

// Moves from the first drawing move on, compared with the plain drawing mapped by `map`.
// G51 P scales Z as well (about the programmed Z, 0 here): z_scale.
void expect_transformed(const std::vector<Move>& got, const std::vector<Move>& plain, Map map, bool swaps,
                        double z_scale = 1.0) {
    ASSERT_EQ(got.size(), plain.size());
    for (std::size_t i = 1; i + 2 < plain.size(); ++i) {  // the drawing: after G0 X0 Y0 Z0, before G0 X0 Y0 and M30
        auto check = [&](const AxisVector& a, const AxisVector& b) {
            const Point p = map({b[Axis::X], b[Axis::Y]});
            EXPECT_NEAR(a[Axis::X], p.x, 1e-9) << i;
            EXPECT_NEAR(a[Axis::Y], p.y, 1e-9) << i;
            EXPECT_NEAR(a[Axis::Z], z_scale * b[Axis::Z], 1e-9) << i;
        };
        if (const auto* arc = std::get_if<Arc>(&got[i].what)) {
            const Arc& ref = std::get<Arc>(plain[i].what);
            check(arc->to, ref.to);
            check(arc->center, ref.center);
            EXPECT_EQ(arc->direction == ref.direction, !swaps) << i;
        } else {
            check(std::get<Line>(got[i].what).to, std::get<Line>(plain[i].what).to);
        }
    }
}

TEST(ProgramTransform, MirrorEqualsTheMirroredDrawingAndSwapsArcDirections) {
    const auto plain = moves_of(program("", ""));
    expect_transformed(
        moves_of(program("G51.1 X10", "G50.1 X0")), plain,
        [](Point p) {
            return Point{20 - p.x, p.y};
        },
        true);
    expect_transformed(
        moves_of(program("G51.1 X10 Y4", "G50.1")), plain,
        [](Point p) {
            return Point{20 - p.x, 8 - p.y};
        },
        false);
}

TEST(ProgramTransform, ScaleEqualsTheScaledDrawingAndANegativeFactorMirrors) {
    const auto plain = moves_of(program("", ""));
    expect_transformed(
        moves_of(program("G51 X5 Y5 P1.5", "G50")), plain,
        [](Point p) {
            return Point{5 + 1.5 * (p.x - 5), 5 + 1.5 * (p.y - 5)};
        },
        false, 1.5);
    expect_transformed(
        moves_of(program("G51 X0 Y0 I-2 J2", "G50")), plain,
        [](Point p) {
            return Point{-2 * p.x, 2 * p.y};
        },
        true);
}

TEST(ProgramTransform, RotationAndTheOrderMirrorScaleRotate) {
    const auto plain = moves_of(program("", ""));
    expect_transformed(
        moves_of(program("G68 X10 Y0 R90", "G69")), plain,
        [](Point p) {
            return Point{10 - p.y, p.x - 10};
        },
        false);
    // Mirror X about 0, then scale by 2 about (0, 0), then rotate 30° about (0, 0).
    expect_transformed(
        moves_of(program("G51.1 X0\nG51 X0 Y0 P2\nG68 X0 Y0 R30", "G69\nG50\nG50.1 X0")), plain,
        [](Point p) {
            const double c = std::cos(std::numbers::pi / 6), s = std::sin(std::numbers::pi / 6);
            const Point q{-2 * p.x, 2 * p.y};
            return Point{c * q.x - s * q.y, s * q.x + c * q.y};
        },
        true, 2.0);
}

TEST(ProgramTransform, PlacedByG52TheTransformActsInTheLocalSystem) {
    // G52 moves the work origin; the mirror line X10 is in local coordinates.
    const auto plain = moves_of(program("G52 X100", ""));
    expect_transformed(
        moves_of(program("G52 X100\nG51.1 X10", "G50.1 X0")), plain,
        [](Point p) {
            return Point{100 + 20 - (p.x - 100), p.y};
        },
        true);
}

TEST(ProgramTransform, CancelledTransformsLeaveTheDrawingAlone) {
    const auto plain = moves_of(program("", ""));
    expect_transformed(
        moves_of(program("G51.1 X10\nG51 X0 Y0 P3\nG68 R45\nG69\nG50\nG50.1", "")), plain, [](Point p) { return p; },
        false);
}

TEST(ProgramTransform, BadTransformsAreLocatedErrors) {
    EXPECT_EQ(error_of(program("G51 X0 Y0 I2 J1", "G50")).code, "bad-transform");  // an arc would be an ellipse
    EXPECT_EQ(error_of("G51 X0 Y0\n").code, "bad-transform");                      // no factor
    const Diagnostic d = error_of("G68 X0 Y0\n");
    EXPECT_EQ(d.code, "bad-transform");
    EXPECT_EQ(d.location.line, 1u);
    EXPECT_EQ(error_of("G51.1 X0\nG28 X1\n").code, "bad-transform");
}

}  // namespace
}  // namespace nckit
