// Step generation: absolute counts over a million random moves, counts at random times against
// round(position × spu), reversals (lines and arcs) and backlash.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "nckit/drive/step_generator.hpp"
#include "nckit/plan/planner.hpp"

namespace nckit {
namespace {

MachineConfig test_machine() {
    MachineConfig machine = default_mill();
    machine.axes[0].steps_per_unit = 800.0;
    machine.axes[1].steps_per_unit = 1234.5678;  // not a round number: boundaries fall anywhere
    machine.axes[2].steps_per_unit = 333.3;
    return machine;
}

AxisVector xyz(double x, double y, double z) {
    AxisVector p;
    p[Axis::X] = x;
    p[Axis::Y] = y;
    p[Axis::Z] = z;
    return p;
}

Move line(const AxisVector& from, const AxisVector& to, double feed_mm_min, bool exact_stop = false) {
    Move m;
    PathControl path;
    path.exact_stop = exact_stop;
    m.what = Line{from, to, Feed{FeedMode::per_minute, feed_mm_min, 0}, false, path};
    return m;
}

Move arc(const AxisVector& from, const AxisVector& to, const AxisVector& center, ArcDirection direction,
         double feed_mm_min) {
    Arc a;
    a.from = from;
    a.to = to;
    a.center = center;
    a.direction = direction;
    a.feed = Feed{FeedMode::per_minute, feed_mm_min, 0};
    Move m;
    m.what = a;
    return m;
}

// Every axis's count at time t_ns (events at or before it), from the start counts.
struct CountIndex {
    std::vector<std::vector<std::int64_t>> times;   // per axis
    std::vector<std::vector<std::int64_t>> counts;  // per axis, after each event
    std::vector<std::int64_t> start;

