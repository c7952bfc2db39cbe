// The Planner: turns Moves into window segments, deciding each junction (stop, pass, blend).
#include "nckit/plan/planner.hpp"

#include <cmath>

#include <fmt/format.h>
#include <limits>
#include <stdexcept>
#include <utility>

#include "junction.hpp"
#include "lookahead.hpp"
#include "nckit/plan/segment_limits.hpp"

namespace nckit {

using plan_detail::WindowEvent;
using plan_detail::WindowSegment;

namespace {

// Moves shorter than this (mm, or deg for rotary-only moves) do not move the machine.
constexpr double min_length = 1e-9;
// A trimmed line shorter than this is dropped; the blends on both sides then meet tangentially.
constexpr double min_trimmed_length = 1e-12;

}  // namespace

struct Planner::Impl {
    //! The last motion, whose end may still be trimmed by a blend with the next one.
    struct Pending {
        PathSegment path;
        double full_length = 0;  //!< programmed length, for the half-line rule
        ProfileLimits limits;
        double feed_mm_s = 0;    //!< +inf for rapids
        bool blendable = false;  //!< a G1 line
        PathControl control;
        SourceLocation where;
        std::int64_t sequence_number = -1;
    };

    MachineConfig machine;
    PlannerOptions options;
    ProfileKind kind;
    plan_detail::Lookahead lookahead;
    std::optional<Pending> pending;
    std::vector<WindowEvent> pending_events;
    AxisVector position;  //!< where the path added so far ends
    bool have_position = false;            //!< a motion has told where the machine is
    std::vector<WindowEvent> leading_events;  //!< events before the first motion: place unknown
    Diagnostics diagnostics;
    SpindleCommand spindle;         //!< the spindle as the moves pushed so far leave it
    bool last_motion_sync = false;  //!< the last motion was G32/G33: a thread goes on at speed

    Impl(MachineConfig m, PlannerOptions o)
        : machine(std::move(m)),
          options(o),
          kind(o.profile.value_or(machine.profile)),
          lookahead(kind, o.window_moves, machine.spindle) {}

    void add_segment(PathSegment path, const ProfileLimits& limits, double junction_max, const SourceLocation& where,
                     std::int64_t sequence_number, bool blend, std::vector<WindowEvent> after) {
        position = end_point(path);
        WindowSegment s;
        s.path = std::move(path);
        s.limits = limits;
        s.junction_max = junction_max;
        s.where = where;
        s.sequence_number = sequence_number;
        s.blend = blend;
        s.after = std::move(after);
        lookahead.add(std::move(s));
    }

    //! The pending motion goes to the window, ending with junction limit junction_max.
    void release_pending(double junction_max) {
        if (!pending) return;
        Pending& p = *pending;
        if (p.path.length > min_trimmed_length) {
            add_segment(std::move(p.path), p.limits, junction_max, p.where, p.sequence_number, false,
                        std::move(pending_events));
        } else {
            for (WindowEvent& e : pending_events) lookahead.add_event(std::move(e), position);
        }
        pending_events.clear();
        pending.reset();
    }

    void connect(Pending next) {
        if (pending) {
            Pending& p = *pending;
            if (p.control.exact_stop) {
                release_pending(0.0);
            } else if (plan_detail::tangent(p.path, next.path)) {
                release_pending(p.limits.max_velocity);
            } else if (p.blendable && next.blendable) {
                const double tolerance = p.control.tolerance_mm > 0 ? p.control.tolerance_mm
                                                                    : options.default_blend_tolerance_mm;
                auto blend = plan_detail::blend_lines(p.path, p.full_length, next.path, tolerance);
                if (blend) {
                    p.path.length -= blend->trim_mm;
                    const ProfileLimits limits = segment_limits(
                        blend->arc, machine, std::min(p.feed_mm_s, next.feed_mm_s), kind,
                        kind == ProfileKind::trapezoid ? trapezoid_blend_normal_share : 0.5);
                    const SourceLocation where = p.where;
                    const std::int64_t number = p.sequence_number;
                    release_pending(p.limits.max_velocity);
                    add_segment(blend->arc, limits, limits.max_velocity, where, number, true, {});
                    next.path.origin = position_at(next.path, blend->trim_mm);
                    next.path.length -= blend->trim_mm;
                } else {
                    release_pending(0.0);
                }
            } else {
                release_pending(0.0);
            }
        }
        pending = std::move(next);
    }

