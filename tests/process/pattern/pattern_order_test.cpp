// Air times against the planner, the cut order against drawing order and its lower bound, and
// the layout's mirror and scale against the transformed drawing.
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "nckit/plan/path_segment.hpp"
#include "nckit/plan/profile.hpp"
#include "nckit/plan/segment_limits.hpp"
#include "nckit/process/pattern/order_bound.hpp"
#include "nckit/process/pattern/pattern_run.hpp"

namespace nckit::pattern {
namespace {

Result<MachineConfig> stepper_mill() {
    return load_machine_config(std::filesystem::path(NCKIT_SOURCE_DIR) / "examples/pattern/stepper_mill.toml");
}

TEST(PatternAirTime, EqualsThePlannersRestToRestTime) {
    Result<MachineConfig> machine = stepper_mill();
    ASSERT_TRUE(machine);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> d(-120, 120);
    for (ProfileKind kind : {ProfileKind::trapezoid, ProfileKind::scurve}) {
        MachineConfig m = *machine;
        m.profile = kind;
        const AirTimer timer(m);
        for (int i = 0; i < 200; ++i) {
            AxisVector from, to;
            to[Axis::X] = d(rng) * (i % 7 == 0 ? 0.001 : 1);
            to[Axis::Y] = i % 5 == 0 ? 0 : d(rng);
            to[Axis::Z] = i % 3 == 0 ? d(rng) / 20 : 0;
            const PathSegment line = make_line(from, to);
            const ProfileLimits limits = segment_limits(line, m, std::numeric_limits<double>::infinity(), kind);
            const double planned = plan_profile(line.length, 0, 0, limits, kind).duration_s();
            EXPECT_NEAR(timer.rapid_s(to[Axis::X], to[Axis::Y], to[Axis::Z]), planned, 1e-9 * (1 + planned));
        }
    }
}

std::vector<CutEnds> random_cuts(std::size_t n, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> x(0, 250), y(-45, 45), step(-6, 6);
    std::vector<CutEnds> cuts;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2 a{x(rng), y(rng)};
        cuts.push_back(describe_cut(Segment{a, a + Vec2{step(rng), step(rng)}}, 0.005));
    }
    return cuts;
}

TEST(PatternOrder, NeverWorseThanDrawingOrderAndNeverBelowTheBound) {
    Result<MachineConfig> machine = stepper_mill();
    ASSERT_TRUE(machine);
    const OrderCosts costs{AirTimer(*machine), {0.002, 0.002}, {0, 0}};
    for (unsigned seed = 1; seed <= 6; ++seed) {
        const std::vector<CutEnds> cuts = random_cuts(20 + 30 * seed, seed);
        const TourCost drawn = evaluate_tour(cuts, drawing_tour(cuts.size()), costs);
        const OrderResult best = optimise_tour(cuts, costs);
        const TourCost found = evaluate_tour(cuts, best.tour, costs);
        EXPECT_LE(found.total_s(), drawn.total_s() + 1e-12);
        // Every cut exactly once.
        std::vector<std::size_t> order = best.tour.order;
        std::sort(order.begin(), order.end());
        for (std::size_t i = 0; i < order.size(); ++i) EXPECT_EQ(order[i], i);
        const double bound_time =
            air_cost_lower_bound(
                cuts, costs.home, [&](Vec2 a, Vec2 b) { return costs.timer.rapid_s(b - a); }, found.air_time_s)
                .value;
        const double bound_distance =
            air_cost_lower_bound(
                cuts, costs.home, [](Vec2 a, Vec2 b) { return length(b - a); }, found.air_distance_mm)
                .value;
        EXPECT_LE(bound_time, found.air_time_s * (1 + 1e-6));
        EXPECT_LE(bound_distance, found.air_distance_mm * (1 + 1e-6));
        EXPECT_GT(bound_distance, 0.5 * found.air_distance_mm);  // a bound worth reporting
    }
}

// The bound against the true optimum, found by trying every order and direction of 6 cuts.
TEST(PatternOrder, BoundIsBelowTheExactOptimumOfSmallCases) {
    for (unsigned seed = 11; seed <= 20; ++seed) {
        const std::vector<CutEnds> cuts = random_cuts(6, seed);
        auto air = [](Vec2 a, Vec2 b) { return length(b - a); };
        double best = 1e300;
        std::vector<std::size_t> perm{0, 1, 2, 3, 4, 5};
        do {
            for (unsigned flips = 0; flips < 64; ++flips) {
                Vec2 at{0, 0};
                double total = 0;
                for (std::size_t k = 0; k < 6; ++k) {
                    const CutEnds& c = cuts[perm[k]];
                    const bool f = (flips >> k) & 1U;
                    total += air(at, f ? c.end : c.start);
                    at = f ? c.start : c.end;
                }
                best = std::min(best, total + air(at, {0, 0}));
            }
        } while (std::next_permutation(perm.begin(), perm.end()));
        const double bound = air_cost_lower_bound(cuts, {0, 0}, air, best).value;
        EXPECT_LE(bound, best * (1 + 1e-6)) << "seed " << seed;
        EXPECT_GT(bound, 0.6 * best) << "seed " << seed;
    }
}

constexpr const char* job_text = R"(
[pattern]
outline = "unused.csv"
border_width_mm = 3.0
reference_hole_mm = [-140.0, -10.0]
depth_mm = 1.0
feed_mm_min = 300
min_cut_mm = 0.0
[motif]
lines = [[-3.0, -2.0, 0.0, 2.0], [0.0, 2.0, 3.0, -2.0]]
arcs = [[0.0, -5.0, 2.5, 20.0, 140.0]]
splines = [[[-3.0, 4.0], [0.0, 5.5], [3.0, 4.0]]]
[lattice]
spacing_mm = [13.0, 10.0]
row_offset_mm = 4.0
angle_deg = 12.0
origin_mm = [3.0, 2.0]
[series]
base_size = 40
motifs = "scale"
[[series.size]]
size = 43
scale = 1.06
)";

