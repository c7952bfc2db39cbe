// Exact step times: each piece is walked in its path parameter s, crossings of the step
// boundaries are found in s, then mapped to time through the inverse of the piecewise-cubic
// profile (s(t) never decreases, so the order of crossings in s is their order in time).
#include "nckit/drive/step_generator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "arc_crossing.hpp"
#include "profile_clock.hpp"

namespace nckit {

using drive_detail::ArcAxisCrossings;
using drive_detail::PhaseSolver;
using drive_detail::ProfileClock;

namespace {

// ns from s, for t >= 0 (rounded half up, as llround would for these values).
std::int64_t to_ns(double t_s) {
    return static_cast<std::int64_t>(t_s * 1e9 + 0.5);
}

}  // namespace

std::int64_t commanded_count(double position, double steps_per_unit) {
    return static_cast<std::int64_t>(std::floor(position * steps_per_unit + 0.5));
}

//! One interval of a piece on which an axis moves one way: [s_a, s_b] with x = q × spu going
//! from x_a to x_b, rising (+1) or falling (-1).
struct StepGenerator::Interval {
    double s_a = 0;
    double s_b = 0;
    double x_a = 0;
    double x_b = 0;
    int rising = 1;
};

StepGenerator::StepGenerator(const MachineConfig& machine, StepSolver solver) : solver_(solver) {
    for (const AxisConfig& config : machine.axes) {
        AxisState state;
        state.axis = config.axis;
        state.spu = config.steps_per_unit;
        state.backlash_steps = std::llround(config.backlash * config.steps_per_unit);
        state.backlash_interval_ns =
            std::max<std::int64_t>(1, std::llround(1e9 / std::max(config.backlash_rate_steps_s, 1e-9)));
        axes_.push_back(std::move(state));
    }
}

void StepGenerator::emit(AxisState& axis, std::uint8_t index, std::int64_t t_ns, int direction) {
    if (axis.last_direction != 0 && direction != axis.last_direction && axis.backlash_steps > 0) {
        std::int64_t t = std::max(t_ns, axis.motor_last_ns);
        if (axis.catching_up) t = std::max(t, axis.motor_last_ns + axis.backlash_interval_ns);
        for (std::int64_t i = 0; i < axis.backlash_steps; ++i) {
            axis.queue.push_back({t, index, static_cast<std::int8_t>(direction), true});
            axis.motor_count += direction;
            axis.motor_last_ns = t;
            t += axis.backlash_interval_ns;
        }
        axis.catching_up = true;
    }
    axis.last_direction = direction;
    std::int64_t t = t_ns;
    if (axis.catching_up) {
        if (t >= axis.motor_last_ns + axis.backlash_interval_ns) {
            axis.catching_up = false;
        } else {
            t = axis.motor_last_ns + axis.backlash_interval_ns;
        }
    }
    axis.queue.push_back({t, index, static_cast<std::int8_t>(direction), false});
    axis.count += direction;
    axis.motor_count += direction;
    axis.motor_last_ns = t;
}

// The steps of one axis over one interval: from its count to the count x_b implies. A step
// whose boundary the interval crosses goes at the crossing (`crossing(boundary, lo)`, the s of
// the boundary at or after lo); a step the interval does not explain (a rounding catch-up, or
// a step back after an overshoot) goes at the interval start.
template <class Crossing, class Clock>
void StepGenerator::walk(AxisState& axis, std::uint8_t index, const Interval& in, Crossing&& crossing,
                         Clock&& time_ns) {
    const std::int64_t target = static_cast<std::int64_t>(std::floor(in.x_b + 0.5));
    if (axis.count == target) return;
    const int direction = target > axis.count ? 1 : -1;
    const double half = 0.5 * direction;
    const auto dir = static_cast<std::int8_t>(direction);
    const bool crosses = direction == in.rising;
    double last_s = in.s_a;
    if (axis.catching_up || axis.backlash_steps > 0) {
        while (axis.count != target) {
            const double boundary = static_cast<double>(axis.count) + half;
            double s = in.s_a;
            if (crosses && (boundary - in.x_a) * in.rising > 0) {
                s = (in.x_b - boundary) * in.rising <= 0 ? in.s_b : crossing(boundary, last_s);
                last_s = s;
            }
            emit(axis, index, time_ns(s), direction);
        }
        return;
    }
    // The common case, without backlash bookkeeping: the loop keeps its state in registers.
    std::vector<StepEvent>& queue = axis.queue;
    queue.reserve(queue.size() + static_cast<std::size_t>(std::llabs(target - axis.count)));
    std::int64_t count = axis.count;
    std::int64_t t_ns = axis.motor_last_ns;
    // In blocks: the crossings first, then their times, so the library calls of one loop (acos
    // on arcs) overlap each other rather than wait behind the other's work.
    constexpr std::int64_t block = 32;
    double s_block[block];
    while (count != target) {
        const std::int64_t n = std::min<std::int64_t>(block, std::llabs(target - count));
        for (std::int64_t k = 0; k < n; ++k) {
            const double boundary = static_cast<double>(count + k * direction) + half;
            double s = in.s_a;
            if (crosses && (boundary - in.x_a) * in.rising > 0) {
                s = (in.x_b - boundary) * in.rising <= 0 ? in.s_b : crossing(boundary, last_s);
                last_s = s;
            }
            s_block[k] = s;
        }
        for (std::int64_t k = 0; k < n; ++k) {
            t_ns = time_ns(s_block[k]);
            queue.push_back({t_ns, index, dir, false});
        }
        count += n * direction;
    }
    axis.motor_count += count - axis.count;
    axis.count = count;
    axis.motor_last_ns = t_ns;
    axis.last_direction = direction;
}

void StepGenerator::add(const TrajectoryPiece& piece) {
    const double piece_start = piece.start_time_s;
    const double piece_end = piece.start_time_s + piece.duration_s;
    const PathSegment& g = piece.segment;
    if (piece.kind != PieceKind::motion || piece.duration_s <= 0) {
        // At rest: only an initial position matters.
        const AxisVector at = start_point(g);
        for (AxisState& axis : axes_) {
            if (!axis.started) {
                axis.count = axis.motor_count = axis.start_count = nckit::commanded_count(at[axis.axis], axis.spu);
                axis.started = true;
            }
        }
        horizon_ns_ = std::max<std::int64_t>(horizon_ns_, to_ns(piece_end));
        dirty_ = true;
        return;
    }
    const double offset_mm = piece.profile_offset_mm - piece.profile.start_position;
    const PhaseSolver phase_solver = solver_ == StepSolver::fast ? PhaseSolver::closed_form : PhaseSolver::newton;
    for (std::size_t a = 0; a < axes_.size(); ++a) {
        AxisState& axis = axes_[a];
        const auto index = static_cast<std::uint8_t>(a);
        const std::size_t i = nckit::index(axis.axis);
        if (!axis.started) {
            axis.count = axis.motor_count = axis.start_count = nckit::commanded_count(start_point(g)[i], axis.spu);
            axis.started = true;
        }
        // An axis off the circle (a helix's axis, UVW, ABC) moves linearly along the piece.
        const bool curved =
            i < 3 && ((g.radius_mm > 0 && (g.u[i] != 0 || g.v[i] != 0)) || g.shape == SegmentShape::quintic);
        if (!curved && g.rate[i] == 0) {
            // The axis does not move along this piece; a rounding step between pieces goes at
            // the piece start.
            const std::int64_t target = nckit::commanded_count(g.origin[i], axis.spu);
            const auto t_ns = to_ns(piece_start);
            while (axis.count != target) emit(axis, index, t_ns, axis.count < target ? 1 : -1);
            continue;
        }
        ProfileClock clock(piece.profile, phase_solver);
        auto time_ns = [&](double s) {
            const double profile_t = clock.time_at(s + offset_mm);
            const double t = piece_start + (profile_t - piece.profile_offset_s);
            return to_ns(std::clamp(t, piece_start, piece_end));
        };
        const double spu = axis.spu;
        const double inv_spu = 1.0 / spu;
        if (!curved) {
            const double inv_rate = 1.0 / g.rate[i];
            const Interval whole{0.0, g.length, position_at(g, 0.0)[i] * spu, position_at(g, g.length)[i] * spu,
                                 g.rate[i] > 0 ? 1 : -1};
            walk(
                axis, index, whole,
                [&](double boundary, double) {
                    return std::clamp((boundary * inv_spu - g.origin[i]) * inv_rate, 0.0, g.length);
                },
                time_ns);
            continue;
        }
        // Monotone intervals of q_i(s), split at its turning points.
        std::vector<double> cuts{0.0};
        for (double s : drive_detail::arc_turning_points(g, i)) cuts.push_back(s);
        cuts.push_back(g.length);
        const bool closed_form = solver_ == StepSolver::fast && ArcAxisCrossings::applies(g, i);
        ArcAxisCrossings arc = closed_form ? ArcAxisCrossings(g, i) : ArcAxisCrossings();
        double x_a = position_at(g, 0.0)[i] * spu;
        double last_s = 0;    // the last crossing on this axis
        double last_gap = 0;  // and the spacing before it: the next guess is last_s + last_gap
        for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
            const double s_a = cuts[c];
            const double s_b = cuts[c + 1];
            const double x_b = position_at(g, s_b)[i] * spu;
            const Interval interval{s_a, s_b, x_a, x_b, x_b >= x_a ? 1 : -1};
            if (closed_form) arc.set_interval(s_a, s_b);
            walk(
                axis, index, interval,
                [&](double boundary, double lo) {
                    double s = closed_form ? arc.crossing(boundary * inv_spu, lo, s_b) : -1.0;
                    if (s < 0) {
                        const double guess = last_s > s_a ? last_s + last_gap : lo + 0.5 * (s_b - lo);
                        s = drive_detail::arc_crossing_newton(g, i, spu, boundary, lo, s_b, interval.rising, guess);
                    }
                    last_gap = s - last_s;
                    last_s = s;
                    return s;
                },
                time_ns);
            x_a = x_b;
        }
    }
    horizon_ns_ = std::max<std::int64_t>(horizon_ns_, to_ns(piece_end));
    dirty_ = true;
}

