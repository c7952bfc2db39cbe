// Held–Karp 1-tree bound with forced cut edges.
#include "nckit/process/pattern/order_bound.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace nckit::pattern {

namespace {

constexpr std::size_t max_matrix_nodes = 4000;

}  // namespace

OrderBound air_cost_lower_bound(const std::vector<CutEnds>& cuts, Vec2 home,
                                const std::function<double(Vec2, Vec2)>& weight, double upper,
                                std::size_t max_iterations) {
    OrderBound out;
    const std::size_t n = 2 * cuts.size() + 1;  // 0: the hole; 2c+1, 2c+2: cut c's ends
    if (cuts.empty()) return out;
    std::vector<Vec2> at(n);
    at[0] = home;
    for (std::size_t c = 0; c < cuts.size(); ++c) {
        at[2 * c + 1] = cuts[c].start;
        at[2 * c + 2] = cuts[c].end;
    }
    auto partner = [](std::size_t v) { return v % 2 == 1 ? v + 1 : v - 1; };
    const bool matrix = n <= max_matrix_nodes;
    std::vector<float> w;
    if (matrix) {
        w.resize(n * n);
        for (std::size_t a = 0; a < n; ++a) {
            for (std::size_t b = a; b < n; ++b) {
                const auto v = static_cast<float>(a == b ? 0.0 : weight(at[a], at[b]));
                w[a * n + b] = v;
                w[b * n + a] = v;
            }
        }
    }
    auto cost = [&](std::size_t a, std::size_t b) {
        return matrix ? static_cast<double>(w[a * n + b]) : weight(at[a], at[b]);
    };
    std::vector<double> pi(n, 0.0);
    std::vector<int> degree(n);
    std::vector<double> key(n);
    std::vector<std::size_t> parent(n);
    std::vector<char> in_tree(n);
    double lambda = 2.0;
    std::size_t since_better = 0;
    const std::size_t iterations = matrix ? max_iterations : 1;
    for (std::size_t it = 0; it < iterations; ++it) {
        ++out.iterations;
        // Prim on nodes 1..n-1; a cut's partner joins right after its end (forced edge, cost 0).
        std::fill(degree.begin(), degree.end(), 0);
        std::fill(key.begin(), key.end(), std::numeric_limits<double>::infinity());
        std::fill(in_tree.begin(), in_tree.end(), 0);
        double tree = 0;
        std::size_t next = 1;
        key[1] = 0;
        parent[1] = 1;
        for (std::size_t added = 0; added + 1 < n; ++added) {
            const std::size_t v = next;
            in_tree[v] = 1;
            if (parent[v] != v) {
                tree += key[v];
                ++degree[v];
                ++degree[parent[v]];
            }
            // The partner is next, through the forced edge (its real cost 0 plus the penalties).
            const std::size_t p = partner(v);
            if (!in_tree[p]) {
                key[p] = -std::numeric_limits<double>::infinity();
                parent[p] = v;
            }
            double best = std::numeric_limits<double>::infinity();
            next = 0;
            for (std::size_t u = 1; u < n; ++u) {
                if (in_tree[u]) continue;
                if (key[u] != -std::numeric_limits<double>::infinity()) {
                    const double e = cost(v, u) + pi[v] + pi[u];
                    if (e < key[u]) {
                        key[u] = e;
                        parent[u] = v;
                    }
                }
                if (key[u] < best || next == 0) {
                    best = key[u];
                    next = u;
                }
            }
            if (next != 0 && key[next] == -std::numeric_limits<double>::infinity()) {
                key[next] = pi[next] + pi[parent[next]];  // the forced edge with its penalties
            }
        }
        // The hole's two cheapest edges.
        double e1 = std::numeric_limits<double>::infinity(), e2 = e1;
        std::size_t v1 = 1, v2 = 1;
        for (std::size_t u = 1; u < n; ++u) {
            const double e = cost(0, u) + pi[0] + pi[u];
            if (e < e1) {
                e2 = e1;
                v2 = v1;
                e1 = e;
                v1 = u;
            } else if (e < e2) {
                e2 = e;
                v2 = u;
            }
        }
        if (n == 3) {  // one cut: the hole joins both its ends
            e2 = cost(0, v1 == 1 ? 2 : 1) + pi[0] + pi[v1 == 1 ? 2 : 1];
            v2 = v1 == 1 ? 2 : 1;
        }
        degree[0] = 2;
        ++degree[v1];
        ++degree[v2];
        double pi_sum = 0;
        for (double p : pi) pi_sum += p;
        const double bound = tree + e1 + e2 - 2.0 * pi_sum;
        if (bound > out.value + 1e-12) {
            out.value = bound;
            since_better = 0;
        } else if (++since_better >= 20) {
            lambda /= 2.0;
            since_better = 0;
        }
        double norm2 = 0;
        for (std::size_t v = 0; v < n; ++v) norm2 += static_cast<double>((degree[v] - 2) * (degree[v] - 2));
        if (norm2 == 0) break;  // the 1-tree is a round trip: optimal
        if (lambda < 1e-6) break;
        const double step = lambda * std::max(upper - bound, 1e-9 * std::abs(upper)) / norm2;
        for (std::size_t v = 0; v < n; ++v) pi[v] += step * (degree[v] - 2);
    }
    return out;
}

}  // namespace nckit::pattern
