#pragma once
// Which of many short segments (run-ups, overruns, cut lines) may come near a given one: the
// segments sorted along the axis on which they spread most. A query visits those whose extent
// on that axis overlaps the query's, so checking every move of a long program against every
// cut costs about one binary search per move, not one test per cut.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "nckit/core/axes.hpp"

namespace nckit::notch_detail {

class SweepIndex {
public:
    struct Segment {
        AxisVector from;
        AxisVector to;
    };
    SweepIndex() = default;
    //! `segments[i]` is reported as i.
    explicit SweepIndex(const std::vector<Segment>& segments);

    //! Calls `visit(i)` for every segment whose extent on the sweep axis comes within pad_mm of
    //! [from, to]'s (a superset of the segments within pad_mm of it over all axes).
    void query(const AxisVector& from, const AxisVector& to, double pad_mm,
               const std::function<void(std::size_t)>& visit) const;

private:
    struct Entry {
        double lo;
        double hi;
        std::uint32_t id;
    };
    std::size_t axis_ = 0;
    double max_extent_ = 0;
    std::vector<Entry> entries_;  // by lo
};

}  // namespace nckit::notch_detail
