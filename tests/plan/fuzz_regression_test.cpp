// Inputs the planner fuzz target (fuzz/fuzz_planner.cpp) found, as readable programs, checked
// from outside: the sampled trajectory's axis accelerations by finite differences of position.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <variant>
#include <vector>

#include "interpreted_moves.hpp"
#include "nckit/interp/interpreter.hpp"
#include "nckit/plan/path_segment.hpp"
#include "nckit/plan/planner.hpp"

namespace nckit {
namespace {

std::vector<Move> moves_of(const std::string& program, const MachineConfig& machine) {
    return plan_test::interpreted_moves(program, machine, "regression.nc");
}

//! The largest |a| / max_acceleration of any axis, from second differences of the position
//! sampled every h seconds over the whole trajectory (the mean of a over 2h: never above the
//! largest |a| there, so a piece that breaks the limit for longer than a few h shows up).
double worst_acceleration_ratio(const Trajectory& trajectory, const MachineConfig& machine, double h) {
    double worst = 0;
    const double duration = trajectory.duration_s();
    const auto steps = static_cast<long>(duration / h);
    TrajectorySample before = trajectory.sample(0.0);
    TrajectorySample here = trajectory.sample(h);
    for (long k = 2; k <= steps; ++k) {
        const TrajectorySample after = trajectory.sample(static_cast<double>(k) * h);
        for (const AxisConfig& axis : machine.axes) {
            const std::size_t i = index(axis.axis);
            const double a = (after.position[i] - 2 * here.position[i] + before.position[i]) / (h * h);
            worst = std::max(worst, std::abs(a) / axis.max_acceleration);
        }
        before = here;
        here = after;
    }
    return worst;
}

// fuzz_planner found it (fuzz/open_findings/fuzz_planner-acceleration.bin, reduced to its
// three moves): the quintic transition between the two arcs turns Y at 12.2 mm/s with 2.3 times
// the axis's 500 mm/s². Its q''_Y is a cubic in s whose s³ coefficient is rounding noise
// (1e-17); the bound of |q''| solved 3 c3 s² + 2 c2 s + c1 = 0 with the textbook formula,
// which cancels to noise / noise and lost the peak at -c1 / (2 c2), so the bound was 0.005
// where q''_Y reaches 3.7 /mm, and the planner let the transition run far too fast.
TEST(PlannerFuzzRegression, TransitionBetweenArcsKeepsAxisAcceleration) {
    const std::string program =
        "G64 P0.05\n"
        "G0 X72.4 Y-102 Z-25.5\n"
        "G1 Y72.4 Z5.3 F8721\n"
        "G3 X72.4 Y-71.6 R119 F1481\n"
        "G3 X72.4 Y72.4 R119 F8721\n"
        "M30\n";
    MachineConfig machine = default_mill();
    machine.profile = ProfileKind::trapezoid;
    PlanResult plan = plan_moves(moves_of(program, machine), machine);
    ASSERT_TRUE(plan.diagnostics.empty());
    // h = 0.1 ms: the transition lasts about 20 ms; rounding of the positions adds < 1e-5 mm/s².
    EXPECT_LE(worst_acceleration_ratio(plan.trajectory, machine, 1e-4), 1 + 1e-6);
    // The S-curve plan of the same program keeps the limit too.
    machine.profile = ProfileKind::scurve;
    PlanResult smooth = plan_moves(moves_of(program, machine), machine);
    ASSERT_TRUE(smooth.diagnostics.empty());
    EXPECT_LE(worst_acceleration_ratio(smooth.trajectory, machine, 1e-4), 1 + 1e-6);
}

// The same bound on its own: quintics whose s⁵ coefficient is 0 or rounding noise, so q'' is
// (nearly) quadratic with its peak inside; the bound must cover q'' sampled densely.
TEST(PlannerFuzzRegression, QuinticCurvatureBoundHoldsWhenTheQuinticTermVanishes) {
    for (double noise : {0.0, 1.4270623622037443e-17, -3e-15, 1e-12}) {
        PathSegment g;
        g.shape = SegmentShape::quintic;
        g.length = 0.285576;
        g.rate[1] = -0.79709762341242119;
        g.poly[0][1] = 0.0025371868091860757;
        g.poly[1][1] = 19.530062186750602;
        g.poly[2][1] = -34.194177718252682;
        g.poly[3][1] = noise;
        const DerivativeBounds bounds = derivative_bounds(g);
        double sampled = 0;
        for (int k = 0; k <= 10000; ++k) sampled = std::max(sampled, std::abs(point_at(g, g.length * k / 10000).d2[1]));
        EXPECT_GE(bounds.d2[1], sampled) << "s^5 coefficient " << noise;
        EXPECT_GT(sampled, 3.6);
    }
}

}  // namespace
}  // namespace nckit