OutlinePoints sole_points() {
    OutlinePoints p;
    for (int i = 0; i < 90; ++i) {
        const double t = 2 * 3.14159265358979323846 * i / 90;
        // An egg-shaped sole, not symmetric across its length axis.
        p.points.push_back({125 * std::cos(t), 42 * std::sin(t) + 6 * std::cos(t) * std::sin(t) + 5});
        p.where.push_back({});
    }
    return p;
}

// Cut end points as an unordered list, sorted, for comparing layouts.
std::vector<std::array<double, 4>> ends_of(const SoleLayout& layout, const Affine& map) {
    std::vector<std::array<double, 4>> out;
    for (const Cut& cut : layout.cuts) {
        Vec2 a = map.apply(point_at(cut.curve, 0));
        Vec2 b = map.apply(point_at(cut.curve, parameter_end(cut.curve)));
        if (std::tie(b.x, b.y) < std::tie(a.x, a.y)) std::swap(a, b);
        out.push_back({a.x, a.y, b.x, b.y});
    }
    std::sort(out.begin(), out.end());
    return out;
}

void expect_same(const std::vector<std::array<double, 4>>& a, const std::vector<std::array<double, 4>>& b) {
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        for (std::size_t k = 0; k < 4; ++k) EXPECT_NEAR(a[i][k], b[i][k], 1e-6) << i;
    }
}

TEST(PatternLayout, MirrorEqualsTheMirroredDrawing) {
    Result<PatternJob> job = parse_pattern_job(job_text, "job.toml");
    ASSERT_TRUE(job);
    const OutlinePoints points = sole_points();
    Result<SoleLayout> right = lay_out_sole(*job, points, *grading_for(*job, 40.0, false));
    Result<SoleLayout> left = lay_out_sole(*job, points, *grading_for(*job, 40.0, true));
    ASSERT_TRUE(right && left);
    ASSERT_GT(right->cuts.size(), 100u);
    // Reflection across the outline's box centre line, in program coordinates.
    const double cy = bounding_box(PlaneCurve(right->outline)).centre().y;
    const Affine reflect{{1, 0, 0, -1}, {0, 2 * cy}};
    expect_same(ends_of(*left, Affine{}), ends_of(*right, reflect));
}

TEST(PatternLayout, ScaledSizeEqualsTheScaledDrawingWhenMotifsScale) {
    // The border keeps its width in every size (like the grooves): only without one is the
    // whole drawing a scaled copy.
    std::string text = job_text;
    text.replace(text.find("border_width_mm = 3.0"), 21, "border_width_mm = 0.0");
    Result<PatternJob> job = parse_pattern_job(text, "job.toml");
    ASSERT_TRUE(job);
    const OutlinePoints points = sole_points();
    Result<SoleLayout> base = lay_out_sole(*job, points, *grading_for(*job, 40.0, false));
    Result<SoleLayout> big = lay_out_sole(*job, points, *grading_for(*job, 43.0, false));
    ASSERT_TRUE(base && big);
    EXPECT_DOUBLE_EQ(big->grading.scale_x, 1.06);
    const Vec2 c = bounding_box(PlaneCurve(base->outline)).centre();
    const Affine scale{{1.06, 0, 0, 1.06}, {c.x - 1.06 * c.x, c.y - 1.06 * c.y}};
    expect_same(ends_of(*big, Affine{}), ends_of(*base, scale));
}

