#include "nckit/plan/sync_report.hpp"

#include <algorithm>
#include <cmath>

namespace nckit {

void SyncReport::add(const TrajectoryPiece& piece) {
    if (piece.kind == PieceKind::io) {
        if (command_.apply(piece.io)) spindle_.set_speed(piece.start_time_s, command_.signed_rpm(spindle_.config()));
        return;
    }
    if (piece.kind == PieceKind::dwell) {
        after_wait_ = piece.waits_for_index;
        wait_s_ = piece.duration_s;
        wait_angle_deg_ = piece.index_angle_deg;
        return;
    }
    if (!after_wait_) return;
    after_wait_ = false;
    SyncStart start;
    start.where = piece.where;
    start.t_s = piece.start_time_s;
    start.wait_s = wait_s_;
    start.spindle_angle_deg = spindle_.angle_deg(piece.start_time_s);
    start.encoder_count = spindle_.count_at(piece.start_time_s);
    start.start_angle_deg = wait_angle_deg_;
    // The start angle is past the index in the turning sense: under M4 the angle runs negative.
    const double sense = command_.direction < 0 ? -1.0 : 1.0;
    const double off_deg = std::remainder(sense * start.spindle_angle_deg - wait_angle_deg_, 360.0);
    max_error_deg_ = std::max(max_error_deg_, std::abs(off_deg));
    ++count_;
    if (starts_.size() < max_kept) starts_.push_back(start);
}

}  // namespace nckit
