// Exact step times: each piece is walked in its path parameter s, crossings of the step
// boundaries are found in s, then mapped to time through the inverse of the piecewise-cubic
// profile (s(t) never decreases, so the order of crossings in s is their order in time).
#include "nckit/drive/step_generator.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <numbers>

namespace nckit {

namespace {
// ns from s, for t >= 0 (rounded half up, as llround would for these values).
std::int64_t to_ns(double t_s) { return static_cast<std::int64_t>(t_s * 1e9 + 0.5); }
}  // namespace

std::int64_t commanded_count(double position, double steps_per_unit) {
    return static_cast<std::int64_t>(std::floor(position * steps_per_unit + 0.5));
}

namespace {

// The profile of one piece, inverted: the time at which it reaches a position. Queries come with
// non-decreasing positions, so the walker only moves forwards through the phases.
class ProfileInverse {
public:
    explicit ProfileInverse(const Profile& profile) : profile_(profile) { enter(0, 0, 0, profile.start_velocity); }

    //! s of profile time at which the profile (relative to its start) reaches p.
    double time_at(double p) {
        while (phase_ + 1 < profile_.phase_count && p > end_p_) {
            const ProfilePhase& ph = profile_.phases[static_cast<std::size_t>(phase_)];
            const double tau = ph.duration_s;
            enter(phase_ + 1, start_s_ + tau, end_p_, v_ + tau * (a_ + 0.5 * tau * j_));
        }
        if (profile_.phase_count == 0) return 0;
        if (p <= p_) return start_s_;  // at (or, by rounding, before) the phase start
        if (p >= end_p_) return start_s_ + duration_;
        if (j_ == 0 && a_ == 0) {  // cruise: linear
            const double x = std::clamp((p - p_) * inv_v_, 0.0, duration_);
            remember(x);
            return start_s_ + x;
        }
        // Newton on the monotone cubic, kept inside a shrinking bracket (bisection fallback),
        // from a second-order Taylor step off the last root (steps come close together, so
        // the first Newton step is usually already below the tolerance).
        double lo = 0;
        double hi = duration_;
        double x = guess_ + last_gap_;
        if (have_root_) {
            const double v = v_ + guess_ * (a_ + 0.5 * guess_ * j_);
            if (v > 0) {
                const double a = a_ + guess_ * j_;
                const double inv_v = 1.0 / v;
                const double d = (p - last_p_) * inv_v;
                x = guess_ + d - 0.5 * a * d * d * inv_v;
            }
        }
        x = std::clamp(x, lo, hi);
        for (int iteration = 0; iteration < 100; ++iteration) {
            const double f = p_ + x * (v_ + x * (half_a_ + x * sixth_j_)) - p;
            if (f < 0) {
                lo = x;
            } else if (f > 0) {
                hi = x;
            } else {
                break;
            }
            const double slope = v_ + x * (a_ + 0.5 * x * j_);
            double next = slope > 0 ? x - f / slope : lo + 0.5 * (hi - lo);
            if (!(next >= lo && next <= hi)) next = lo + 0.5 * (hi - lo);
            const double step = std::abs(next - x);
            x = next;
            // A Newton step this small leaves an error of the order of its square: done.
            if (step < 1e-10 || hi - lo < 1e-12) break;
        }
        remember(x);
        have_root_ = true;
        last_p_ = p;
        return start_s_ + x;
    }

private:
    void remember(double x) {
        last_gap_ = x - guess_;
        guess_ = x;
    }

    void enter(int phase, double start_s, double p, double v) {
        phase_ = phase;
        start_s_ = start_s;
        p_ = p;
        v_ = v;
        guess_ = 0;
        last_gap_ = 0;
        have_root_ = false;
        if (phase >= profile_.phase_count) return;
        const ProfilePhase& ph = profile_.phases[static_cast<std::size_t>(phase)];
        a_ = ph.acceleration;
        j_ = ph.jerk;
        duration_ = ph.duration_s;
        inv_v_ = v > 0 ? 1.0 / v : 0.0;
        half_a_ = 0.5 * a_;
        sixth_j_ = j_ / 6.0;
        end_p_ = phase + 1 == profile_.phase_count
                     ? profile_.distance
                     : p + duration_ * (v + duration_ * (0.5 * a_ + duration_ * j_ / 6.0));
    }

