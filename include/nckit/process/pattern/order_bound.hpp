#pragma once
// A lower bound on the air cost of any cutting order (Held–Karp's 1-tree bound).
//
// Make a graph of the hole and both ends of every cut. Any order is a closed round trip through
// every node that uses each cut's own edge (its two ends, free) and air edges between; drop the
// hole from the round trip and what is left is a spanning tree of the other nodes that holds
// every cut edge, and the hole keeps two air edges. So the cheapest such "1-tree" (cut edges
// forced in, then a minimum spanning tree, plus the hole's two cheapest edges) costs no more
// than any order. Adding a penalty π_v to every edge at node v changes every round trip by
// exactly 2·Σπ (each node has degree 2 in it) but 1-trees by different amounts; subgradient
// steps on π (raise π where the tree's degree exceeds 2) push the bound up towards the optimum.
// Reversal costs are left out (they are >= 0), so the bound holds for air time alone.
#include <functional>
#include <vector>

#include "nckit/process/pattern/cut_order.hpp"

namespace nckit::pattern {

struct OrderBound {
    double value = 0;  //!< the best bound found
    std::size_t iterations = 0;
};

//! `weight(a, b)`: the air cost between two points (distance, or rapid time); `upper` is the
//! cost of a known order (it sizes the subgradient steps). Up to `max_iterations` steps; the
//! full weight matrix is kept (floats) when there are at most 4000 nodes, otherwise weights are
//! recomputed and only the plain 1-tree (no steps) is taken.
[[nodiscard]] OrderBound air_cost_lower_bound(const std::vector<CutEnds>& cuts, Vec2 home,
                                              const std::function<double(Vec2, Vec2)>& weight, double upper,
                                              std::size_t max_iterations = 300);

}  // namespace nckit::pattern
