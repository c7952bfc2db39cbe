// The firmware command stream of `nckit steps --compress`: replayed per axis it gives back every
// step, in its direction, within the error bound, and memory stays bounded on long moves.
#include <gtest/gtest.h>

#include <cstdlib>
#include <random>
#include <vector>

#include "nckit/drive/step_queue.hpp"

namespace nckit {
namespace {

struct Replayed {
    std::int64_t t_ns;
    int direction;
};

// What the firmware does with the commands: per axis, the steps with their directions.
std::vector<std::vector<Replayed>> replay(const std::vector<StepQueueCommand>& commands, std::size_t axes) {
    std::vector<std::vector<Replayed>> out(axes);
    std::vector<int> direction(axes, 0);
    std::vector<std::int64_t> t_prev(axes, 0);
    for (const StepQueueCommand& c : commands) {
        if (c.kind == StepQueueCommand::Kind::set_direction) {
            direction[c.axis] = c.direction;
            continue;
        }
        EXPECT_NE(direction[c.axis], 0) << "a run before any direction";
        for (std::int64_t t : expand_run(c.run, t_prev[c.axis])) {
            out[c.axis].push_back({t, direction[c.axis]});
            t_prev[c.axis] = t;
        }
    }
    return out;
}

std::vector<StepEvent> random_steps(std::mt19937_64& random, std::size_t axes, int count) {
    std::uniform_int_distribution<int> axis(0, static_cast<int>(axes) - 1);
    std::uniform_int_distribution<int> gap_ns(1, 200000);
    std::bernoulli_distribution reverse(0.01);
    std::vector<int> direction(axes, 1);
    std::vector<StepEvent> steps;
    std::int64_t t = 0;
    for (int i = 0; i < count; ++i) {
        t += gap_ns(random);
        const auto a = static_cast<std::size_t>(axis(random));
        if (reverse(random)) direction[a] = -direction[a];
        steps.push_back(StepEvent{
            .t_ns = t, .axis = static_cast<std::uint8_t>(a), .direction = static_cast<std::int8_t>(direction[a])});
    }
    return steps;
}

void check_replay(const std::vector<StepEvent>& steps, const std::vector<StepQueueCommand>& commands, std::size_t axes,
                  std::int64_t max_error_ns) {
    const auto replayed = replay(commands, axes);
    std::vector<std::size_t> next(axes, 0);
    for (const StepEvent& e : steps) {
        const std::vector<Replayed>& axis = replayed[e.axis];
        ASSERT_LT(next[e.axis], axis.size()) << "a step lost on axis " << int(e.axis);
        const Replayed& r = axis[next[e.axis]++];
        EXPECT_EQ(r.direction, e.direction);
        EXPECT_LE(std::llabs(r.t_ns - e.t_ns), max_error_ns);
    }
    for (std::size_t a = 0; a < axes; ++a) EXPECT_EQ(next[a], replayed[a].size()) << "extra steps on axis " << a;
}

TEST(StepQueue, RandomMultiAxisStepsReplayWithinTheBound) {
    std::mt19937_64 random(2026);
    for (std::int64_t max_error_ns : {0, 1000, 25000}) {
        const std::vector<StepEvent> steps = random_steps(random, 3, 20000);
        StepQueue queue(3, max_error_ns);
        std::vector<StepQueueCommand> commands;
        for (const StepEvent& e : steps) queue.add(e, commands);
        queue.finish(commands);
        check_replay(steps, commands, 3, max_error_ns);
        EXPECT_EQ(queue.steps(), 20000);
        std::int64_t runs = 0;
        for (const StepQueueCommand& c : commands) runs += c.kind == StepQueueCommand::Kind::queue_step ? 1 : 0;
        EXPECT_EQ(queue.runs(), runs);
    }
}

TEST(StepQueue, ConstantSpeedCompressesIntoFewRuns) {
    StepQueue queue(1, 1000);
    std::vector<StepQueueCommand> commands;
    std::vector<StepEvent> steps;
    for (int k = 1; k <= 10000; ++k) steps.push_back(StepEvent{.t_ns = 250000LL * k, .axis = 0, .direction = 1});
    for (const StepEvent& e : steps) queue.add(e, commands);
    queue.finish(commands);
    check_replay(steps, commands, 1, 1000);
    EXPECT_EQ(commands.front().kind, StepQueueCommand::Kind::set_direction);
    EXPECT_GT(queue.compression_ratio(), 1000.0);
}

TEST(StepQueue, CommandsComeOutWhenDirectionChangesOrThePendingStepsAreFull) {
    StepQueue queue(2, 0, 4);
    std::vector<StepQueueCommand> commands;
    for (int k = 1; k <= 4; ++k) queue.add(StepEvent{.t_ns = 1000LL * k, .axis = 1, .direction = -1}, commands);
    // Only the direction so far: the four steps wait.
    ASSERT_EQ(commands.size(), 1U);
    EXPECT_EQ(commands[0].axis, 1U);
    EXPECT_EQ(commands[0].direction, -1);
    queue.add(StepEvent{.t_ns = 5000, .axis = 1, .direction = -1}, commands);  // the fifth: four are flushed
    EXPECT_GT(commands.size(), 1U);
    const std::size_t before = commands.size();
    queue.add(StepEvent{.t_ns = 6000, .axis = 1, .direction = 1}, commands);  // reversal: flush, then direction
    ASSERT_GT(commands.size(), before);
    EXPECT_EQ(commands.back().kind, StepQueueCommand::Kind::set_direction);
    EXPECT_EQ(commands.back().direction, 1);
    queue.finish(commands);
    check_replay({{1000, 1, -1}, {2000, 1, -1}, {3000, 1, -1}, {4000, 1, -1}, {5000, 1, -1}, {6000, 1, 1}}, commands, 2,
                 0);
}

TEST(StepQueue, BadParametersAndUnknownAxesAreProgrammingErrors) {
    EXPECT_THROW(StepQueue(1, -1), std::invalid_argument);
    StepQueue queue(1, 0);
    std::vector<StepQueueCommand> commands;
    EXPECT_THROW(queue.add(StepEvent{.t_ns = 1, .axis = 1, .direction = 1}, commands), std::out_of_range);
}

}  // namespace
}  // namespace nckit
