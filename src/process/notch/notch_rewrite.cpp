// Finding the cuts and rewriting them: run-up before the notch start, overrun past its end.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include <fmt/format.h>

#include "nckit/process/notch/notch.hpp"
#include "nckit/plan/profile.hpp"
#include "notch_geometry.hpp"
#include "nckit/plan/segment_limits.hpp"

namespace nckit {

namespace {

using notch_detail::dot;
using notch_detail::scaled;

bool is_motion(const Move& move) {
    return notch_detail::motion_ends(move).has_value();
}

const Io* mcode_of(const Move& move) {
    const auto* io = std::get_if<Io>(&move.what);
    return io != nullptr && io->kind == IoKind::mcode ? io : nullptr;
}

//! The written program keeps 4 decimals in mm; rounding a distance *up* to that grid keeps the
//! written run-up at least as long as the S-curve needs (a notch start on the grid stays there).
double round_up_to_grid(double mm) {
    return std::ceil(mm * 1e4 - 1e-6) / 1e4;
}

//! A point on the cut's line `distance_mm` (at least) beyond `from`, away from `toward`, whose
//! written coordinates (10 decimals) lie exactly on that line. When both ends are on the 4-decimal
//! grid of a program, the point is from + k·(from − toward) with k a multiple of 1e-6 (rounded
//! up): in units of 1e-10 mm every coordinate is then a whole number, from·1e6 + m·(from − toward),
//! so the written run-up continues the cut without the bend a rounded point would put there.
//! Off that grid, the point along the direction (off the line by under 1e-10 mm when written).
struct PlacedPoint {
    AxisVector point;
    double distance_mm = 0;  //!< how far beyond `from` it lies, >= the distance asked for
};
PlacedPoint beyond(const AxisVector& from, const AxisVector& toward, double distance_mm) {
    const double length = notch_detail::measured_length(from, toward);
    auto on_grid = [](double mm) { return std::abs(mm * 1e4 - std::round(mm * 1e4)) < 1e-6 && std::abs(mm) < 1e5; };
    bool grid = length > 0;
    for (std::size_t i = 0; i < axis_count && grid; ++i) grid = on_grid(from[i]) && on_grid(toward[i]);
    const double fraction = distance_mm / length;
    if (!grid || !(fraction < 1e6)) {
        const AxisVector away = scaled(from - toward, 1.0 / length);
        const double placed = round_up_to_grid(distance_mm);
        return {from + scaled(away, placed), placed};
    }
    // An axis-parallel cut (most are): the 4-decimal distance already lands on the grid and on
    // the line; keep those shorter numbers.
    {
        const AxisVector away = scaled(from - toward, 1.0 / length);
        const double placed = round_up_to_grid(distance_mm);
        const AxisVector p = from + scaled(away, placed);
        std::array<std::int64_t, axis_count> pg{};
        std::array<std::int64_t, axis_count> fg{};
        std::array<std::int64_t, axis_count> dg{};
        bool exact = true;
        for (std::size_t i = 0; i < axis_count && exact; ++i) {
            exact = on_grid(p[i]);
            pg[i] = std::llround(p[i] * 1e4);
            fg[i] = std::llround(from[i] * 1e4);
            dg[i] = fg[i] - std::llround(toward[i] * 1e4);
        }
        for (std::size_t i = 0; i < axis_count && exact; ++i) {
            for (std::size_t j = i + 1; j < axis_count && exact; ++j) {
                exact = (pg[i] - fg[i]) * dg[j] == (pg[j] - fg[j]) * dg[i];
            }
        }
        if (exact) return {p, placed};
    }
    const auto m = static_cast<std::int64_t>(std::ceil(fraction * 1e6 - 1e-9));
    PlacedPoint out;
    for (std::size_t i = 0; i < axis_count; ++i) {
        const auto f = static_cast<std::int64_t>(std::llround(from[i] * 1e4));
        const auto t = static_cast<std::int64_t>(std::llround(toward[i] * 1e4));
        out.point[i] = static_cast<double>(f * 1'000'000 + m * (f - t)) / 1e10;
    }
    out.distance_mm = static_cast<double>(m) / 1e6 * length;
    return out;
}

std::string block_name(const Move& move) {
    if (move.sequence_number >= 0) return fmt::format("N{} (line {})", move.sequence_number, move.where.line);
    return fmt::format("line {}", move.where.line);
}

std::string axis_value(double mm) {
    return fmt::format("{:.4f}", mm);
}

//! Unit direction of a straight move over all axes scaled to its measured length: the rate
//! dq/ds the planner uses, so that `start + rate * d` lies d mm (of path) along it.
AxisVector rate_of(const AxisVector& from, const AxisVector& to) {
    return scaled(to - from, 1.0 / notch_detail::measured_length(from, to));
}

struct Cut {
    std::size_t laser_on = 0;                   // index of the laser-on M-code
    std::size_t line = 0;                       // index of the cutting move
    std::optional<std::size_t> approach;        // last motion before the laser-on M-code
    std::optional<std::size_t> next;            // first motion after the cut
    std::optional<std::size_t> programmed_off;  // a laser-off M-code right after the cut
};

class Rewriter {
public:
    Rewriter(const std::vector<Move>& moves, const MachineConfig& machine, const NotchOptions& options)
        : moves_(moves), machine_(machine), options_(options) {
        for (const Move& move : moves_) polylines_.push_back(notch_detail::path_polyline(move, options.clearance_mm));
    }