    CountIndex(const std::vector<StepEvent>& events, std::vector<std::int64_t> start_counts)
        : times(start_counts.size()), counts(start_counts.size()), start(std::move(start_counts)) {
        std::vector<std::int64_t> c = start;
        for (const StepEvent& e : events) {
            c[e.axis] += e.direction;
            times[e.axis].push_back(e.t_ns);
            counts[e.axis].push_back(c[e.axis]);
        }
    }
    std::int64_t count_at(std::size_t axis, double t_ns) const {
        const auto& ts = times[axis];
        auto it = std::upper_bound(ts.begin(), ts.end(), t_ns,
                                   [](double t, std::int64_t e) { return t < static_cast<double>(e); });
        if (it == ts.begin()) return start[axis];
        return counts[axis][static_cast<std::size_t>(it - ts.begin() - 1)];
    }
    // ns to the nearest event of the axis.
    double distance_to_step(std::size_t axis, double t_ns) const {
        const auto& ts = times[axis];
        auto it = std::lower_bound(ts.begin(), ts.end(), t_ns,
                                   [](std::int64_t e, double t) { return static_cast<double>(e) < t; });
        double d = 1e300;
        if (it != ts.end()) d = std::min(d, static_cast<double>(*it) - t_ns);
        if (it != ts.begin()) d = std::min(d, t_ns - static_cast<double>(*(it - 1)));
        return d;
    }
};

TEST(StepGenerator, MillionRandomShortMovesEndWithZeroCountError) {
    const MachineConfig machine = test_machine();
    Planner planner(machine);
    StepGenerator steps(machine);
    std::mt19937_64 rng(12345);
    std::uniform_real_distribution<double> delta(-0.05, 0.05);
    std::uniform_real_distribution<double> feed(300, 6000);
    std::vector<std::int64_t> counts(machine.axes.size(), 0);
    std::int64_t last_t = 0;
    std::int64_t events = 0;
    bool ordered = true;
    auto drain = [&] {
        TrajectoryPiece piece;
        StepEvent e;
        while (planner.pop(piece)) {
            steps.add(piece);
            while (steps.pop(e)) {
                counts[e.axis] += e.direction;
                ordered = ordered && e.t_ns >= last_t;
                last_t = e.t_ns;
                ++events;
            }
        }
    };
    AxisVector at = xyz(0, 0, 0);
    constexpr int moves = 1'000'000;
    for (int n = 0; n < moves; ++n) {
        AxisVector to = at;
        for (std::size_t i = 0; i < 3; ++i) to[i] = std::clamp(at[i] + delta(rng), -400.0, 400.0);
        planner.push(line(at, to, feed(rng)));
        at = to;
        drain();
    }
    planner.finish();
    drain();
    steps.finish();
    StepEvent e;
    while (steps.pop(e)) {
        counts[e.axis] += e.direction;
        ordered = ordered && e.t_ns >= last_t;
        last_t = e.t_ns;
        ++events;
    }
    ASSERT_TRUE(planner.diagnostics().empty());
    EXPECT_TRUE(ordered);
    EXPECT_GT(events, moves);
    for (std::size_t a = 0; a < machine.axes.size(); ++a) {
        const std::int64_t expected = commanded_count(at[machine.axes[a].axis], machine.axes[a].steps_per_unit);
        EXPECT_EQ(counts[a], expected) << "axis " << a;
        EXPECT_EQ(steps.commanded_count(a), expected);
    }
}

// Lines and arcs (with reversals inside them), blended and stopped.
std::vector<Move> random_program(std::mt19937_64& rng, int count) {
    std::uniform_real_distribution<double> delta(-3.0, 3.0);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Move> moves;
    AxisVector at = xyz(0.1, -0.2, 0.3);
    for (int n = 0; n < count; ++n) {
        const double f = 200 + 5000 * unit(rng);
        if (unit(rng) < 0.4) {
            // An arc about a random centre, ending on the circle.
            const double r = 0.2 + 3 * unit(rng);
            const double phase = 6.283185307179586 * unit(rng);
            const double sweep = 6.283185307179586 * unit(rng);
            AxisVector center = at;
            center[Axis::X] = at[Axis::X] - r * std::cos(phase);
            center[Axis::Y] = at[Axis::Y] - r * std::sin(phase);
            const ArcDirection dir = unit(rng) < 0.5 ? ArcDirection::counterclockwise : ArcDirection::clockwise;
            const double end = phase + (dir == ArcDirection::counterclockwise ? sweep : -sweep);
            AxisVector to = at;
            to[Axis::X] = center[Axis::X] + r * std::cos(end);
            to[Axis::Y] = center[Axis::Y] + r * std::sin(end);
            to[Axis::Z] = at[Axis::Z] + delta(rng) * 0.2;  // sometimes a helix
            moves.push_back(arc(at, to, center, dir, f));
            at = to;
        } else {
            AxisVector to = at;
            for (std::size_t i = 0; i < 3; ++i) to[i] = at[i] + delta(rng);
            moves.push_back(line(at, to, f, unit(rng) < 0.2));
            at = to;
        }
    }
    return moves;
}

TEST(StepGenerator, CountAtRandomTimesIsRoundedPosition) {
    const MachineConfig machine = test_machine();
    std::mt19937_64 rng(7);
    const std::vector<Move> moves = random_program(rng, 3000);
    const PlanResult plan = plan_moves(moves, machine);
    ASSERT_TRUE(plan.diagnostics.empty());
    const std::vector<StepEvent> events = generate_steps(plan.trajectory, machine);
    const AxisVector start = plan.trajectory.sample(0).position;
    std::vector<std::int64_t> start_counts;
    for (const AxisConfig& a : machine.axes) start_counts.push_back(commanded_count(start[a.axis], a.steps_per_unit));
    const CountIndex index(events, start_counts);
    const double duration = plan.trajectory.duration_s();
    std::uniform_real_distribution<double> when(0.0, duration);
    int checked = 0;
    int near = 0;
    for (int n = 0; n < 300000; ++n) {
        const double t = when(rng);
        const AxisVector p = plan.trajectory.sample(t).position;
        for (std::size_t a = 0; a < machine.axes.size(); ++a) {
            const double spu = machine.axes[a].steps_per_unit;
            const std::int64_t expected = commanded_count(p[machine.axes[a].axis], spu);
            const std::int64_t got = index.count_at(a, t * 1e9);
            // Step times are rounded to whole ns and the crossings found to ~1e-11 s: within
            // 1 ns of a step the count may still show the other side of it.
            if (index.distance_to_step(a, t * 1e9) <= 1.0) {
                ++near;
                EXPECT_LE(std::llabs(got - expected), 1);
                continue;
            }
            ASSERT_EQ(got, expected) << "axis " << a << " t " << t;
            ++checked;
        }
    }
    EXPECT_GT(checked, 800000);
    const AxisVector end = plan.trajectory.sample(duration).position;
    for (std::size_t a = 0; a < machine.axes.size(); ++a) {
        EXPECT_EQ(index.count_at(a, 1e30), commanded_count(end[machine.axes[a].axis], machine.axes[a].steps_per_unit));
    }
    // Ordered in time, ties in axis order.
    for (std::size_t k = 1; k < events.size(); ++k) {
        ASSERT_TRUE(events[k - 1].t_ns < events[k].t_ns ||
                    (events[k - 1].t_ns == events[k].t_ns && events[k - 1].axis <= events[k].axis));
    }
}

TEST(StepGenerator, ReversalBetweenLines) {
    const MachineConfig machine = test_machine();
    const PlanResult plan =
        plan_moves({line(xyz(0, 0, 0), xyz(1, 0, 0), 600), line(xyz(1, 0, 0), xyz(0, 0, 0), 600)}, machine);
    ASSERT_TRUE(plan.diagnostics.empty());
    const std::vector<StepEvent> events = generate_steps(plan.trajectory, machine);
    ASSERT_EQ(events.size(), 1600U);
    for (std::size_t k = 0; k < events.size(); ++k) {
        EXPECT_EQ(events[k].axis, 0);
        EXPECT_EQ(events[k].direction, k < 800 ? 1 : -1);
        EXPECT_FALSE(events[k].backlash);
    }
    // Step k+1 (up) is where x crosses (k + 0.5) / spu.
    const double t = static_cast<double>(events[0].t_ns) * 1e-9;
    EXPECT_NEAR(plan.trajectory.sample(t).position[Axis::X] * 800.0, 0.5, 1e-3);
}

TEST(StepGenerator, ReversalsInsideAFullCircle) {
    const MachineConfig machine = test_machine();
    // Radius 1 about (1, 0): X goes 0 → 2 → 0, Y 0 → -1 → 0 → 1 → 0 (clockwise).
    const PlanResult plan =
        plan_moves({arc(xyz(0, 0, 0), xyz(0, 0, 0), xyz(1, 0, 0), ArcDirection::clockwise, 1200)}, machine);
    ASSERT_TRUE(plan.diagnostics.empty());
    const std::vector<StepEvent> events = generate_steps(plan.trajectory, machine);
    std::vector<int> steps(3, 0);
    std::vector<int> reversals(3, 0);
    std::vector<int> last(3, 0);
    std::vector<std::int64_t> count(3, 0);
    for (const StepEvent& e : events) {
        ++steps[e.axis];
        if (last[e.axis] != 0 && last[e.axis] != e.direction) ++reversals[e.axis];
        last[e.axis] = e.direction;
        count[e.axis] += e.direction;
    }
    EXPECT_EQ(steps[0], 2 * 1600);
    EXPECT_EQ(reversals[0], 1);
    const std::int64_t y_peak = commanded_count(1.0, 1234.5678);
    EXPECT_EQ(steps[1], 4 * y_peak);
    EXPECT_EQ(reversals[1], 2);
    EXPECT_EQ(count[0], 0);
    EXPECT_EQ(count[1], 0);
    EXPECT_EQ(steps[2], 0);
}

TEST(StepGenerator, BacklashStepsAtTheReversal) {
    MachineConfig machine = test_machine();
    machine.axes[0].backlash = 0.01;                // 8 steps
    machine.axes[0].backlash_rate_steps_s = 20000;  // one every 50 µs
    const PlanResult plan = plan_moves({line(xyz(0, 0, 0), xyz(1, 0, 0), 600), line(xyz(1, 0, 0), xyz(0.5, 0, 0), 600),
                                        line(xyz(0.5, 0, 0), xyz(2, 0, 0), 600)},
                                       machine);
    ASSERT_TRUE(plan.diagnostics.empty());
    StepGenerator generator(machine);
    std::vector<StepEvent> events;
    StepEvent e;
    for (const TrajectoryPiece& piece : plan.trajectory.pieces) {
        generator.add(piece);
        while (generator.pop(e)) events.push_back(e);
    }
    generator.finish();
    while (generator.pop(e)) events.push_back(e);
    // 800 up, 8 backlash + 400 down, 8 backlash + 1200 up.
    ASSERT_EQ(events.size(), 800U + 8 + 400 + 8 + 1200);
    EXPECT_EQ(generator.commanded_count(0), 1600);
    EXPECT_EQ(generator.motor_count(0), 1600);  // -8 then +8
    const std::vector<StepEvent> plain = generate_steps(plan.trajectory, test_machine());
    ASSERT_EQ(plain.size(), 800U + 400 + 1200);
    // The take-up starts at the first down step's own time, 50 µs apart, then the commanded
    // step follows 50 µs after the last.
    for (int k = 0; k < 8; ++k) {
        EXPECT_TRUE(events[800 + k].backlash);
        EXPECT_EQ(events[800 + k].direction, -1);
        EXPECT_EQ(events[800 + k].t_ns, plain[800].t_ns + 50000 * k);
    }
    EXPECT_FALSE(events[808].backlash);
    EXPECT_GE(events[808].t_ns, events[807].t_ns + 50000);
    // Delayed steps catch up: the last down step is at its own time.
    EXPECT_EQ(events[808 + 399].t_ns, plain[800 + 399].t_ns);
    for (std::size_t k = 1; k < events.size(); ++k) ASSERT_LE(events[k - 1].t_ns, events[k].t_ns);
    EXPECT_TRUE(events[1208].backlash);
    EXPECT_EQ(events[1208].direction, 1);
}

}  // namespace
}  // namespace nckit
