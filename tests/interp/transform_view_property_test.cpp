// TransformView::unmap is the inverse of map for every mirror, scaling (negative factors too)
// and rotation in any plane: what `nckit restart` relies on to write the rest of a run in the
// program's untransformed coordinates and have the reader's transform give the same points.
#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "nckit/interp/transform_view.hpp"

namespace nckit {
namespace {

TransformView random_transform(std::mt19937_64& random) {
    std::uniform_real_distribution<double> coordinate(-200.0, 200.0);
    std::uniform_real_distribution<double> factor(0.05, 4.0);
    std::uniform_int_distribution<int> coin(0, 1);
    TransformView t;
    for (std::size_t i = 0; i < axis_count; ++i) {
        t.mirrored[i] = coin(random) == 1;
        t.mirror_at.value[i] = coordinate(random);
        t.scale_center.value[i] = coordinate(random);
        t.scale[i] = factor(random) * (coin(random) == 1 ? -1.0 : 1.0);
    }
    t.scale_on = coin(random) == 1;
    t.rotate_on = coin(random) == 1;
    const Plane planes[] = {Plane::xy, Plane::zx, Plane::yz};
    t.rotate_plane = planes[std::uniform_int_distribution<int>(0, 2)(random)];
    t.rotate_first = coordinate(random);
    t.rotate_second = coordinate(random);
    t.rotate_deg = std::uniform_real_distribution<double>(-720.0, 720.0)(random);
    return t;
}

TEST(TransformViewProperty, UnmapUndoesMapAndMapUndoesUnmap) {
    std::mt19937_64 random(20261126);
    std::uniform_real_distribution<double> coordinate(-500.0, 500.0);
    for (int trial = 0; trial < 2000; ++trial) {
        const TransformView t = random_transform(random);
        AxisVector p;
        for (double& v : p.value) v = coordinate(random);
        const AxisVector there_and_back = t.unmap(t.map(p));
        const AxisVector back_and_there = t.map(t.unmap(p));
        for (std::size_t i = 0; i < axis_count; ++i) {
            // A few ulp of the largest intermediate (factors down to 0.05 enlarge by 20).
            EXPECT_NEAR(there_and_back.value[i], p.value[i], 1e-9) << "trial " << trial << " axis " << i;
            EXPECT_NEAR(back_and_there.value[i], p.value[i], 1e-9) << "trial " << trial << " axis " << i;
        }
    }
}

TEST(TransformViewProperty, InactiveTransformIsTheIdentity) {
    TransformView t;
    t.scale.fill(3.0);
    t.rotate_deg = 30;  // not on: no effect
    AxisVector p;
    p[Axis::X] = 1.5;
    p[Axis::Z] = -7.25;
    EXPECT_FALSE(t.active());
    EXPECT_EQ(t.map(p), p);
    EXPECT_EQ(t.unmap(p), p);
}

TEST(TransformViewProperty, ReversesCountsMirrorsAndNegativeFactorsInThePlane) {
    TransformView t;
    t.scale.fill(1.0);
    EXPECT_FALSE(t.reverses(Plane::xy));
    t.mirrored[index(Axis::X)] = true;
    EXPECT_TRUE(t.reverses(Plane::xy));
    EXPECT_FALSE(t.reverses(Plane::yz));  // X is not in the YZ plane
    t.scale_on = true;
    t.scale[index(Axis::Y)] = -2.0;
    EXPECT_FALSE(t.reverses(Plane::xy));  // two flips
    EXPECT_TRUE(t.reverses(Plane::yz));
}

}  // namespace
}  // namespace nckit