    const Profile& profile_;
    int phase_ = 0;
    double start_s_ = 0;   // s, profile time at the phase start
    double duration_ = 0;  // s
    double p_ = 0, v_ = 0, a_ = 0, j_ = 0;  // state at the phase start (p relative to the profile)
    double end_p_ = 0;     // mm at the phase end
    double inv_v_ = 0;     // s/mm at the phase start (cruise phases)
    double half_a_ = 0, sixth_j_ = 0;  // the cubic's coefficients a/2, j/6
    double guess_ = 0;     // s into the phase: the last root, a good start for the next
    double last_gap_ = 0;  // s between the last two roots
    bool have_root_ = false;  // guess_ is a root in this phase, at position last_p_
    double last_p_ = 0;
};

// Where dq/ds of one XYZ axis of an arc is zero, in (0, length), sorted.
std::vector<double> arc_turning_points(const PathSegment& g, std::size_t i) {
    std::vector<double> out;
    const double k = g.angle_rate;
    const double m = std::hypot(g.u[i], g.v[i]);
    if (g.radius_mm <= 0 || k == 0 || m < 1e-15) return out;
    // dq/ds = rate + R k (v cos θ − u sin θ) = rate + R k m cos(θ + φ), φ = atan2(u, v).
    const double c = -g.rate[i] / (g.radius_mm * k * m);
    if (!(std::abs(c) <= 1)) return out;
    const double phi = std::atan2(g.u[i], g.v[i]);
    const double alpha = std::acos(c);
    const double theta_lo = std::min(0.0, k * g.length);
    const double theta_hi = std::max(0.0, k * g.length);
    constexpr double two_pi = 2 * std::numbers::pi;
    for (double base : {alpha - phi, -alpha - phi}) {
        double theta = base - two_pi * std::floor((base - theta_lo) / two_pi);
        for (; theta < theta_hi; theta += two_pi) {
            const double s = theta / k;
            if (s > 0 && s < g.length) out.push_back(s);
        }
    }
    std::sort(out.begin(), out.end());
    return out;
}

// q_i(s) and dq_i/ds of one XYZ axis of an arc, as point_at computes them.
struct AxisPoint {
    double position = 0;
    double d1 = 0;
};
AxisPoint arc_axis_at(const PathSegment& g, std::size_t i, double s) {
    const double k = g.angle_rate;
    const double theta = k * s;
    const double c = std::cos(theta);
    const double sn = std::sin(theta);
    return {g.origin[i] + g.rate[i] * s + g.radius_mm * (c * g.u[i] + sn * g.v[i]),
            g.rate[i] + g.radius_mm * k * (-sn * g.u[i] + c * g.v[i])};
}

// s in [lo, hi] where x(s) = spu·q_i(s) crosses `target`; x is monotone on the interval, rising
// when direction > 0. Newton on the exact derivative from `guess`, safeguarded by bisection;
// stops when a Newton step is below 1e-13 of the length scale, or the bracket is exhausted.
double arc_crossing(const PathSegment& g, std::size_t i, double spu, double target, double lo, double hi,
                    int direction, double guess) {
    double x = std::clamp(guess, lo, hi);
    const double scale = 1e-13 * std::max(1.0, g.length);
    for (int iteration = 0; iteration < 200; ++iteration) {
        const AxisPoint p = arc_axis_at(g, i, x);
        const double f = direction * (p.position * spu - target);
        if (f < 0) {
            lo = x;
        } else if (f > 0) {
            hi = x;
        } else {
            return x;
        }
        const double slope = direction * p.d1 * spu;
        double next = slope > 0 ? x - f / slope : lo + 0.5 * (hi - lo);
        if (!(next > lo && next < hi)) next = lo + 0.5 * (hi - lo);
        if (!(next > lo && next < hi)) return x;  // bracket down to adjacent doubles
        const double step = std::abs(next - x);
        x = next;
        if (step <= scale) return x;
    }
    return x;
}

}  // namespace

StepGenerator::StepGenerator(const MachineConfig& machine) {
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

void StepGenerator::add(const TrajectoryPiece& piece) {
    const double piece_start = piece.start_time_s;
    const double piece_end = piece.start_time_s + piece.duration_s;
    const PathSegment& g = piece.segment;
    if (piece.kind != PieceKind::motion || piece.duration_s <= 0) {
        // At rest: only an initial position matters.
        const AxisVector at = start_point(g);
        for (AxisState& axis : axes_) {
            if (!axis.started) {
                axis.count = axis.motor_count = nckit::commanded_count(at[axis.axis], axis.spu);
                axis.started = true;
            }
        }
        horizon_ns_ = std::max<std::int64_t>(horizon_ns_, to_ns(piece_end));
        dirty_ = true;
        return;
    }
    const double offset_mm = piece.profile_offset_mm - piece.profile.start_position;
    for (std::size_t a = 0; a < axes_.size(); ++a) {
        AxisState& axis = axes_[a];
        const auto index = static_cast<std::uint8_t>(a);
        const std::size_t i = nckit::index(axis.axis);
        if (!axis.started) {
            axis.count = axis.motor_count = nckit::commanded_count(start_point(g)[i], axis.spu);
            axis.started = true;
        }
        const bool curved = g.radius_mm > 0 && i < 3;
        if (!curved && g.rate[i] == 0) {
            // The axis does not move along this piece; a rounding step between pieces goes at
            // the piece start.
            const std::int64_t target = nckit::commanded_count(g.origin[i], axis.spu);
            const auto t_ns = to_ns(piece_start);
            while (axis.count != target) emit(axis, index, t_ns, axis.count < target ? 1 : -1);
            continue;
        }
        ProfileInverse inverse(piece.profile);
        auto time_ns = [&](double s) {
            const double profile_t = inverse.time_at(s + offset_mm);
            const double t = piece_start + (profile_t - piece.profile_offset_s);
            return to_ns(std::clamp(t, piece_start, piece_end));
        };
        // Monotone intervals of q_i(s).
        std::vector<double> cuts{0.0};
        if (curved) {
            for (double s : arc_turning_points(g, i)) cuts.push_back(s);
        }
        cuts.push_back(g.length);
        const double inv_spu = 1.0 / axis.spu;
        const double inv_rate = curved ? 0.0 : 1.0 / g.rate[i];
        double x_a = position_at(g, 0.0)[i] * axis.spu;
        double last_s = 0;    // the last crossing on this axis (arcs)
        double last_gap = 0;  // and the spacing before it: the next guess is last_s + last_gap
        for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
            const double s_a = cuts[c];
            const double s_b = cuts[c + 1];
            const double x_b = position_at(g, s_b)[i] * axis.spu;
            const std::int64_t target = static_cast<std::int64_t>(std::floor(x_b + 0.5));
            const int direction = target > axis.count ? 1 : -1;
            const int rising = curved ? (x_b >= x_a ? 1 : -1) : (g.rate[i] > 0 ? 1 : -1);
            while (axis.count != target) {
                const double boundary = static_cast<double>(axis.count) + 0.5 * direction;
                double s = s_a;
                if (direction == rising && (boundary - x_a) * rising > 0) {
                    if ((x_b - boundary) * rising <= 0) {
                        s = s_b;
                    } else if (!curved) {
                        s = std::clamp((boundary * inv_spu - g.origin[i]) * inv_rate, s_a, s_b);
                    } else {
                        const double lo = std::max(s_a, last_s);
                        s = arc_crossing(g, i, axis.spu, boundary, lo, s_b, rising,
                                         last_s > s_a ? last_s + last_gap : lo + 0.5 * (s_b - lo));
                        last_gap = s - last_s;
                        last_s = s;
                    }
                }
                const std::int64_t t_ns = time_ns(s);
                if (!axis.catching_up && axis.backlash_steps == 0) {
                    // The common case, without backlash bookkeeping.
                    axis.queue.push_back({t_ns, index, static_cast<std::int8_t>(direction), false});
                    axis.count += direction;
                    axis.motor_count += direction;
                    axis.motor_last_ns = t_ns;
                    axis.last_direction = direction;
                } else {
                    emit(axis, index, t_ns, direction);
                }
            }
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

// Moves every event before the horizon from the axis queues into ready_, merged in time order;
// std::merge takes from its first range on ties, so merging in axis order keeps ties in axis
// order.
void StepGenerator::release() {
    const std::int64_t limit = finished_ ? std::numeric_limits<std::int64_t>::max() : horizon_ns_;
    ready_.erase(ready_.begin(), ready_.begin() + static_cast<std::ptrdiff_t>(ready_head_));
    ready_head_ = 0;
    auto before_limit = [limit](const StepEvent& e) { return e.t_ns < limit; };
    for (AxisState& axis : axes_) {
        const auto begin = axis.queue.begin() + static_cast<std::ptrdiff_t>(axis.head);
        const auto end = std::partition_point(begin, axis.queue.end(), before_limit);
        if (begin == end) continue;
        if (ready_.empty()) {
            ready_.assign(begin, end);
        } else {
            merged_.clear();
            merged_.reserve(ready_.size() + static_cast<std::size_t>(end - begin));
            std::merge(ready_.begin(), ready_.end(), begin, end, std::back_inserter(merged_),
                       [](const StepEvent& a, const StepEvent& b) { return a.t_ns < b.t_ns; });
            ready_.swap(merged_);
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
}

bool StepGenerator::pop(StepEvent& event) {
    if (ready_head_ == ready_.size()) {
        if (!dirty_) return false;
        release();
        dirty_ = false;
        if (ready_head_ == ready_.size()) return false;
    }
    event = ready_[ready_head_++];
    return true;
}

std::vector<StepEvent> generate_steps(const Trajectory& trajectory, const MachineConfig& machine) {
    StepGenerator generator(machine);
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