    bool check_axes(const PathSegment& path, const SourceLocation& where) {
        const DerivativeBounds b = derivative_bounds(path);
        for (std::size_t i = 0; i < axis_count; ++i) {
            if (b.d1[i] > 0 && machine.find(static_cast<Axis>(i)) == nullptr) {
                diagnostics.push_back(error_at(where, "unknown-axis",
                                               std::string("move of axis ") + axis_letters[i] +
                                                   ", which the machine does not have"));
                return false;
            }
        }
        return true;
    }

    void motion(PathSegment path, double feed_mm_s, bool blendable, PathControl control, const Move& move) {
        if (!(path.length > min_length)) {
            if (control.exact_stop) release_pending(0.0);
            return;
        }
        if (!(feed_mm_s > 0)) {
            diagnostics.push_back(error_at(move.where, "no-feed", "cutting move with no usable feed rate"));
            return;
        }
        if (!check_axes(path, move.where)) return;
        Pending next;
        next.limits = segment_limits(path, machine, feed_mm_s, kind);
        next.full_length = path.length;
        next.path = std::move(path);
        next.feed_mm_s = feed_mm_s;
        next.blendable = blendable;
        next.control = control;
        next.where = move.where;
        next.sequence_number = move.sequence_number;
        connect(std::move(next));
    }

    //! The machine is at `from` (the start of a motion).
    void locate(const AxisVector& from) {
        if (pending) return;
        position = from;
        if (!have_position) {
            have_position = true;
            for (WindowEvent& e : leading_events) lookahead.add_event(std::move(e), position);
            leading_events.clear();
        }
    }

    void event(WindowEvent e, bool stop) {
        if (stop) release_pending(0.0);
        if (!have_position) {
            leading_events.push_back(std::move(e));
        } else if (pending) {
            pending_events.push_back(std::move(e));
        } else {
            lookahead.add_event(std::move(e), position);
        }
    }

    //! mm/s of a programmed feed. G95 follows the spindle: mm/rev times the speed it turns at
    //! on average (its ripple slows a turn), not the S word alone; without a turning spindle the
    //! interpreter's figure stands (0 when it knew no speed either: "no usable feed").
    [[nodiscard]] double feed_mm_s(const Feed& feed) const {
        if (feed.mode != FeedMode::per_revolution) return feed.mm_per_min / 60.0;
        const double rpm = spindle.mean_rpm(machine.spindle);
        if (rpm == 0.0) return feed.mm_per_min / 60.0;
        return feed.mm_per_rev * rpm / 60.0;
    }

    //! G32/G33: the axes stop, wait for the index pulse, and move the lead per turn, without
    //! feed override (locked, as on Fanuc and LinuxCNC). A thread chained to the previous G32
    //! goes on at speed; anything else in between means a new wait, so every pass of a
    //! repeated thread starts at the same spindle angle.
    void sync_motion(const SyncMove& sync, const Move& move, bool after_sync) {
        const double rpm = spindle.signed_rpm(machine.spindle);
        if (rpm == 0.0) {
            diagnostics.push_back(error_at(move.where, "sync-spindle-stopped",
                                           "G32/G33 needs the spindle turning (M3 or M4 with S): no index pulse to wait for"));
            return;
        }
        PathSegment path = make_line(sync.from, sync.to);
        if (!(path.length > min_length)) return;
        const double speed_mm_s = sync.feed.mm_per_rev * spindle.mean_rpm(machine.spindle) / 60.0;
        if (!(speed_mm_s > 0)) {
            diagnostics.push_back(error_at(move.where, "no-feed", "G32/G33 with no lead (F)"));
            return;
        }
        if (!check_axes(path, move.where)) return;
        const ProfileLimits limits = segment_limits(path, machine, speed_mm_s, kind);
        // The axes must keep up with the spindle's fastest moment, not only its mean.
        const double peak_mm_s = sync.feed.mm_per_rev * std::abs(rpm) * (1.0 + machine.spindle.ripple_fraction) / 60.0;
        const ProfileLimits axis_limits =
            segment_limits(path, machine, std::numeric_limits<double>::infinity(), kind);
        if (peak_mm_s > axis_limits.max_velocity * (1.0 + 1e-9)) {
            diagnostics.push_back(error_at(
                move.where, "sync-too-fast",
                fmt::format("a lead of {} mm/rev at {} rpm needs {:.6g} mm/s along the thread, more than the axes' "
                            "{:.6g} mm/s: lower S",
                            sync.feed.mm_per_rev, std::abs(rpm), peak_mm_s, axis_limits.max_velocity)));
            return;
        }
        if (!after_sync) {
            release_pending(0.0);
            WindowEvent wait;
            wait.kind = PieceKind::dwell;
            wait.wait_index = true;
            wait.where = move.where;
            wait.sequence_number = move.sequence_number;
            event(std::move(wait), true);
        }
        Pending next;
        next.limits = limits;
        next.full_length = path.length;
        next.path = std::move(path);
        next.feed_mm_s = speed_mm_s;
        next.blendable = false;
        next.where = move.where;
        next.sequence_number = move.sequence_number;
        connect(std::move(next));
        last_motion_sync = true;
    }

