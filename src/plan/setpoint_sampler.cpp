#include "nckit/plan/setpoint_sampler.hpp"

#include <algorithm>
#include <stdexcept>

namespace nckit {

SetpointSampler::SetpointSampler(double period_s, SamplerEnd end_rule) : period_s_(period_s), end_rule_(end_rule) {
    if (!(period_s > 0)) throw std::invalid_argument("SetpointSampler: the period must be > 0");
}

void SetpointSampler::add(const TrajectoryPiece& piece, const Sink& sink) {
    const double end = piece.start_time_s + piece.duration_s;
    for (double t = time_of(next_index_); t < end; t = time_of(++next_index_)) sink(sample(piece, t));
    last_ = piece;
    end_s_ = std::max(end_s_, end);
    any_ = true;
}

void SetpointSampler::finish(const Sink& sink) {
    if (!any_) return;
    for (;;) {
        const double t = time_of(next_index_);
        if (end_rule_ == SamplerEnd::within_cycle && t > end_s_ + 1e-12) break;
        // sample() clamps into the last piece: past its end the setpoint is the end position.
        TrajectorySample s = sample(last_, t);
        s.t = t;
        sink(s);
        ++next_index_;
        if (end_rule_ == SamplerEnd::through_first_after_end && t >= end_s_) break;
    }
}

}  // namespace nckit
