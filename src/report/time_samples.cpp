#include "nckit/report/time_samples.hpp"

#include <cmath>

namespace nckit {

TimeSampler::TimeSampler(const MachineConfig& machine, std::size_t max_samples) : max_samples_(max_samples) {
    samples_.period_s = machine.servo_period_s;
    for (std::size_t i = 0; i < axis_count; ++i) {
        if (machine.find(static_cast<Axis>(i)) != nullptr) samples_.axes.push_back(static_cast<Axis>(i));
    }
    const std::size_t n = samples_.axes.size();
    samples_.position.resize(n);
    samples_.velocity.resize(n);
    samples_.acceleration.resize(n);
    samples_.jerk.resize(n);
}

void TimeSampler::take(const TrajectorySample& s) {
    samples_.t_s.push_back(s.t);
    for (std::size_t k = 0; k < samples_.axes.size(); ++k) {
        const Axis axis = samples_.axes[k];
        samples_.position[k].push_back(s.position[axis]);
        samples_.velocity[k].push_back(s.velocity[axis]);
        samples_.acceleration[k].push_back(s.acceleration[axis]);
        samples_.jerk[k].push_back(s.jerk[axis]);
    }
    const double xyz = std::hypot(s.velocity[Axis::X], s.velocity[Axis::Y], s.velocity[Axis::Z]);
    samples_.speed_mm_s.push_back(xyz > 0 ? xyz : std::abs(s.path_velocity));
}

void TimeSampler::halve() {
    auto keep_even = [](std::vector<double>& v) {
        std::size_t out = 0;
        for (std::size_t i = 0; i < v.size(); i += 2) v[out++] = v[i];
        v.resize(out);
    };
    keep_even(samples_.t_s);
    keep_even(samples_.speed_mm_s);
    for (auto* group : {&samples_.position, &samples_.velocity, &samples_.acceleration, &samples_.jerk}) {
        for (auto& v : *group) keep_even(v);
    }
    // Samples are at multiples of the period from t = 0, so the even ones are the new period's.
    samples_.period_s *= 2;
    next_index_ = (next_index_ + 1) / 2;
}

void TimeSampler::add(const TrajectoryPiece& piece) {
    if (piece.duration_s <= 0) return;
    const double end_s = piece.start_time_s + piece.duration_s;
    // Each pass takes one sample or halves the store, and halving doubles the step: the loop
    // runs at most about 2·max_samples times per halving, whatever the piece's length.
    for (;;) {
        const double t = static_cast<double>(next_index_) * samples_.period_s;
        if (t >= end_s) break;
        if (t >= piece.start_time_s) take(sample(piece, t));
        ++next_index_;
        if (samples_.t_s.size() >= 2 * max_samples_) halve();
    }
    last_ = piece;
    any_ = true;
}

TimeSamples TimeSampler::finish() {
    if (any_) {
        const double end_s = last_.start_time_s + last_.duration_s;
        if (samples_.t_s.empty() || samples_.t_s.back() < end_s) take(sample(last_, end_s));
    }
    return std::move(samples_);
}

}  // namespace nckit