    std::vector<Cut> find_cuts() const {
        std::vector<Cut> cuts;
        for (std::size_t i = 0; i + 1 < moves_.size(); ++i) {
            const Io* io = mcode_of(moves_[i]);
            if (io == nullptr || !machine_.is_laser_on_mcode(io->number)) continue;
            const auto* line = std::get_if<Line>(&moves_[i + 1].what);
            if (line == nullptr || line->rapid || line->feed.mode != FeedMode::per_minute ||
                !(line->feed.mm_per_min > 0) || !(notch_detail::measured_length(line->from, line->to) > 0)) {
                continue;
            }
            Cut cut;
            cut.laser_on = i;
            cut.line = i + 1;
            for (std::size_t k = i; k-- > 0;) {
                if (is_motion(moves_[k])) {
                    cut.approach = k;
                    break;
                }
            }
            if (i + 2 < moves_.size()) {
                const Io* off = mcode_of(moves_[i + 2]);
                if (off != nullptr && machine_.is_laser_off_mcode(off->number)) cut.programmed_off = i + 2;
            }
            for (std::size_t k = i + 2; k < moves_.size(); ++k) {
                if (is_motion(moves_[k])) {
                    cut.next = k;
                    break;
                }
            }
            cuts.push_back(cut);
        }
        return cuts;
    }

