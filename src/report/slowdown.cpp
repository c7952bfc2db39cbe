#include "nckit/report/slowdown.hpp"

namespace nckit {

std::string_view slowdown_name(Slowdown slowdown) {
    switch (slowdown) {
        case Slowdown::none:
            return "none";
        case Slowdown::corner:
            return "corner";
        case Slowdown::arc_limit:
            return "arc limit";
        case Slowdown::short_segment:
            return "short segment";
        case Slowdown::exact_stop:
            return "exact stop";
        case Slowdown::axis_limit:
            return "axis limit";
    }
    return "none";
}

Slowdown classify_slowdown(const SlowdownFacts& facts) {
    if (!(facts.feed_mm_s > 0) || facts.peak_mm_s >= reached_fraction * facts.feed_mm_s) return Slowdown::none;
    if (facts.limit_mm_s < reached_fraction * facts.feed_mm_s) {
        return facts.arc ? Slowdown::arc_limit : Slowdown::axis_limit;
    }
    // The profile rises from one end and falls to the other: the slower end is the one whose
    // speed the move could not get away from in its length.
    const Junction held = facts.start_mm_s <= facts.end_mm_s ? facts.start : facts.end;
    switch (held) {
        case Junction::exact_stop:
            return Slowdown::exact_stop;
        case Junction::corner:
            return Slowdown::corner;
        case Junction::tangent:
            return Slowdown::short_segment;
    }
    return Slowdown::short_segment;
}

}  // namespace nckit
