// G76, the multiple threading cycle, in the 0i's two-block form and the one-block form of
// older controls, expanded into spindle-locked passes (SyncMove, as G32) of constant area:
//   G76 P(mm rr aa) Q(smallest step) R(finishing allowance)
//   G76 X(U) Z(W) R(taper) P(thread height) Q(first depth) F(lead)
//   G76 X(U) Z(W) I(taper) K(thread height) D(first depth) F(lead) A(angle) Q(start angle)
//                                                                               (one block)
// P, Q and the one-block D are in least increments when written without a decimal point
// (P1500 = 1.5 mm). Pass n cuts to depth d·√n below the crest, so every pass removes the same
// area of the V; a step smaller than Q is raised to Q; the last rough pass stops at the height
// less the allowance; then mm finishing passes cut at the full height. Each pass: rapid in X
// to its depth (the start moved depth·tan(aa/2) along Z towards the thread's end, so one flank
// cuts), the cut locked to the spindle, a 45-degree pull-out of rr/10 leads when rr is given,
// rapid out in X, rapid back to the start. The one-block form's Q shifts every pass's start by
// an angle past the index (a multi-start thread); the two-block form's Q is the first depth, so
// it has no start angle, as on the 0i.
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "executor.hpp"
#include "lathe_codes.hpp"