    Result<NotchRewrite> run() {
        std::optional<int> sync_off;
        for (int code : machine_.laser_off_mcodes) {
            if (!machine_.is_exact_stop_mcode(code)) {
                sync_off = code;
                break;
            }
        }
        const std::vector<Cut> cuts = find_cuts();
        NotchRewrite out;
        Diagnostics errors;
        std::size_t copied = 0;                      // moves_[0, copied) are in out.moves
        std::optional<std::size_t> last_motion_out;  // index in out.moves of the last motion copied
        auto copy_until = [&](std::size_t end) {
            for (; copied < end; ++copied) {
                if (is_motion(moves_[copied])) last_motion_out = out.moves.size();
                out.moves.push_back(moves_[copied]);
            }
        };
        for (const Cut& cut : cuts) {
            const Move& cut_move = moves_[cut.line];
            const Line& line = std::get<Line>(cut_move.what);
            if (!sync_off) {
                errors.push_back(error_at(cut_move.where, "notch-no-sync-off",
                                          "the machine has no laser-off M-code that switches without a stop: "
                                          "list one in 'laser_off_mcodes' and not in 'exact_stop_mcodes'"));
                continue;
            }
            NotchCut info = describe(cut, line);
            const AxisVector rate = rate_of(line.from, line.to);
            const PlacedPoint run_up_at = beyond(line.from, line.to, info.run_up_mm);
            const PlacedPoint overrun_at = beyond(line.to, line.from, info.overrun_mm);
            info.run_up_placed_mm = run_up_at.distance_mm;
            const AxisVector run_up_point = run_up_at.point;
            const double overrun_placed = overrun_at.distance_mm;
            const AxisVector overrun_point = overrun_at.point;
            const bool shortened = approach_holds_run_up(cut, rate, info.run_up_placed_mm);
            info.approach_shortened = shortened;
            bool ok = check_travel(cut_move, run_up_point, "run-up", info.run_up_placed_mm, errors) &&
                      check_travel(cut_move, overrun_point, "overrun", overrun_placed, errors);
            ok = ok && check_clear(cut, run_up_point, line.from, cut.approach, shortened, "run-up", errors);
            ok = ok && check_clear(cut, line.to, overrun_point, cut.next, false, "overrun", errors);
            out.cuts.push_back(info);
            if (!ok || !errors.empty()) continue;

            // Up to the laser-on M-code: the approach ends at the run-up point when it runs along
            // the cut line; otherwise the head goes back from the notch start to the run-up point.
            copy_until(cut.laser_on);
            if (shortened) {
                std::get<Line>(out.moves[*last_motion_out].what).to = run_up_point;
            } else {
                Line back;
                back.from = line.from;
                back.to = run_up_point;
                back.rapid = true;
                out.moves.push_back(Move{back, cut_move.where, cut_move.sequence_number});
            }
            out.moves.push_back(moves_[cut.laser_on]);
            Line run_up = line;
            run_up.from = run_up_point;
            run_up.to = line.from;
            run_up.path = PathControl{};
            out.moves.push_back(Move{run_up, cut_move.where, cut_move.sequence_number});
            Line stroke = line;
            stroke.path = PathControl{};  // passes the programmed end at speed
            out.moves.push_back(Move{stroke, cut_move.where, cut_move.sequence_number});
            Io off{IoKind::mcode, *sync_off, 0};
            out.moves.push_back(Move{off, cut_move.where, cut_move.sequence_number});
            Line overrun = line;
            overrun.from = line.to;
            overrun.to = overrun_point;
            overrun.path = PathControl{true, 0};  // comes to rest at the overrun's end
            out.moves.push_back(Move{overrun, cut_move.where, cut_move.sequence_number});
            copied = cut.line + 1;
            if (cut.programmed_off) copy_until(*cut.programmed_off + 1);  // at rest, beam already off
            Line back;
            back.from = overrun_point;
            back.to = line.to;
            back.rapid = true;
            out.moves.push_back(Move{back, cut_move.where, cut_move.sequence_number});
            last_motion_out = out.moves.size() - 1;
        }
        if (!errors.empty()) return errors;
        copy_until(moves_.size());
        return out;
    }

private:
    NotchCut describe(const Cut& cut, const Line& line) const {
        NotchCut info;
        const Move& move = moves_[cut.line];
        info.where = move.where;
        info.sequence_number = move.sequence_number;
        info.laser_on_mcode = std::get<Io>(moves_[cut.laser_on].what).number;
        info.start = line.from;
        info.end = line.to;
        info.length_mm = notch_detail::measured_length(line.from, line.to);
        info.feed_mm_min = line.feed.mm_per_min;
        const ProfileKind kind = machine_.profile;
        const ProfileLimits limits =
            segment_limits(make_line(line.from, line.to), machine_, line.feed.mm_per_min / 60.0, kind);
        info.cut_speed_mm_min = limits.max_velocity * 60.0;
        info.run_up_mm = speed_change_distance(0.0, limits.max_velocity, limits, kind);
        info.run_up_placed_mm = round_up_to_grid(info.run_up_mm);
        info.overrun_mm = speed_change_distance(limits.max_velocity, 0.0, limits, kind);
        int moving = 0;
        for (const AxisConfig& axis : machine_.axes) {
            if (line.to[axis.axis] != line.from[axis.axis]) {
                ++moving;
                info.profile_axis = axis.axis;
            }
        }
        if (moving != 1) info.profile_axis.reset();
        return info;
    }

