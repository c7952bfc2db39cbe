// The single cycles G90 (turning), G92 (threading) and G94 (facing) of lathe G-code system A
// (G77/G78/G79 in B, G20/G21/G24 in C), expanded into rapids, feeds and spindle-locked moves.
// From the start point S and the end point E (X Z words, U W incremental from S):
//   G90: rapid X to E.x + R, feed to E (a taper when R is not 0), feed X back to S.x, rapid to S;
//   G92: as G90 with the cut locked to the spindle (lead F, starting Q past the index) and the
//        X retreat at rapid;
//   G94: rapid Z to E.z + R, feed to E, feed Z back to S.z, rapid to S.
// The words stay for the following blocks: a block with X alone cuts the next pass.
#include "executor.hpp"
#include "lathe_codes.hpp"

namespace nckit::interp {

std::optional<Diagnostic> Executor::lathe_single_cycle(std::vector<Move>& out) {
    LatheSingleCycle& cycle = modal_.lathe.single;
    if (cycle.mode != motion_) cycle = LatheSingleCycle{motion_, position_, 0, 0, 0};
    const AxisVector start = position_;
    const AxisVector words = target_from_words(false);
    if (words_.has('X')) cycle.end[Axis::X] = words[Axis::X];
    if (words_.has('Z')) cycle.end[Axis::Z] = words[Axis::Z];
    if (const Word* r = words_.word('R')) cycle.taper_mm = offset_value(*r);
    if (motion_ == lathe_threading_cycle) {
        if (const Word* f = words_.word('F')) cycle.lead_mm = offset_value(*f);
        // Q stays with the cycle's other words: the passes of one start need it only once.
        if (const Word* q = words_.word('Q')) {
            if (auto e = thread_start_angle(*q, cycle.start_angle_deg)) return e;
        }
    }
    const AxisVector end = [&] {
        AxisVector e = start;
        e[Axis::X] = cycle.end[Axis::X];
        e[Axis::Z] = cycle.end[Axis::Z];
        return e;
    }();
    auto to = [&](double x, double z) {
        AxisVector p = start;
        p[Axis::X] = x;
        p[Axis::Z] = z;
        return p;
    };
    if (motion_ == lathe_facing_cycle) {
        if (auto e = straight(g(0), to(start[Axis::X], end[Axis::Z] + cycle.taper_mm), out)) return e;
        if (auto e = straight(g(1), end, out)) return e;
        if (auto e = straight(g(1), to(end[Axis::X], start[Axis::Z]), out)) return e;
        return straight(g(0), start, out);
    }
    if (auto e = straight(g(0), to(end[Axis::X] + cycle.taper_mm, start[Axis::Z]), out)) return e;
    if (motion_ == lathe_threading_cycle) {
        if (auto e = check_line_travel(end)) return e;
        Feed feed;
        feed.mode = FeedMode::per_revolution;
        feed.mm_per_rev = cycle.lead_mm;
        feed.mm_per_min = cycle.lead_mm * spindle_rpm_at(work_x());
        push(out, SyncMove{position_, end, feed, cycle.start_angle_deg});
        position_ = end;
        if (auto e = straight(g(0), to(start[Axis::X], end[Axis::Z]), out)) return e;
        return straight(g(0), start, out);
    }
    if (auto e = straight(g(1), end, out)) return e;
    if (auto e = straight(g(1), to(start[Axis::X], end[Axis::Z]), out)) return e;
    return straight(g(0), start, out);
}

}  // namespace nckit::interp
