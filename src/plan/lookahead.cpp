#include "lookahead.hpp"

#include <algorithm>

#include "profile_inverse.hpp"

namespace nckit::plan_detail {

namespace {
// Plans at least this many new segments at a time: a pass costs about the window's unfinished
// tail, so batching keeps the cost per segment constant (see add()).
constexpr std::size_t min_batch = 64;
//! Runs after a curved one whose end speeds must be final before it is committed (on the 100
//! semicircles at j 5,000: 0, 2, 4, 6, 8 gave 41.62, 41.41, 41.49, 41.46, 40.86 s; more, the same).
constexpr std::size_t curved_commit_ahead = 8;
//! S-curve: the most pieces of a transition in one run. The slow middle of a transition is one
//! run of nearly equal limits, which a bell (bell_search.hpp) can only leave at its end; cut
//! into runs of this many pieces, the bells may start speeding up inside it (on the 100
//! semicircles at j 5,000: no cut 40.61 s; 16, 12, 10, 8, 6, 4, 2 pieces 40.61, 40.57, 40.45,
//! 40.12, 40.83, 40.61, 41.43 s). Since the check lets a speed change pass above the cruise
//! speed and the quintics at joins of arcs are as wide as P allows: 8, 6, 5, 4, 3, 2 pieces
//! 39.36, 39.72, 40.70, 39.24, 39.36, 40.62 s. A run boundary at the slowest piece (the middle
//! of the 32) counts most: the runs' end speeds are their slowest pieces' limits.
constexpr std::size_t transition_run_pieces = 4;

//! A run's limits are its first segment's, lowered by this factor, and never change: a later
//! segment joins only when its own limits are at least the run's. Limits that only ever stay
//! put keep the look-ahead's bounds monotone as the window grows (a committed end speed stays
//! reachable), and the margin lets segments whose limits differ by rounding share a run.
constexpr double run_margin = 1.0 - 1e-9;
//! Trapezoid runs merge segments whose limits are equal up to rounding (see joins_last_run).
constexpr double trapezoid_run_spread = 1.0 + 4e-9;

bool joins(double segment_limit, double run_limit, double spread = run_spread) {
    return segment_limit >= run_limit && segment_limit <= run_limit * spread;
}
bool straight(const WindowSegment& segment) {
    return segment.path.shape != SegmentShape::arc && !(segment.check.cruise_velocity > 0);
}
//! S-curve: the spread of acceleration and jerk limits a segment may share a run with.
double rate_spread(const WindowRun& run, const WindowSegment& segment) {
    return run.straight && straight(segment) ? straight_run_rate_spread : run_spread;
}
}  // namespace

bool Lookahead::ends_transition_run(const WindowRun& run, const WindowSegment& segment) const {
    // Pieces of a transition next to an arc (split for a jerk limit), not a CAM chain's whole
    // transitions between lines.
    const auto transition_piece = [](const WindowSegment& s) {
        return s.path.shape == SegmentShape::quintic && s.check.limits_need_knee;
    };
    return run.count >= transition_run_pieces && transition_piece(segment) && transition_piece(segments_.back());
}

bool Lookahead::joins_last_run(const WindowSegment& segment) const {
    if (runs_.empty() || segments_.back().junction_max <= 0) return false;
    const WindowRun& run = runs_.back();
    if (run.count >= max_run_segments()) return false;
    if (kind_ == ProfileKind::scurve && ends_transition_run(run, segment)) return false;
    const ProfileLimits& l = segment.limits;
    if (kind_ == ProfileKind::trapezoid) {
        // A trapezoid's acceleration may jump at any junction, so ending a run costs nothing:
        // the passes choose its end speed as they would inside a run, and each run is then
        // planned time-optimally with its own limits. Only segments whose limits are the run's
        // (up to rounding) share one, so none runs below its own limits.
        return l.max_velocity >= run.limits.max_velocity && l.max_acceleration >= run.limits.max_acceleration &&
               l.max_velocity <= run.limits.max_velocity * trapezoid_run_spread &&
               l.max_acceleration <= run.limits.max_acceleration * trapezoid_run_spread;
    }
    const bool at_least = l.max_velocity >= run.limits.max_velocity &&
                          l.max_acceleration >= run.limits.max_acceleration && l.max_jerk >= run.limits.max_jerk;
    if (!at_least) return false;
    const double rates = rate_spread(run, segment);
    if (joins(l.max_velocity, run.limits.max_velocity) &&
        joins(l.max_acceleration, run.limits.max_acceleration, rates) &&
        (l.max_jerk == run.limits.max_jerk || joins(l.max_jerk, run.limits.max_jerk, rates))) {
        return true;
    }
    // A faster segment too short to speed up much on its own (e.g. the short lines left between
    // blends in a chain of tiny segments) loses less by running at the run's limits than by
    // ending the run, which would bring the acceleration to 0 at both its ends.
    return segment.path.length < speed_change_distance(run.limits.max_velocity, l.max_velocity, run.limits, kind_);
}

bool Lookahead::lowers_last_run(const WindowSegment& segment, ProfileLimits& lowered) const {
    // Trapezoid runs gain nothing from merging (joins_last_run); a lower segment starts a run.
    if (kind_ != ProfileKind::scurve || runs_.empty() || segments_.back().junction_max <= 0) return false;
    const WindowRun& run = runs_.back();
    if (run.count >= max_run_segments()) return false;
    if (ends_transition_run(run, segment)) return false;
    const ProfileLimits& l = segment.limits;
    const ProfileLimits& first = run.first_limits;
    // Within run_spread of the run's first limits both ways, so the run never drifts far below
    // any of its segments.
    auto near = [](double value, double reference, double spread) {
        return value == reference || (value * spread >= reference && value <= reference * spread);
    };
    const double rates = rate_spread(run, segment);
    if (!near(l.max_velocity, first.max_velocity, run_spread) ||
        !near(l.max_acceleration, first.max_acceleration, rates) || !near(l.max_jerk, first.max_jerk, rates)) {
        return false;
    }
    lowered = {std::min(run.limits.max_velocity, l.max_velocity * run_margin),
               std::min(run.limits.max_acceleration, l.max_acceleration * run_margin),
               std::min(run.limits.max_jerk, l.max_jerk * run_margin)};
    // Safety. The run is the window's last: every pass so far planned it with a stop at its end
    // (bound 0), from a length at most run.length, so the bound of the run before it never
    // exceeded max_end_speed(run.length, 0) with the old limits. Later passes give it at least
    // max_end_speed(length, 0) of its limits then (see plan()). If the longer run with the
    // lower limits can still brake from that speed, no bound upstream can fall below what it
    // was, so every speed already committed stays reachable and stoppable.
    const double before = stop_speed(run);
    const double after = max_end_speed(run.length + segment.path.length, 0.0, lowered, kind_);
    return after >= before;
}

//! Bounded so a run is never more than a quarter of the window (the forced commit keeps half).
std::size_t Lookahead::max_run_segments() const {
    return std::max<std::size_t>(1, window_ / 4);
}

double Lookahead::stop_speed(const WindowRun& run) const {
    if (run.stop_speed < 0 || full_passes_) run.stop_speed = max_end_speed(run.length, 0.0, run.limits, kind_);
    return run.stop_speed;
}

void Lookahead::add(WindowSegment segment) {
    segment.junction_max = std::min(segment.junction_max, segment.limits.max_velocity * run_margin);
    if (!segments_.empty()) {
        WindowSegment& last = segments_.back();
        last.junction_max = std::min(last.junction_max, segment.limits.max_velocity * run_margin);
        runs_.back().junction_max = std::min(last.junction_max, runs_.back().limits.max_velocity);
        touch(runs_.size() - 1);
    }
    ProfileLimits lowered;
    const bool joins = joins_last_run(segment);
    if (joins || lowers_last_run(segment, lowered)) {
        WindowRun& run = runs_.back();
        if (!joins) run.limits = lowered;
        ++run.count;
        run.length += segment.path.length;
        run.junction_max = std::min(segment.junction_max, run.limits.max_velocity);
        run.cruise_velocity = std::min(run.cruise_velocity, segment.check.cruise_velocity);
        run.straight = run.straight && straight(segment);
        run.stop_speed = -1;
        touch(runs_.size() - 1);
    } else {
        WindowRun run;
        run.count = 1;
        run.length = segment.path.length;
        run.limits = {segment.limits.max_velocity * run_margin, segment.limits.max_acceleration * run_margin,
                      segment.limits.max_jerk * run_margin};
        run.first_limits = run.limits;
        run.cruise_velocity = segment.check.cruise_velocity;
        run.straight = straight(segment);
        run.junction_max = std::min(segment.junction_max, run.limits.max_velocity);
        runs_.push_back(run);
        touch(runs_.size() - 1);
    }
    segments_.push_back(std::move(segment));
    ++added_since_plan_;
    if (segments_.size() >= window_) {
        plan(window_ / 2);
    } else if (added_since_plan_ >= std::max(min_batch, left_after_plan_)) {
        // Planning when the new segments outnumber the unfinished ones left by the last pass
        // makes the passes' total cost linear in the program (each segment is visited a bounded
        // number of times on average), yet pieces come out soon after their timing is known.
        plan(window_);
    }
}

void Lookahead::add_event(WindowEvent event, const AxisVector& position) {
    if (segments_.empty()) {
        emit_event(event, position);
    } else {
        segments_.back().after.push_back(std::move(event));
    }
}

void Lookahead::finish() {
    finished_ = true;
    plan(0);
}

void Lookahead::plan(std::size_t keep_at_most) {
    added_since_plan_ = 0;
    const std::size_t n = runs_.size();
    if (n == 0) return;
    if (full_passes_) dirty_from_ = 0;
    // Backward: the end of the window is a stop until more segments arrive; bound[k] is the
    // highest end speed of run k from which every later junction limit can still be kept.
    // bound[k] is a function of run k's junction_max and run k + 1's length, limits and bound:
    // before dirty_from_, where the runs are as the last pass left them, the pass can stop at
    // the first bound that comes out as it was (all earlier ones would too).
    bool next_changed = runs_[n - 1].bound != 0 || runs_[n - 1].bound_final != finished_ || n - 1 >= dirty_from_;
    runs_[n - 1].bound = 0;
    runs_[n - 1].bound_final = finished_;
    for (std::size_t k = n - 1; k-- > 0;) {
        if (!next_changed && k + 1 < dirty_from_) break;
        const WindowRun& next = runs_[k + 1];
        WindowRun& here = runs_[k];
        const double old_bound = here.bound;
        const bool old_final = here.bound_final;
        // max_end_speed(d, v) >= v: once the next bound reaches this junction's limit, no call.
        if (next.bound >= here.junction_max) {
            here.bound = here.junction_max;
            here.bound_final = true;
            next_changed = here.bound != old_bound || !old_final;
            continue;
        }
        // The highest speed from which the next run can brake to its bound *or stop*. With jerk
        // limits braking to a stop can fit where braking to a low speed does not (see
        // speed_change.hpp), so max_end_speed(d, w) dips as w rises from 0; taking the larger
        // of the two makes the bound grow with w, so bounds only rise as the window grows and a
        // committed speed stays stoppable. From any start at or below it, plan_profile's end
        // speed is never above the one asked for (it picks the highest reachable below).
        double brake_from =
            next.bound > 0 ? max_end_speed(next.length, next.bound, next.limits, kind_) : stop_speed(next);
        if (kind_ == ProfileKind::scurve && next.bound > 0) {
            brake_from = std::max(brake_from, stop_speed(next));
        }
        here.bound = std::min(here.junction_max, brake_from);
        // Held by its own junction limit, or by braking for a later run whose bound is final (a
        // junction limit ahead, not the window's provisional stop): more segments cannot raise it.
        here.bound_final = here.bound >= here.junction_max || next.bound_final;
        next_changed = here.bound != old_bound || here.bound_final != old_final;
    }
    dirty_from_ = n;
    // Forward: commit runs while their end speed is final, i.e. no later segment could raise it
    // (it is held by its junction limit or by how fast it can speed up, not by the window's
    // stop); when the window is too full, commit as planned anyway.
    while (!runs_.empty()) {
        double v_end = 0;
        bool final_speed = end_speed(runs_.front(), start_speed_, v_end);
        // A run of curved pieces waits until the runs after it are final too: a bell or merge
        // over them (merge_following) needs their end speeds, and committed early the run
        // would have had to take its own profile.
        if (final_speed && kind_ == ProfileKind::scurve && !finished_ && runs_.front().cruise_velocity > 0) {
            final_speed = following_runs_final(v_end);
        }
        if (!final_speed && segments_.size() <= keep_at_most) break;
        commit_front(v_end);
    }
    left_after_plan_ = segments_.size();
    dirty_from_ = runs_.size();
}

bool Lookahead::following_runs_final(double v_front_end) const {
    double v = v_front_end;
    for (std::size_t m = 1; m <= curved_commit_ahead; ++m) {
        if (m >= runs_.size()) return false;
        double v_end = 0;
        if (!end_speed(runs_[m], v, v_end)) return false;
        v = v_end;
    }
    return true;
}

bool Lookahead::end_speed(const WindowRun& r, double v_start, double& v_end) const {
    if (v_start >= r.bound) {
        v_end = r.bound;
        return finished_ || (final_bound_commits_ ? r.bound_final : r.bound >= r.junction_max);
    }
    const double reachable = max_end_speed(r.length, v_start, r.limits, kind_);
    v_end = std::min(r.bound, reachable);
    return finished_ || (final_bound_commits_ && r.bound_final) || r.bound >= std::min(r.junction_max, reachable);
}

void Lookahead::commit_front(double v_end) {
    Profile profile = run_profile(runs_.front(), 0, start_speed_, v_end);
    const std::size_t taken = kind_ == ProfileKind::scurve && merge_runs_ ? merge_following(profile) : 1;
    std::size_t count = 0;
    for (std::size_t k = 0; k < taken; ++k) {
        count += runs_.front().count;
        runs_.pop_front();
        if (dirty_from_ > 0) --dirty_from_;
    }
    const double total_s = profile.duration_s();
    start_speed_ = profile.end_velocity;
    ProfileWalker walker(profile);
    double offset_mm = 0;
    double offset_s = 0;
    const double run_start_s = clock_s_;
    for (std::size_t i = 0; i < count; ++i) {
        WindowSegment& s = segments_.front();
        const bool last = i + 1 == count;
        const double end_mm = offset_mm + s.path.length;
        const double end_s = last ? total_s : std::max(offset_s, walker.time_at(end_mm));
        TrajectoryPiece& piece = output_.push_back_slot();
        piece.kind = PieceKind::motion;
        piece.profile = profile;
        piece.profile_offset_s = offset_s;
        piece.profile_offset_mm = offset_mm;
        piece.ends_profile = last;
        piece.start_time_s = run_start_s + offset_s;
        piece.duration_s = end_s - offset_s;
        piece.where = std::move(s.where);
        piece.sequence_number = s.sequence_number;
        piece.blend = s.blend;
        piece.continues_move = s.continues_move;
        piece.segment = s.path;
        piece.io = Io{};
        piece.waits_for_index = false;
        clock_s_ = run_start_s + end_s;
        if (!s.after.empty()) {
            const AxisVector end = end_point(s.path);
            for (const WindowEvent& event : s.after) emit_event(event, end);
        }
        offset_mm = end_mm;
        offset_s = end_s;
        segments_.pop_front();
    }
}

void Lookahead::emit_event(const WindowEvent& event, const AxisVector& position) {
    TrajectoryPiece piece;
    piece.kind = event.kind;
    piece.segment = make_line(position, position);
    piece.start_time_s = clock_s_;
    piece.duration_s = event.kind == PieceKind::dwell ? std::max(0.0, event.dwell_s) : 0.0;
    if (event.wait_index) {
        // The planner refuses G32/G33 with the spindle stopped, so an index always comes.
        const std::optional<double> index_s = spindle_.next_index_s(clock_s_, event.index_angle_deg);
        piece.duration_s = index_s ? *index_s - clock_s_ : 0.0;
        piece.waits_for_index = true;
        piece.index_angle_deg = event.index_angle_deg;
    }
    piece.where = event.where;
    piece.sequence_number = event.sequence_number;
    piece.io = event.io;
    if (event.kind == PieceKind::io && spindle_command_.apply(event.io)) {
        spindle_.set_speed(clock_s_, spindle_command_.signed_rpm(spindle_.config()));
    }
    clock_s_ += piece.duration_s;
    output_.push_back(std::move(piece));
}

}  // namespace nckit::plan_detail
