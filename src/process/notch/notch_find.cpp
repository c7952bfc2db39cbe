// Pass 1 of the notch job: finding the cuts as the moves go by, and placing each cut's run-up
// before the notch start and overrun past its end.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>

#include <fmt/format.h>

#include "nckit/plan/profile.hpp"
#include "nckit/plan/segment_limits.hpp"
#include "notch_geometry.hpp"
#include "notch_passes.hpp"

namespace nckit::notch_detail {

namespace {

bool is_motion(const Move& move) {
    return motion_ends(move).has_value();
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
    const double length = measured_length(from, toward);
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

//! Unit direction of a straight move over all axes scaled to its measured length: the rate
//! dq/ds the planner uses, so that `start + rate * d` lies d mm (of path) along it.
AxisVector rate_of(const AxisVector& from, const AxisVector& to) {
    return scaled(to - from, 1.0 / measured_length(from, to));
}

NotchCut describe(const Move& move, const Line& line, int laser_on_mcode, const MachineConfig& machine) {
    NotchCut info;
    info.where = move.where;
    info.sequence_number = move.sequence_number;
    info.laser_on_mcode = laser_on_mcode;
    info.start = line.from;
    info.end = line.to;
    info.length_mm = measured_length(line.from, line.to);
    info.feed_mm_min = line.feed.mm_per_min;
    const ProfileKind kind = machine.profile;
    const ProfileLimits limits =
        segment_limits(make_line(line.from, line.to), machine, line.feed.mm_per_min / 60.0, kind);
    info.cut_speed_mm_min = limits.max_velocity * 60.0;
    info.run_up_mm = speed_change_distance(0.0, limits.max_velocity, limits, kind);
    info.run_up_placed_mm = round_up_to_grid(info.run_up_mm);
    info.overrun_mm = speed_change_distance(limits.max_velocity, 0.0, limits, kind);
    int moving = 0;
    for (const AxisConfig& axis : machine.axes) {
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
bool approach_holds_run_up(const Move* approach_move, const Line& cut, double run_up_mm) {
    if (approach_move == nullptr) return false;
    const auto* approach = std::get_if<Line>(&approach_move->what);
    if (approach == nullptr) return false;
    if (!(approach->to == cut.from)) return false;
    const double length = measured_length(approach->from, approach->to);
    if (length < run_up_mm) return false;
    const AxisVector along = rate_of(approach->from, approach->to) - rate_of(cut.from, cut.to);
    return std::sqrt(dot(along, along)) < 1e-9;
}

std::unique_ptr<Diagnostic> travel_error(const MachineConfig& machine, const Move& cut_move, const AxisVector& point,
                                         const char* what, double distance_mm) {
    for (const AxisConfig& axis : machine.axes) {
        const double q = point[axis.axis];
        if (q < axis.min - 1e-9 || q > axis.max + 1e-9) {
            return std::make_unique<Diagnostic>(
                error_at(cut_move.where, "notch-travel",
                         fmt::format("the {} of {:.4f} mm for this notch takes {} to {:.4f}, outside its travel "
                                     "({}..{})",
                                     what, distance_mm, letter(axis.axis), q, axis.min, axis.max)));
        }
    }
    return nullptr;
}

}  // namespace

std::optional<int> sync_off_mcode(const MachineConfig& machine) {
    for (int code : machine.laser_off_mcodes) {
        if (!machine.is_exact_stop_mcode(code)) return code;
    }
    return std::nullopt;
}

CutFinder::CutFinder(const MachineConfig& machine, const NotchOptions& /*options*/,
                     std::function<void(CutRecord&&)> out)
    : machine_(machine), sync_off_(sync_off_mcode(machine)), out_(std::move(out)) {}

void CutFinder::add(const Move& move) {
    const std::uint64_t k = index_++;
    const bool motion = is_motion(move);
    if (open_) {
        if (k == open_->line + 1) {
            const Io* off = mcode_of(move);
            if (off != nullptr && machine_.is_laser_off_mcode(off->number)) open_->programmed_off = k;
        }
        if (motion && k > open_->line) {
            // Its laser-off code (the move right after the cut) has been seen too: complete.
            open_->next = k;
            out_(std::move(*open_));
            open_.reset();
        }
    }
    if (laser_on_) start_cut(laser_on_->first, laser_on_->second, move);
    laser_on_.reset();
    if (const Io* io = mcode_of(move); io != nullptr && machine_.is_laser_on_mcode(io->number))
        laser_on_ = {{k, io->number}};
    if (motion) last_motion_ = {{k, move}};
}

void CutFinder::finish() {
    if (open_) out_(std::move(*open_));
    open_.reset();
}

void CutFinder::start_cut(std::uint64_t laser_on, int laser_on_mcode, const Move& move) {
    const auto* line = std::get_if<Line>(&move.what);
    if (line == nullptr || line->rapid || line->feed.mode != FeedMode::per_minute || !(line->feed.mm_per_min > 0) ||
        !(measured_length(line->from, line->to) > 0)) {
        return;
    }
    CutRecord cut;
    cut.laser_on = laser_on;
    cut.line = laser_on + 1;
    if (last_motion_) cut.approach = last_motion_->first;
    if (!sync_off_) {
        cut.local_error =
            std::make_unique<Diagnostic>(error_at(move.where, "notch-no-sync-off",
                                                  "the machine has no laser-off M-code that switches without a stop: "
                                                  "list one in 'laser_off_mcodes' and not in 'exact_stop_mcodes'"));
        open_ = std::move(cut);
        return;
    }
    cut.info = describe(move, *line, laser_on_mcode, machine_);
    const PlacedPoint run_up_at = beyond(line->from, line->to, cut.info.run_up_mm);
    const PlacedPoint overrun_at = beyond(line->to, line->from, cut.info.overrun_mm);
    cut.info.run_up_placed_mm = run_up_at.distance_mm;
    cut.run_up_point = run_up_at.point;
    cut.overrun_point = overrun_at.point;
    cut.overrun_placed_mm = overrun_at.distance_mm;
    cut.info.approach_shortened =
        approach_holds_run_up(last_motion_ ? &last_motion_->second : nullptr, *line, cut.info.run_up_placed_mm);
    cut.local_error = travel_error(machine_, move, cut.run_up_point, "run-up", cut.info.run_up_placed_mm);
    if (!cut.local_error) {
        cut.local_error = travel_error(machine_, move, cut.overrun_point, "overrun", cut.overrun_placed_mm);
    }
    open_ = std::move(cut);
}

}  // namespace nckit::notch_detail