namespace nckit::interp {

namespace {
constexpr int max_thread_passes = 1000;
constexpr double deg_to_rad = std::numbers::pi / 180.0;
}  // namespace

std::optional<Diagnostic> Executor::sync_to(const AxisVector& target, double lead_mm, double start_angle_deg,
                                            std::vector<Move>& out) {
    if (auto e = check_line_travel(target)) return e;
    Feed feed;
    feed.mode = FeedMode::per_revolution;
    feed.mm_per_rev = lead_mm;
    feed.mm_per_min = lead_mm * spindle_rpm_at(work_x());
    push(out, SyncMove{position_, target, feed, start_angle_deg});
    position_ = target;
    return std::nullopt;
}

std::optional<Diagnostic> Executor::thread_cycle(std::vector<Move>& out) {
    const std::string name = lathe_code_name(machine_.gcode_system, lathe_thread_repeat);
    const std::uint32_t column = words_.group_column(ModalGroup::non_modal);
    LatheCycleSettings& settings = modal_.lathe.settings;
    const bool inch = modal_.length_factor_mm != 1.0;
    // A P Q D word without a decimal point counts least increments (0.001 mm, 0.0001 in).
    auto increments = [&](const Word& w) {
        return w.has_decimal_point ? offset_value(w) : w.value * (inch ? 0.0001 * 25.4 : 0.001);
    };
    const bool moves = words_.has('X') || words_.has('Z');
    if (!moves) {
        if (const Word* p = words_.word('P')) {
            const double v = p->value;
            if (v < 0 || v > 999999 || v != std::floor(v)) {
                return error(p->column, "bad-value", fmt::format("{} P is six digits: passes, chamfer, angle", name));
            }
            const auto digits = static_cast<long>(v);
            settings.finish_passes = static_cast<int>(digits / 10000);
            settings.chamfer_leads = static_cast<double>((digits / 100) % 100) / 10.0;
            settings.thread_angle_deg = static_cast<double>(digits % 100);
            if (settings.finish_passes < 1) settings.finish_passes = 1;
        }
        if (const Word* q = words_.word('Q')) settings.min_cut_mm = increments(*q);
        if (const Word* r = words_.word('R')) settings.thread_allowance_mm = offset_value(*r);
        return std::nullopt;
    }
    const bool one_block = words_.has('K') || words_.has('D');
    const Word* height_word = one_block ? words_.word('K') : words_.word('P');
    const Word* first_word = one_block ? words_.word('D') : words_.word('Q');
    const Word* lead_word = words_.word('F');
    if (height_word == nullptr || first_word == nullptr || lead_word == nullptr || !words_.has('X') ||
        !words_.has('Z')) {
        return error(column, "missing-word",
                     one_block ? fmt::format("{} needs X Z K (height) D (first depth) F (lead)", name)
                               : fmt::format("{} needs X Z P (height) Q (first depth) F (lead)", name));
    }
    const double height = one_block ? offset_value(*height_word) : increments(*height_word);
    const double first = one_block ? offset_value(*first_word) : increments(*first_word);
    const double lead = offset_value(*lead_word);
    const double allowance = one_block ? 0.0 : settings.thread_allowance_mm;
    const double min_cut = one_block ? 0.0 : settings.min_cut_mm;
    double angle = one_block ? 60.0 : settings.thread_angle_deg;
    if (const Word* a = words_.word('A'); a != nullptr && one_block) angle = a->value;
    double start_angle_deg = 0;
    if (const Word* q = words_.word('Q'); q != nullptr && one_block) {
        if (auto e = thread_start_angle(*q, start_angle_deg)) return e;
    }
    if (const Word* p = words_.word('P'); p != nullptr && one_block && p->value != 1) {
        return error(p->column, "unsupported-word",
                     fmt::format("{} P{}: only infeed P1 (one flank, constant area) is supported", name, p->value));
    }
    if (height <= 0 || first <= 0) {
        return error(height <= 0 ? height_word->column : first_word->column, "bad-value",
                     fmt::format("{}: the thread height and the first depth must be positive", name));
    }
    if (allowance < 0 || allowance >= height) {
        return error(column, "bad-value",
                     fmt::format("{}: the finishing allowance must lie between 0 and the height", name));
    }
    if (std::pow((height - allowance) / first, 2.0) > max_thread_passes) {
        return error(first_word->column, "bad-value",
                     fmt::format("{}: the first depth needs more than {} passes", name, max_thread_passes));
    }
    const Word* taper_word = one_block ? words_.word('I') : words_.word('R');
    const double taper = taper_word != nullptr ? offset_value(*taper_word) : 0.0;
    const AxisVector start = position_;
    const AxisVector root = target_from_words(false);
    const double outward = start[Axis::X] >= root[Axis::X] ? 1.0 : -1.0;  // outside thread: the crest is above
    const double along = root[Axis::Z] < start[Axis::Z] ? -1.0 : 1.0;
    const double flank = std::tan(angle / 2.0 * deg_to_rad);
    const double chamfer = settings.chamfer_leads * lead;
    std::vector<double> depths;
    for (int n = 1; depths.empty() || depths.back() < height - allowance - 1e-12; ++n) {
        double d = std::min(first * std::sqrt(static_cast<double>(n)), height - allowance);
        if (!depths.empty() && d - depths.back() < min_cut) d = std::min(depths.back() + min_cut, height - allowance);
        depths.push_back(d);
    }
    const int finish_passes = one_block ? 0 : settings.finish_passes;
    for (int k = 0; k < finish_passes; ++k) depths.push_back(height);
    auto at = [&](double x, double z) {
        AxisVector p = start;
        p[Axis::X] = x;
        p[Axis::Z] = z;
        return p;
    };
    for (double depth : depths) {
        const double x = root[Axis::X] + outward * (height - depth);
        const double z = start[Axis::Z] + along * depth * flank;
        if (auto e = straight(g(0), at(start[Axis::X], z), out)) return e;
        if (auto e = straight(g(0), at(x + taper, z), out)) return e;
        if (chamfer > 0) {
            if (auto e = sync_to(at(x, root[Axis::Z] - along * chamfer), lead, start_angle_deg, out)) return e;
            if (auto e = sync_to(at(x + outward * chamfer, root[Axis::Z]), lead, start_angle_deg, out)) return e;
        } else if (auto e = sync_to(at(x, root[Axis::Z]), lead, start_angle_deg, out)) {
            return e;
        }
        if (auto e = straight(g(0), at(start[Axis::X], root[Axis::Z]), out)) return e;
        if (auto e = straight(g(0), start, out)) return e;
    }
    return std::nullopt;
}

}  // namespace nckit::interp
