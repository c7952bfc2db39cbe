// The Planner: turns Moves into window segments, deciding each junction (stop, pass, blend).
#include "nckit/plan/planner.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "chain_smoother.hpp"
#include "corner_stop.hpp"
#include "junction.hpp"
#include "lookahead.hpp"
#include "pending_motion.hpp"
#include "ramp_transition.hpp"
#include "transition.hpp"
#include "window_feed.hpp"
#include "nckit/plan/segment_limits.hpp"

namespace nckit {

using plan_detail::WindowEvent;
using plan_detail::WindowSegment;

// A trimmed line shorter than this is dropped; the blends on both sides then meet tangentially.
constexpr double min_trimmed_length = 1e-12;

struct Planner::Impl {
    using Pending = plan_detail::PendingMotion;

    MachineConfig machine;
    PlannerOptions options;
    ProfileKind kind;
    plan_detail::Lookahead lookahead;
    plan_detail::WindowFeed window_feed;  //!< where segments enter the lookahead; knows where the path ends
    //! Two slots the pending motion and the next one alternate in: a Pending holds a whole
    //! transition (about 2 kB), which moving from a local into an optional cost on every move.
    std::array<Pending, 2> slots;
    Pending* pending = nullptr;  //!< one of slots, or none
    std::vector<WindowEvent> pending_events;
    bool have_position = false;               //!< a motion has told where the machine is
    std::vector<WindowEvent> leading_events;  //!< events before the first motion: place unknown
    Diagnostics diagnostics;
    SpindleCommand spindle;              //!< the spindle as the moves pushed so far leave it
    bool last_motion_sync = false;       //!< the last motion was G32/G33: a thread goes on at speed
    plan_detail::ChainSmoother chains;   //!< S-curve: CAM polylines smoothed within G64 P
    plan_detail::TurningLimits turning;  //!< X, Y, Z limits, for choosing a transition's shape

    Impl(MachineConfig m, PlannerOptions o)
        : machine(std::move(m)),
          options(o),
          kind(o.profile.value_or(machine.profile)),
          lookahead(kind, o.window_moves, machine.spindle),
          window_feed(machine, kind, lookahead),
          turning(plan_detail::turning_limits(machine)) {}

    //! The pending motion goes to the window, ending at rest when `stop`, else at most at its own
    //! speed limit (the next segment's lowers it further). An arc whose curvature sets its speed
    //! goes as pieces with limits of their own (arc_pieces.hpp).
    void release_pending(bool stop) {
        if (!pending) return;
        Pending& p = *pending;
        const bool eaten = stop && kind == ProfileKind::scurve && plan_detail::end_at_rest(p);
        if (p.entry) {
            window_feed.add_transition(*p.entry, p.entry_feed_mm_s, {p.entry_where, p.entry_number}, eaten);
            p.entry.reset();
        }
        if (!(p.path.length > min_trimmed_length)) {
            for (WindowEvent& e : pending_events) lookahead.add_event(std::move(e), window_feed.position);
        } else {
            window_feed.add_motion(std::move(p.path), p.feed_mm_s, stop, {p.where, p.sequence_number, p.spindle_locked},
                                   std::move(pending_events), p.limits, p.normal_share);
        }
        pending_events.clear();
        pending = nullptr;
    }

    //! The slot the pending motion is not in, emptied for the next motion (its path is the
    //! caller's to set).
    Pending& fresh_slot() {
        Pending& s = pending == &slots[0] ? slots[1] : slots[0];
        s.full_length = 0;
        s.limits.reset();
        s.normal_share = 0.5;
        s.feed_mm_s = 0;
        s.blendable = false;
        s.spindle_locked = false;
        s.control = PathControl{};
        s.where = SourceLocation{};
        s.sequence_number = -1;
        s.entry.reset();
        s.entry_feed_mm_s = 0;
        s.entry_tolerance_mm = 0;
        s.entry_where = SourceLocation{};
        s.entry_number = -1;
        return s;
    }

    void connect(Pending& next) {
        if (pending) {
            Pending& p = *pending;
            // Trapezoids may step the acceleration, so only the direction must be continuous;
            // a jerk limit needs the curvature continuous too (docs/planner.md).
            const bool jerk_limited = kind == ProfileKind::scurve;
            if (p.control.exact_stop) {
                release_pending(true);
            } else if (jerk_limited
                           ? plan_detail::smooth_join(p.path, next.path, plan_detail::smooth_direction_tolerance, true)
                           : plan_detail::tangent(p.path, next.path)) {
                release_pending(false);
            } else if (p.blendable && next.blendable) {
                const double tolerance =
                    p.control.tolerance_mm > 0 ? p.control.tolerance_mm : options.default_blend_tolerance_mm;
                const bool rounded =
                    (!jerk_limited && blend_corner(p, next, tolerance)) || transition(p, next, tolerance);
                if (!rounded) {
                    release_pending(true);
                }
            } else {
                release_pending(true);
            }
        }
        pending = &next;
    }

