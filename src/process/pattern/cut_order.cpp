// Nearest neighbour, 2-opt and Or-opt over reversible cuts.
#include "nckit/process/pattern/cut_order.hpp"

#include <algorithm>
#include <numeric>

namespace nckit::pattern {

namespace {

// One cut as it is cut (drawn or turned round), or the hole (index npos).
struct Node {
    Vec2 start, end;
    Signs first, last;
};

constexpr std::size_t hole = static_cast<std::size_t>(-1);

class Costing {
public:
    Costing(const std::vector<CutEnds>& cuts, const OrderCosts& costs) : cuts_(cuts), costs_(costs) {}

    [[nodiscard]] Node node(std::size_t cut, bool flipped) const {
        if (cut == hole) return Node{costs_.home, costs_.home, {0, 0}, {0, 0}};
        const CutEnds& c = cuts_[cut];
        if (!flipped) return Node{c.start, c.end, c.first, c.last};
        return Node{c.end, c.start, {-c.last[0], -c.last[1]}, {-c.first[0], -c.first[1]}};
    }
    //! Air time from a's end to b's start plus the reversals where the motions meet.
    [[nodiscard]] double edge(const Node& a, const Node& b) const {
        const Vec2 d = b.start - a.end;
        const Signs s = signs_of(d);
        double cost = costs_.timer.rapid_s(d);
        for (std::size_t i = 0; i < 2; ++i) {
            int n = 0;
            if (s[i] != 0) {
                n = (a.last[i] != 0 && a.last[i] != s[i]) + (b.first[i] != 0 && b.first[i] != s[i]);
            } else {
                n = a.last[i] != 0 && b.first[i] != 0 && a.last[i] != b.first[i];
            }
            cost += n * costs_.reversal_s[i];
        }
        return cost;
    }

private:
    const std::vector<CutEnds>& cuts_;
    const OrderCosts& costs_;
};

double tour_cost(const Costing& k, const Tour& t) {
    double total = 0;
    Node prev = k.node(hole, false);
    for (std::size_t p = 0; p < t.order.size(); ++p) {
        const Node n = k.node(t.order[p], t.flipped[p] != 0);
        total += k.edge(prev, n);
        prev = n;
    }
    return total + k.edge(prev, k.node(hole, false));
}

}  // namespace

CutEnds describe_cut(const PlaneCurve& curve, double deviation_mm) {
    const std::vector<Vec2> points = polyline(curve, deviation_mm);
    CutEnds out{points.front(), points.back(), {0, 0}, {0, 0}, {0, 0}};
    ReversalCounter counter;
    for (std::size_t i = 1; i < points.size(); ++i) {
        const Signs s = signs_of(points[i] - points[i - 1], 1e-7);
        for (std::size_t a = 0; a < 2; ++a) {
            if (s[a] != 0 && out.first[a] == 0) out.first[a] = s[a];
        }
        counter.move(points[i] - points[i - 1]);
    }
    out.last = counter.last;
    out.internal_reversals = counter.per_axis;
    return out;
}

Tour drawing_tour(std::size_t cuts) {
    Tour t;
    t.order.resize(cuts);
    std::iota(t.order.begin(), t.order.end(), std::size_t{0});
    t.flipped.assign(cuts, 0);
    return t;
}

TourCost evaluate_tour(const std::vector<CutEnds>& cuts, const Tour& tour, const OrderCosts& costs) {
    const Costing k(cuts, costs);
    TourCost out;
    ReversalCounter counter;
    auto run = [&](const CutEnds& c, bool flipped) {
        // The cut's own motion, as the counter would see it: first direction, the reversals
        // inside, last direction.
        const Signs first = flipped ? Signs{-c.last[0], -c.last[1]} : c.first;
        const Signs last = flipped ? Signs{-c.first[0], -c.first[1]} : c.last;
        for (std::size_t i = 0; i < 2; ++i) {
            if (first[i] == 0) continue;
            if (counter.last[i] != 0 && counter.last[i] != first[i]) {
                ++counter.count;
                ++counter.per_axis[i];
            }
            counter.last[i] = last[i];
            counter.count += c.internal_reversals[i];
            counter.per_axis[i] += c.internal_reversals[i];
        }
    };
    Vec2 at = costs.home;
    for (std::size_t p = 0; p < tour.order.size(); ++p) {
        const Node n = k.node(tour.order[p], tour.flipped[p] != 0);
        const Vec2 d = n.start - at;
        out.air_distance_mm += length(d);
        out.air_time_s += costs.timer.rapid_s(d);
        counter.move(d);
        run(cuts[tour.order[p]], tour.flipped[p] != 0);
        at = n.end;
    }
    const Vec2 back = costs.home - at;
    out.air_distance_mm += length(back);
    out.air_time_s += costs.timer.rapid_s(back);
    counter.move(back);
    out.reversals = counter.count;
    out.reversal_time_s = counter.per_axis[0] * costs.reversal_s[0] + counter.per_axis[1] * costs.reversal_s[1];
    return out;
}

OrderResult optimise_tour(const std::vector<CutEnds>& cuts, const OrderCosts& costs, std::size_t max_evaluations) {
    const Costing k(cuts, costs);
    const std::size_t n = cuts.size();
    OrderResult result;
    if (n == 0) return result;
    // Nearest neighbour from the hole, either way round.
    std::vector<char> used(n, 0);
    Node at = k.node(hole, false);
    for (std::size_t step = 0; step < n; ++step) {
        double best = 1e300;
        std::size_t best_cut = 0;
        bool best_flip = false;
        for (std::size_t c = 0; c < n; ++c) {
            if (used[c]) continue;
            for (bool f : {false, true}) {
                const double e = k.edge(at, k.node(c, f));
                if (e < best) {
                    best = e;
                    best_cut = c;
                    best_flip = f;
                }
            }
        }
        result.evaluations += 2 * (n - step);
        used[best_cut] = 1;
        result.tour.order.push_back(best_cut);
        result.tour.flipped.push_back(best_flip ? 1 : 0);
        at = k.node(best_cut, best_flip);
    }
    Tour& t = result.tour;
    auto node_at = [&](std::ptrdiff_t p) {
        if (p < 0 || p >= static_cast<std::ptrdiff_t>(n)) return k.node(hole, false);
        const auto q = static_cast<std::size_t>(p);
        return k.node(t.order[q], t.flipped[q] != 0);
    };
    auto flipped_at = [&](std::ptrdiff_t p) {
        const auto q = static_cast<std::size_t>(p);
        return k.node(t.order[q], t.flipped[q] == 0);
    };
    constexpr double gain_eps = 1e-12;
    const auto len = static_cast<std::ptrdiff_t>(n);
    bool improved = true;
    while (improved && result.evaluations < max_evaluations) {
        improved = false;
        ++result.passes;
        // 2-opt: reverse positions i..j (each cut turned round).
        for (std::ptrdiff_t i = 0; i < len && result.evaluations < max_evaluations; ++i) {
            const Node before = node_at(i - 1);
            for (std::ptrdiff_t j = i; j < len; ++j) {
                const Node after = node_at(j + 1);
                const double old_cost = k.edge(before, node_at(i)) + k.edge(node_at(j), after);
                const double new_cost = k.edge(before, flipped_at(j)) + k.edge(flipped_at(i), after);
                ++result.evaluations;
                if (new_cost < old_cost - gain_eps) {
                    std::reverse(t.order.begin() + i, t.order.begin() + j + 1);
                    std::reverse(t.flipped.begin() + i, t.flipped.begin() + j + 1);
                    for (std::ptrdiff_t q = i; q <= j; ++q) {
                        char& f = t.flipped[static_cast<std::size_t>(q)];
                        f = static_cast<char>(f == 0 ? 1 : 0);
                    }
                    improved = true;
                }
            }
        }
        // Or-opt: move the run i..i+r-1 to between positions p and p+1, either way round.
        for (std::ptrdiff_t r = 1; r <= 3; ++r) {
            for (std::ptrdiff_t i = 0; i + r <= len && result.evaluations < max_evaluations; ++i) {
                const std::ptrdiff_t j = i + r - 1;
                const double removed = k.edge(node_at(i - 1), node_at(i)) + k.edge(node_at(j), node_at(j + 1)) -
                                       k.edge(node_at(i - 1), node_at(j + 1));
                double best_gain = gain_eps;
                std::ptrdiff_t best_p = -2;
                bool best_rev = false;
                for (std::ptrdiff_t p = -1; p < len; ++p) {
                    if (p >= i - 1 && p <= j) continue;
                    const Node a = node_at(p), b = node_at(p + 1);
                    const double gap = k.edge(a, b);
                    const double keep = k.edge(a, node_at(i)) + k.edge(node_at(j), b) - gap;
                    const double turn = k.edge(a, flipped_at(j)) + k.edge(flipped_at(i), b) - gap;
                    result.evaluations += 2;
                    if (removed - keep > best_gain) {
                        best_gain = removed - keep;
                        best_p = p;
                        best_rev = false;
                    }
                    if (removed - turn > best_gain) {
                        best_gain = removed - turn;
                        best_p = p;
                        best_rev = true;
                    }
                }
                if (best_p == -2) continue;
                std::vector<std::size_t> run_order(t.order.begin() + i, t.order.begin() + j + 1);
                std::vector<char> run_flip(t.flipped.begin() + i, t.flipped.begin() + j + 1);
                if (best_rev) {
                    std::reverse(run_order.begin(), run_order.end());
                    // Reversed and flipped in one pass (an in-place flip after std::reverse
                    // trips GCC 12's -Wstringop-overflow on an empty-looking vector).
                    std::vector<char> reversed_flip;
                    reversed_flip.reserve(run_flip.size());
                    for (auto f = run_flip.rbegin(); f != run_flip.rend(); ++f) {
                        reversed_flip.push_back(static_cast<char>(*f == 0 ? 1 : 0));
                    }
                    run_flip = std::move(reversed_flip);
                }
                t.order.erase(t.order.begin() + i, t.order.begin() + j + 1);
                t.flipped.erase(t.flipped.begin() + i, t.flipped.begin() + j + 1);
                const std::ptrdiff_t insert_at = best_p < i ? best_p + 1 : best_p + 1 - r;
                t.order.insert(t.order.begin() + insert_at, run_order.begin(), run_order.end());
                t.flipped.insert(t.flipped.begin() + insert_at, run_flip.begin(), run_flip.end());
                improved = true;
            }
        }
    }
    result.budget_spent = result.evaluations >= max_evaluations;
    const Tour drawn = drawing_tour(n);
    if (tour_cost(k, drawn) < tour_cost(k, t)) result.tour = drawn;
    return result;
}

}  // namespace nckit::pattern