TEST(PatternLayout, GroovesAreSplitAtRegionEdgesAndCutAtTheirRegionsDepth) {
    const std::string text = std::string(job_text) + "[[region]]\nfrom_pct = 0\nto_pct = 40\ndepth_mm = 2.0\n";
    Result<PatternJob> job = parse_pattern_job(text, "job.toml");
    ASSERT_TRUE(job);
    Result<SoleLayout> layout = lay_out_sole(*job, sole_points(), *grading_for(*job, 40.0, false));
    ASSERT_TRUE(layout);
    const Box box = bounding_box(PlaneCurve(layout->outline));
    const double edge = box.low.x + 0.4 * box.size().x;
    int deep = 0, crossing_split = 0;
    for (const Cut& cut : layout->cuts) {
        for (const Vec2& p : polyline(cut.curve, 0.001)) {
            if (cut.depth_mm == 2.0) {
                EXPECT_LE(p.x, edge + 1e-9);
            } else {
                EXPECT_EQ(cut.depth_mm, 1.0);
                EXPECT_GE(p.x, edge - 1e-9);
            }
        }
        const double x0 = point_at(cut.curve, 0).x, x1 = point_at(cut.curve, parameter_end(cut.curve)).x;
        if (std::abs(x0 - edge) < 1e-9 || std::abs(x1 - edge) < 1e-9) ++crossing_split;
        deep += cut.depth_mm == 2.0 ? 1 : 0;
    }
    EXPECT_GT(deep, 20);
    EXPECT_GT(crossing_split, 4);  // grooves really were split at the edge
}

TEST(PatternRun, ProgramStartsOnWholeStepsAndThePlannerAgreesWithTheAirModel) {
    Result<PatternJob> job = parse_pattern_job(job_text, "job.toml");
    Result<MachineConfig> machine = stepper_mill();
    ASSERT_TRUE(job && machine);
    Result<SoleRun> run = run_pattern_sole(*job, sole_points(), *grading_for(*job, 40.0, false), *machine, "test");
    ASSERT_TRUE(run) << format_diagnostic(run.diagnostics()[0]);
    for (const ProgramCut& cut : run->program_cuts) {
        const Vec2 s = point_at(cut.curve, 0);
        EXPECT_NEAR(s.x * 100, std::round(s.x * 100), 1e-6);
        EXPECT_NEAR(s.y * 100, std::round(s.y * 100), 1e-6);
    }
    // The planner's rapids take exactly the modelled air time (XY air plus the Z rapids).
    const double model = run->optimised.air_time_s + run->z_air_time_s;
    EXPECT_NEAR(run->planned_air_s, model, 1e-6 * model);
    EXPECT_LE(run->optimised.total_s(), run->drawing.total_s());
    EXPECT_LE(run->bound_time_s, run->optimised.air_time_s);
}

TEST(PatternJobFile, ASizeWithNoFactorIsAnErrorAtItsTable) {
    std::string text = job_text;
    text += "[[series.size]]\nsize = 41\n";
    Result<PatternJob> job = parse_pattern_job(text, "job.toml");
    ASSERT_FALSE(job);
    EXPECT_EQ(job.diagnostics()[0].code, "series-size");
    EXPECT_GT(job.diagnostics()[0].location.line, 20u);
}

TEST(PatternJobFile, AMotifLargerThanTheSoleIsAnError) {
    std::string text = job_text;
    const std::string small = "lines = [[-3.0, -2.0, 0.0, 2.0], [0.0, 2.0, 3.0, -2.0]]";
    text.replace(text.find(small), small.size(), "lines = [[-300.0, 0.0, 300.0, 0.0]]");
    Result<PatternJob> job = parse_pattern_job(text, "job.toml");
    ASSERT_TRUE(job);
    Result<SoleLayout> layout = lay_out_sole(*job, sole_points(), *grading_for(*job, 40.0, false));
    ASSERT_FALSE(layout);
    EXPECT_EQ(layout.diagnostics()[0].code, "motif-size");
    EXPECT_EQ(layout.diagnostics()[0].location.line, 9u);  // the [motif] table
}

}  // namespace
}  // namespace nckit::pattern
