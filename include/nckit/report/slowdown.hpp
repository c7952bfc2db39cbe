#pragma once
// Why a move did not reach its programmed feed: the causes a process engineer can act on.
#include <cstdint>
#include <string_view>

namespace nckit {

enum class Slowdown : std::uint8_t {
    none,           //!< the feed was reached (or the move is a rapid or a thread)
    corner,         //!< the speed had to come down for a corner: a stop or a blend arc
    arc_limit,      //!< the arc's curvature: the axes' acceleration caps the speed below the feed
    short_segment,  //!< too short to get up to feed between its neighbours' speeds
    exact_stop,     //!< G61/G9, a dwell, a waiting M-code, or the program's start or end
    axis_limit      //!< a straight move whose axes cannot go that fast
};

[[nodiscard]] std::string_view slowdown_name(Slowdown slowdown);

//! How the path passes one end of a move.
enum class Junction : std::uint8_t {
    tangent,    //!< on at speed into a tangent neighbour
    corner,     //!< a corner: a blend arc or a stop
    exact_stop  //!< a stop the program asks for
};

//! The facts one move's classification needs.
struct SlowdownFacts {
    double feed_mm_s = 0;   //!< programmed
    double limit_mm_s = 0;  //!< the segment's own speed limit (segment_limits)
    double peak_mm_s = 0;   //!< planned top speed on the move
    double start_mm_s = 0;  //!< planned speed at its start
    double end_mm_s = 0;    //!< planned speed at its end
    bool arc = false;
    Junction start = Junction::exact_stop;
    Junction end = Junction::exact_stop;
};

//! A move reaches its feed when its planned peak is within reached_fraction of it.
inline constexpr double reached_fraction = 0.99;

//! The segment's own limit first (arc_limit / axis_limit); otherwise the slower of its two ends
//! holds the speed down: that junction's kind, a tangent one meaning the run of moves is too short.
[[nodiscard]] Slowdown classify_slowdown(const SlowdownFacts& facts);

}  // namespace nckit