void StepGenerator::finish() {
    finished_ = true;
    dirty_ = true;
}

namespace {

// Merges the time-ordered runs a and b into out, a's events first at equal times. The choice
// is a conditional move, not a branch: steps of two axes interleave unpredictably.
StepEvent* merge_runs(const StepEvent* a, const StepEvent* a_end, const StepEvent* b, const StepEvent* b_end,
                      StepEvent* out) {
    while (a != a_end && b != b_end) {
        const bool take_b = b->t_ns < a->t_ns;
        *out++ = *(take_b ? b : a);
        b += take_b ? 1 : 0;
        a += take_b ? 0 : 1;
    }
    out = std::copy(a, a_end, out);
    return std::copy(b, b_end, out);
}

}  // namespace

bool StepGenerator::refill() {
    if (!dirty_) return false;
    release();
    dirty_ = false;
    return ready_head_ < ready_.size();
}

// Moves every event before the horizon from the axis queues into ready_, merged in time order,
// ties in axis order (the merge takes the lower axes first). Events released earlier are all
// before the old horizon and new ones at or after it, so the new ones are appended.
void StepGenerator::release() {
    const std::int64_t limit = finished_ ? std::numeric_limits<std::int64_t>::max() : horizon_ns_;
    ready_.erase(ready_.begin(), ready_.begin() + static_cast<std::ptrdiff_t>(ready_head_));
    ready_head_ = 0;
    auto before_limit = [limit](const StepEvent& e) { return e.t_ns < limit; };
    const std::size_t old_size = ready_.size();
    for (AxisState& axis : axes_) {
        const auto begin = axis.queue.begin() + static_cast<std::ptrdiff_t>(axis.head);
        const auto end = std::partition_point(begin, axis.queue.end(), before_limit);
        if (begin == end) continue;
        const auto count = static_cast<std::size_t>(end - begin);
        if (ready_.size() == old_size) {
            ready_.insert(ready_.end(), begin, end);
        } else {
            // Merge this axis into the run of the axes before it.
            merged_.resize(ready_.size() - old_size + count);
            merge_runs(ready_.data() + old_size, ready_.data() + ready_.size(), &*begin, &*end, merged_.data());
            ready_.resize(old_size);
            ready_.insert(ready_.end(), merged_.begin(), merged_.end());
        }
        axis.head = static_cast<std::size_t>(end - axis.queue.begin());
        if (axis.head == axis.queue.size()) {
            axis.queue.clear();
            axis.head = 0;
        } else if (axis.head > 4096 && axis.head * 2 > axis.queue.size()) {
            axis.queue.erase(axis.queue.begin(), axis.queue.begin() + static_cast<std::ptrdiff_t>(axis.head));
            axis.head = 0;
        }
    }
    // Kept for safety: should an earlier release have left an event after a new one, restore
    // the order (stable, so ties stay in axis order).
    if (old_size > 0 && ready_.size() > old_size && ready_[old_size].t_ns < ready_[old_size - 1].t_ns) {
        std::inplace_merge(ready_.begin(), ready_.begin() + static_cast<std::ptrdiff_t>(old_size), ready_.end(),
                           [](const StepEvent& x, const StepEvent& y) { return x.t_ns < y.t_ns; });
    }
}

std::vector<StepEvent> generate_steps(const Trajectory& trajectory, const MachineConfig& machine, StepSolver solver) {
    StepGenerator generator(machine, solver);
    std::vector<StepEvent> out;
    StepEvent event;
    for (const TrajectoryPiece& piece : trajectory.pieces) {
        generator.add(piece);
        while (generator.pop(event)) out.push_back(event);
    }
    generator.finish();
    while (generator.pop(event)) out.push_back(event);
    return out;
}

}  // namespace nckit