    //! The approach is a straight feed or rapid move along the cut direction, ending at the notch
    //! start and at least as long as the run-up: the run-up then lies on it.
    bool approach_holds_run_up(const Cut& cut, const AxisVector& rate, double run_up_mm) const {
        if (!cut.approach) return false;
        const auto* approach = std::get_if<Line>(&moves_[*cut.approach].what);
        if (approach == nullptr) return false;
        const AxisVector start = std::get<Line>(moves_[cut.line].what).from;
        if (!(approach->to == start)) return false;
        const double length = notch_detail::measured_length(approach->from, approach->to);
        if (length < run_up_mm) return false;
        const AxisVector along = rate_of(approach->from, approach->to) - rate;
        return std::sqrt(dot(along, along)) < 1e-9;
    }

    bool check_travel(const Move& cut_move, const AxisVector& point, const char* what, double distance_mm,
                      Diagnostics& errors) const {
        for (const AxisConfig& axis : machine_.axes) {
            const double q = point[axis.axis];
            if (q < axis.min - 1e-9 || q > axis.max + 1e-9) {
                errors.push_back(error_at(
                    cut_move.where, "notch-travel",
                    fmt::format("the {} of {} mm for this notch takes {} to {}, outside its travel "
                                "({}..{})",
                                what, axis_value(distance_mm), letter(axis.axis), axis_value(q), axis.min, axis.max)));
                return false;
            }
        }
        return true;
    }

    //! The segment [p0, p1] (run-up or overrun) keeps clear of every other move's path. The
    //! adjacent move (the approach, or the move after the cut) shares a point with it: a
    //! straight one crosses only when it runs along the same line over part of the segment.
    bool check_clear(const Cut& cut, const AxisVector& p0, const AxisVector& p1, std::optional<std::size_t> adjacent,
                     bool adjacent_holds_it, const char* what, Diagnostics& errors) const {
        const AxisVector dir = rate_of(p0, p1);
        auto refuse = [&](std::size_t k) {
            errors.push_back(
                error_at(moves_[cut.line].where, "notch-crossing",
                         fmt::format("the {} of {} mm for this notch crosses the path of {}", what,
                                     axis_value(notch_detail::measured_length(p0, p1)), block_name(moves_[k]))));
            return false;
        };
        for (std::size_t k = 0; k < moves_.size(); ++k) {
            if (k == cut.line || polylines_[k].empty()) continue;
            if (adjacent && k == *adjacent) {
                if (adjacent_holds_it) continue;
                const auto* adjacent_line = std::get_if<Line>(&moves_[k].what);
                if (adjacent_line == nullptr) continue;  // an arc meeting the segment at its end: not checked
                const double length = notch_detail::measured_length(adjacent_line->from, adjacent_line->to);
                if (!(length > 0)) continue;
                const AxisVector w = rate_of(adjacent_line->from, adjacent_line->to);
                const double cosine = dot(w, dir) / std::sqrt(dot(w, w) * dot(dir, dir));
                if (std::abs(cosine) < 1.0 - 1e-12) continue;  // two lines meet once: at the shared point
                // Collinear: overlapping the segment by more than the clearance is a crossing.
                const double s0 = dot(adjacent_line->from - p0, dir);
                const double s1 = dot(adjacent_line->to - p0, dir);
                const double seg = notch_detail::measured_length(p0, p1);
                const double overlap = std::min(std::max(s0, s1), seg) - std::max(std::min(s0, s1), 0.0);
                if (overlap > options_.clearance_mm) return refuse(k);
                continue;
            }
            const std::vector<AxisVector>& poly = polylines_[k];
            for (std::size_t c = 0; c + 1 < poly.size(); ++c) {
                if (notch_detail::segment_distance(p0, p1, poly[c], poly[c + 1]) < options_.clearance_mm)
                    return refuse(k);
            }
        }
        return true;
    }

    const std::vector<Move>& moves_;
    const MachineConfig& machine_;
    const NotchOptions& options_;
    std::vector<std::vector<AxisVector>> polylines_;
};

}  // namespace

Result<NotchRewrite> rewrite_notches(const std::vector<Move>& moves, const MachineConfig& machine,
                                     const NotchOptions& options) {
    Rewriter rewriter(moves, machine, options);
    return rewriter.run();
}

}  // namespace nckit
