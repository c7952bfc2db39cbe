#pragma once
// Builds move lists for planner tests, tracking the current position.
#include <cstdint>
#include <limits>
#include <vector>

#include "nckit/interp/move.hpp"

namespace nckit::plan_test {

class MoveBuilder {
public:
    AxisVector position;
    std::vector<Move> moves;
    std::vector<double> feeds_mm_s;  //!< per move (its index is the move's sequence number)

    void line(AxisVector to, double feed_mm_min, PathControl path = {}) {
        Line l{position, to, Feed{FeedMode::per_minute, feed_mm_min, 0}, false, path};
        add(l, feed_mm_min / 60);
        position = to;
    }
    void rapid(AxisVector to) {
        Line l{position, to, {}, true, {}};
        add(l, std::numeric_limits<double>::infinity());
        position = to;
    }
    void arc(AxisVector to, AxisVector center, ArcDirection dir, double feed_mm_min, PathControl path = {},
             Plane plane = Plane::xy) {
        Arc a;
        a.from = position;
        a.to = to;
        a.center = center;
        a.plane = plane;
        a.direction = dir;
        a.feed = Feed{FeedMode::per_minute, feed_mm_min, 0};
        a.path = path;
        add(a, feed_mm_min / 60);
        position = to;
    }
    void dwell(double s) { add(Dwell{s}, 0); }
    //! G32/G33 with `lead_mm` per spindle turn.
    void thread(AxisVector to, double lead_mm) {
        SyncMove sync{position, to, Feed{FeedMode::per_revolution, 0, lead_mm}};
        add(sync, 0);
        position = to;
    }
    //! M3/M4 (number 3 or 4) at `rpm`, or M5.
    void spindle(int number, double rpm = 0) {
        Io io;
        io.number = number;
        io.value = rpm;
        add(io, 0);
    }
    void mcode(int number, bool waits = false) {
        Io io;
        io.number = number;
        io.waits = waits;
        add(io, 0);
    }

private:
    template <class T>
    void add(T what, double feed) {
        Move m;
        m.what = what;
        m.sequence_number = static_cast<std::int64_t>(moves.size());
        m.where.line = static_cast<std::uint32_t>(moves.size() + 1);
        moves.push_back(m);
        feeds_mm_s.push_back(feed);
    }
};

inline AxisVector xyz(double x, double y, double z = 0, double a = 0) {
    AxisVector p;
    p[0] = x;
    p[1] = y;
    p[2] = z;
    p[3] = a;
    return p;
}

}  // namespace nckit::plan_test