    void push(const Move& move) {
        if (!diagnostics.empty()) return;
        const double override_factor = options.feed_override;
        const bool after_sync = std::exchange(last_motion_sync, false);
        if (const auto* line = std::get_if<Line>(&move.what)) {
            locate(line->from);
            const double feed = line->rapid ? std::numeric_limits<double>::infinity()
                                            : feed_mm_s(line->feed) * override_factor;
            motion(make_line(line->from, line->to), feed, !line->rapid, line->path, move);
        } else if (const auto* arc = std::get_if<Arc>(&move.what)) {
            locate(arc->from);
            motion(make_arc(*arc), feed_mm_s(arc->feed) * override_factor, false, arc->path, move);
        } else if (const auto* sync = std::get_if<SyncMove>(&move.what)) {
            locate(sync->from);
            sync_motion(*sync, move, after_sync);
            return;
        } else if (const auto* dwell = std::get_if<Dwell>(&move.what)) {
            WindowEvent e;
            e.kind = PieceKind::dwell;
            e.dwell_s = dwell->seconds;
            e.where = move.where;
            e.sequence_number = move.sequence_number;
            event(std::move(e), true);
        } else if (const auto* io = std::get_if<Io>(&move.what)) {
            spindle.apply(*io);
            const bool waits = io->waits || (io->kind == IoKind::mcode && machine.is_exact_stop_mcode(io->number));
            WindowEvent e;
            e.kind = PieceKind::io;
            e.io = *io;
            e.io.waits = waits;
            e.where = move.where;
            e.sequence_number = move.sequence_number;
            event(std::move(e), waits);
        }
    }
};

Planner::Planner(MachineConfig machine, PlannerOptions options) {
    if (!(options.feed_override > 0 && options.feed_override <= 2)) {
        throw std::invalid_argument("feed_override must be in (0, 2]");
    }
    if (options.window_moves < 2) throw std::invalid_argument("window_moves must be at least 2");
    if (!(options.default_blend_tolerance_mm >= 0)) throw std::invalid_argument("negative blend tolerance");
    impl_ = std::make_unique<Impl>(std::move(machine), options);
}

Planner::~Planner() = default;
Planner::Planner(Planner&&) noexcept = default;
Planner& Planner::operator=(Planner&&) noexcept = default;

void Planner::push(const Move& move) { impl_->push(move); }

void Planner::finish() {
    impl_->release_pending(0.0);
    impl_->locate(impl_->position);  // events of a program without motion: at the origin
    impl_->lookahead.finish();
}

bool Planner::pop(TrajectoryPiece& piece) {
    auto& out = impl_->lookahead.output();
    if (out.empty()) return false;
    piece = std::move(out.front());
    out.pop_front();
    return true;
}

const Diagnostics& Planner::diagnostics() const { return impl_->diagnostics; }

PlanResult plan_moves(const std::vector<Move>& moves, const MachineConfig& machine, const PlannerOptions& options) {
    PlanResult result;
    Planner planner(machine, options);
    TrajectoryPiece piece;
    for (const Move& move : moves) {
        planner.push(move);
        while (planner.pop(piece)) result.trajectory.pieces.push_back(std::move(piece));
    }
    planner.finish();
    while (planner.pop(piece)) result.trajectory.pieces.push_back(std::move(piece));
    result.diagnostics = planner.diagnostics();
    return result;
}

}  // namespace nckit