    //! Trapezoid plans round a corner between two lines with a parabola (junction.hpp).
    bool blend_corner(Pending& p, Pending& next, double tolerance) {
        auto blend = plan_detail::parabolic_corner(p.path, p.full_length, next.path, tolerance);
        if (!blend) return false;
        p.path.length -= blend->trim_mm;
        insert_between(p, next, blend->arc, blend->trim_mm, trapezoid_blend_normal_share);
        return true;
    }

    //! Any other corner, and every join with a jump in curvature under a jerk limit: a quintic
    //! transition within the tolerance (pending_motion.hpp), or a stop where faster (corner_stop.hpp).
    bool transition(Pending& p, Pending& next, double tolerance) {
        const plan_detail::TurningLimits* limits = kind == ProfileKind::scurve ? &turning : nullptr;
        const bool from_rest = window_feed.at_rest() && !p.entry;  // p follows a stop
        if (!plan_detail::join_by_transition(p, next, tolerance, limits, from_rest)) return false;
        if (limits && options.stop_sharp_corners && plan_detail::unjoin_for_a_stop(p, next, *limits)) return false;
        release_pending(false);
        return true;
    }

    //! `curve` goes between the pending motion (already trimmed) and `next`, whose start loses
    //! trim_after.
    void insert_between(Pending& p, Pending& next, const PathSegment& curve, double trim_after, double normal_share) {
        const ProfileLimits limits =
            segment_limits(curve, machine, std::min(p.feed_mm_s, next.feed_mm_s), kind, normal_share);
        const SourceLocation where = p.where;
        const std::int64_t number = p.sequence_number;
        release_pending(false);
        window_feed.add_segment(curve, limits, limits.max_velocity, {where, number}, true, {});
        next.path = trim_start(next.path, trim_after);
    }

    bool check_axes(const PathSegment& path, const SourceLocation& where) {
        // A line moves exactly the axes its rate moves; other shapes by their bounds.
        const AxisVector moving = path.shape == SegmentShape::line ? path.rate : derivative_bounds(path).d1;
        for (std::size_t i = 0; i < axis_count; ++i) {
            if (moving[i] != 0 && machine.find(static_cast<Axis>(i)) == nullptr) {
                diagnostics.push_back(
                    error_at(where, "unknown-axis",
                             std::string("move of axis ") + axis_letters[i] + ", which the machine does not have"));
                return false;
            }
        }
        return true;
    }

    //! `path` by reference: a path segment passed by value is copied into the call's arguments
    //! (a few hundred bytes per move), and then once more into the pending slot.
    void motion(const PathSegment& path, double feed_mm_s, bool blendable, PathControl control, const Move& move) {
        if (!(path.length > min_move_length)) {
            if (control.exact_stop) release_pending(true);
            return;
        }
        if (!(feed_mm_s > 0)) {
            diagnostics.push_back(error_at(move.where, "no-feed", "cutting move with no usable feed rate"));
            return;
        }
        if (!check_axes(path, move.where)) return;
        Pending& next = fresh_slot();
        // A trapezoid arc runs at constant speed where it is slowest: like a blend, it gives most
        // of the acceleration to the turning (the rest still changes speed along it).
        const double share =
            kind == ProfileKind::trapezoid && path.shape == SegmentShape::arc ? trapezoid_blend_normal_share : 0.5;
        next.normal_share = share;
        next.full_length = path.length;
        next.path = path;
        next.feed_mm_s = feed_mm_s;
        next.blendable = blendable;
        next.control = control;
        next.where = move.where;
        next.sequence_number = move.sequence_number;
        connect(next);
    }

    //! The machine is at `from` (the start of a motion).
    void locate(const AxisVector& from) {
        if (pending) return;
        window_feed.position = from;
        if (!have_position) {
            have_position = true;
            for (WindowEvent& e : leading_events) lookahead.add_event(std::move(e), window_feed.position);
            leading_events.clear();
        }
    }

    void event(WindowEvent e, bool stop) {
        if (stop) release_pending(true);
        if (!have_position) {
            leading_events.push_back(std::move(e));
        } else if (pending) {
            pending_events.push_back(std::move(e));
        } else {
            lookahead.add_event(std::move(e), window_feed.position);
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

    //! G32/G33: the axes stop, wait for the index pulse (or the start angle past it, Q), and
    //! move the lead per turn, without feed override (locked, as on Fanuc and LinuxCNC). A
    //! thread chained to the previous G32 goes on at speed (its Q has no effect, as on Fanuc);
    //! anything else in between means a new wait, so every pass of a repeated thread starts at
    //! the same spindle angle, and each start of a multi-start thread at its own.
    void sync_motion(const SyncMove& sync, const Move& move, bool after_sync) {
        const double rpm = spindle.signed_rpm(machine.spindle);
        if (rpm == 0.0) {
            diagnostics.push_back(
                error_at(move.where, "sync-spindle-stopped",
                         "G32/G33 needs the spindle turning (M3 or M4 with S): no index pulse to wait for"));
            return;
        }
        PathSegment path = make_line(sync.from, sync.to);
        if (!(path.length > min_move_length)) return;
        const double speed_mm_s = sync.feed.mm_per_rev * spindle.mean_rpm(machine.spindle) / 60.0;
        if (!(speed_mm_s > 0)) {
            diagnostics.push_back(error_at(move.where, "no-feed", "G32/G33 with no lead (F)"));
            return;
        }
        if (!check_axes(path, move.where)) return;
        const ProfileLimits limits = segment_limits(path, machine, speed_mm_s, kind);
        // The axes must keep up with the spindle's fastest moment, not only its mean.
        const double peak_mm_s = sync.feed.mm_per_rev * std::abs(rpm) * (1.0 + machine.spindle.ripple_fraction) / 60.0;
        const ProfileLimits axis_limits = segment_limits(path, machine, std::numeric_limits<double>::infinity(), kind);
        if (peak_mm_s > axis_limits.max_velocity * (1.0 + 1e-9)) {
            diagnostics.push_back(error_at(
                move.where, "sync-too-fast",
                fmt::format("a lead of {} mm/rev at {} rpm needs {:.6g} mm/s along the thread, more than the axes' "
                            "{:.6g} mm/s: lower S",
                            sync.feed.mm_per_rev, std::abs(rpm), peak_mm_s, axis_limits.max_velocity)));
            return;
        }
        if (!after_sync) {
            release_pending(true);
            WindowEvent wait;
            wait.kind = PieceKind::dwell;
            wait.wait_index = true;
            wait.index_angle_deg = sync.start_angle_deg;
            wait.where = move.where;
            wait.sequence_number = move.sequence_number;
            event(std::move(wait), true);
        }
        Pending& next = fresh_slot();
        next.limits = limits;
        next.full_length = path.length;
        next.path = path;
        next.feed_mm_s = speed_mm_s;
        next.blendable = false;
        next.spindle_locked = true;
        next.where = move.where;
        next.sequence_number = move.sequence_number;
        connect(next);
        last_motion_sync = true;
    }

    //! Under a jerk limit, G1 lines go through the chain smoother first (chain_smoother.hpp).
    void push(const Move& move) {
        if (!diagnostics.empty()) return;
        if (kind != ProfileKind::scurve) {
            plan(move);
            return;
        }
        double tolerance = 0;
        if (const auto* line = std::get_if<Line>(&move.what)) {
            tolerance = line->path.tolerance_mm > 0 ? line->path.tolerance_mm : options.default_blend_tolerance_mm;
        }
        const bool held = chains.push(move, tolerance);
        if (!held) chains.flush();
        drain_chains();
        if (!held) plan(move);
    }

    void drain_chains() {
        while (const Move* smoothed = chains.ready()) {
            plan(*smoothed);
            chains.drop_ready();
        }
    }

    void finish() {
        chains.flush();
        drain_chains();
        release_pending(true);
        locate(window_feed.position);  // events of a program without motion: at the origin
        lookahead.finish();
    }

    void plan(const Move& move) {
        if (!diagnostics.empty()) return;
        const double override_factor = options.feed_override;
        const bool after_sync = std::exchange(last_motion_sync, false);
        if (const auto* line = std::get_if<Line>(&move.what)) {
            locate(line->from);
            const double feed =
                line->rapid ? std::numeric_limits<double>::infinity() : feed_mm_s(line->feed) * override_factor;
            motion(make_line(line->from, line->to), feed, !line->rapid, line->path, move);
        } else if (const auto* arc = std::get_if<Arc>(&move.what)) {
            locate(arc->from);
            motion(make_arc(*arc), feed_mm_s(arc->feed) * override_factor, true, arc->path, move);
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

void Planner::push(const Move& move) {
    impl_->push(move);
}

void Planner::finish() {
    impl_->finish();
}

bool Planner::pop(TrajectoryPiece& piece) {
    auto& out = impl_->lookahead.output();
    if (out.empty()) return false;
    piece = std::move(out.front());
    out.pop_front();
    return true;
}

const Diagnostics& Planner::diagnostics() const {
    return impl_->diagnostics;
}

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
