#!/usr/bin/env python3
"""Jerk-limited time-optimal reference on the exact programmed path (docs/planner.md,
"The jerk-limited reference").

The path q(s) of a G1/G2/G3 program (s = arc length; parsed by topp_reference.py) is sampled
on a grid s_0 < ... < s_N. The unknowns are u_k = sdot^2 at the nodes; on interval k the path
acceleration is A_k = sddot = (u_{k+1} - u_k) / (2 h_k). Per axis i, with a = amax and
J = jmax:
  speed         |q_i'| sdot <= vmax, sdot <= F:              bounds on u_k
  acceleration  |q_i'' u + q_i' A_k| <= a  (interval midpoint):  linear in u
  jerk          j_i = q_i''' sdot^3 + 3 q_i'' sdot sddot + q_i' sdddot, the FULL per-axis jerk.
                With sdddot = (A_k - A_{k-1}) / dt_k, dt_k the time between the midpoints of
                the intervals beside node k, and sdot dt_k = m_k = (h_{k-1} + h_k) / 2 where
                the speed is smooth, |j_i| <= J becomes
                  |m_k (q_i''' u_k + 1.5 q_i'' (A_{k-1} + A_k)) + q_i' (A_k - A_{k-1})| <= J dt_k(u)
                At a node where the axes rest (sdot = 0) the curvature terms vanish and the
                acceleration on either side is taken with that side's direction:
                  |q_i'(+) A_k - q_i'(-) A_{k-1}| <= J dt_k(u),  A = 0 before the start and after
                the end (rest with zero acceleration).
The left-hand sides are linear in u. dt_k(u) = sum over the half intervals beside node k of
h / (sqrt(u_k) + sqrt(u_mid)) (exact when u is linear there) is convex in u, so its tangent
plane at any point lies below it: replacing dt_k by the tangent at the previous iterate gives
linear constraints whose solutions all keep the true constraint (an inner approximation).
Each iteration maximises sum m_k u_k under them (scipy's linprog, HiGHS); the previous iterate
stays feasible, so the objective never decreases (convex-concave procedure) and the iteration
stops when it moves by less than 1e-9 relative. The first iterate is the acceleration-limited
optimum (the same LP without the jerk rows).

Time: sum 2 h_k / (sqrt(u_k) + sqrt(u_{k+1})) (exact for u linear on each interval), except
on an interval that starts or ends at rest, where s grows as t^3 (zero acceleration at rest),
u as s^(4/3), and the time is 3 h / sqrt(u at the other end). Grids are graded towards every
rest point (s ~ xi^3 there, so u is smooth in the grid variable); the number of nodes is
doubled until the time moves by less than 1e-4 relative.

Joins: a direction change above --kink-rad is a corner: the exact path has to stop there.
A jump of the curvature vector q'' above --curvature-tol /mm steps the acceleration by
|dq''| sdot^2, which no jerk limit allows at speed: with --joins stop the reference stops
there too (a feasible trajectory on the exact path); with --joins pass it passes them and keeps
the jerk on either side only (a relaxation: the step in acceleration at the join is allowed).

Usage: bench/jerk_reference.py PROGRAM --jmax J [--vmax 100] [--amax 500] [--joins stop|pass]
Prints JSON: {"program", "time_s", "grid_points", "refinements": [[points, time_s, iters]],
"corners", "curvature_jumps", "joins", "converged"}.
"""
import argparse
import json
import math
import os
import sys

try:
    import numpy as np
    from scipy import sparse
    from scipy.optimize import linprog
except ImportError:
    # Debian's python3-scipy is installed for /usr/bin/python3; a python3 earlier on PATH
    # (a virtual environment, pyenv) may not see it.
    if os.path.exists("/usr/bin/python3") and os.path.realpath(sys.executable) != os.path.realpath("/usr/bin/python3"):
        os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv)
    sys.exit("jerk_reference.py: needs numpy and scipy (Debian python3-scipy: scripts/deps.sh bench)")

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from topp_reference import Piece, parse  # noqa: E402  (the same path model as the TOPP reference)

U_FLOOR = 1e-12  # (mm/s)^2: tangents are taken at no smaller u (any point gives a valid tangent)


def classify_joins(pieces, kink_rad, curvature_tol):
    """Indices n of the pieces whose start is a corner, and those whose start steps q''."""
    corners, jumps = set(), set()
    for n in range(1, len(pieces)):
        a1, a2, _ = pieces[n - 1].derivatives3(pieces[n - 1].length)
        b1, b2, _ = pieces[n].derivatives3(0.0)
        dot = max(-1.0, min(1.0, sum(x * y for x, y in zip(a1, b1))))
        if math.acos(dot) > kink_rad:
            corners.add(n)
        elif math.sqrt(sum((x - y) ** 2 for x, y in zip(a2, b2))) > curvature_tol:
            jumps.add(n)
    return corners, jumps


def graded(m, stop_start, stop_end):
    """m + 1 values from 0 to 1, s ~ xi^3 at an end that is a rest point, uniform elsewhere."""
    xi = np.linspace(0.0, 1.0, m + 1)
    if stop_start and stop_end:
        return xi - np.sin(2 * math.pi * xi) / (2 * math.pi)
    if stop_start:
        return xi - np.sin(math.pi * xi) / math.pi
    if stop_end:
        return 1.0 - ((1.0 - xi) - np.sin(math.pi * (1.0 - xi)) / math.pi)
    return xi


class Grid:
    """Nodes along the path: s, geometry on the left and right of each node, rest points."""

    def __init__(self, pieces, stops, points):
        total = sum(p.length for p in pieces)
        s, left, right, rest, mids = [0.0], [], [], [True], []
        zero = ([0.0] * 3, [0.0] * 3, [0.0] * 3)
        left.append(zero)
        offset = 0.0
        for n, p in enumerate(pieces):
            m = max(8, math.ceil(points * p.length / total))
            xs = graded(m, n in stops, n + 1 == len(pieces) or (n + 1) in stops) * p.length
            right.append(p.derivatives3(0.0))
            for k in range(1, m + 1):
                mids.append(p.derivatives3(0.5 * (xs[k - 1] + xs[k]))[:2] + (p.feed,))
                s.append(offset + xs[k])
                left.append(p.derivatives3(xs[k]))
                if k < m:
                    right.append(left[-1])
                    rest.append(False)
            rest.append(n + 1 == len(pieces) or (n + 1) in stops)
            offset += p.length
        right.append(zero)
        self.s = np.array(s)
        self.h = np.diff(self.s)
        self.rest = np.array(rest)
        self.left, self.right, self.mids = left, right, mids
        self.feed = [p.feed for p in pieces]


def node_bounds(grid, vmax):
    """Upper bound of u at each node from the axis speeds and the feed."""
    n = len(grid.s)
    upper = np.full(n, np.inf)
    for k in range(n):
        for geo in (grid.left[k], grid.right[k]):
            d1 = geo[0]
            for x in d1:
                if abs(x) > 1e-12:
                    upper[k] = min(upper[k], (vmax / abs(x)) ** 2)
    for k, (d1, _, feed) in enumerate(grid.mids):
        if math.isfinite(feed):
            upper[k] = min(upper[k], feed ** 2)
            upper[k + 1] = min(upper[k + 1], feed ** 2)
    upper[grid.rest] = 0.0
    return upper


def acceleration_rows(grid, amax):
    """|q'' (u_k + u_{k+1}) / 2 + q' (u_{k+1} - u_k) / (2 h_k)| <= amax per interval and axis."""
    rows, cols, vals, rhs = [], [], [], []
    r = 0
    for k, (d1, d2, _) in enumerate(grid.mids):
        h = grid.h[k]
        for i in range(3):
            if abs(d1[i]) < 1e-15 and abs(d2[i]) < 1e-15:
                continue
            c0, c1 = d2[i] / 2 - d1[i] / (2 * h), d2[i] / 2 + d1[i] / (2 * h)
            for sign in (1.0, -1.0):
                rows += [r, r]
                cols += [k, k + 1]
                vals += [sign * c0, sign * c1]
                rhs.append(amax)
                r += 1
    return rows, cols, vals, rhs, r


def jerk_terms(grid):
    """Per node and axis (and side at a join), the linear jerk expression as
    (node, {column: coefficient}); the right-hand side is jmax * dt_node(u)."""
    terms = []
    n = len(grid.s)
    for k in range(n):
        hl = grid.h[k - 1] if k > 0 else None
        hr = grid.h[k] if k < n - 1 else None
        if grid.rest[k]:
            d1l, d1r = grid.left[k][0], grid.right[k][0]
            for i in range(3):
                coef = {}
                if hr is not None and abs(d1r[i]) > 1e-15:  # + q_i'(+) A_k
                    coef[k + 1] = coef.get(k + 1, 0.0) + d1r[i] / (2 * hr)
                    coef[k] = coef.get(k, 0.0) - d1r[i] / (2 * hr)
                if hl is not None and abs(d1l[i]) > 1e-15:  # - q_i'(-) A_{k-1}
                    coef[k] = coef.get(k, 0.0) - d1l[i] / (2 * hl)
                    coef[k - 1] = coef.get(k - 1, 0.0) + d1l[i] / (2 * hl)
                if coef:
                    terms.append((k, coef))
            continue
        m = 0.5 * (hl + hr)
        geos = [grid.left[k]] if grid.left[k] is grid.right[k] else [grid.left[k], grid.right[k]]
        for d1, d2, d3 in geos:
            for i in range(3):
                if abs(d1[i]) < 1e-15 and abs(d2[i]) < 1e-15 and abs(d3[i]) < 1e-15:
                    continue
                ca_prev = 1.5 * m * d2[i] - d1[i]  # coefficient of A_{k-1}
                ca_next = 1.5 * m * d2[i] + d1[i]  # coefficient of A_k
                terms.append((k, {k - 1: -ca_prev / (2 * hl),
                                  k: m * d3[i] + ca_prev / (2 * hl) - ca_next / (2 * hr),
                                  k + 1: ca_next / (2 * hr)}))
    return terms


def half_time(h, u_node, u_other):
    """Time over the half interval of length h/2 next to a node, u linear: value and gradient."""
    x, w = max(u_node, U_FLOOR), max(0.5 * (u_node + u_other), U_FLOOR)
    root = math.sqrt(x) + math.sqrt(w)
    value = h / root  # 2 (h / 2) / (sqrt(u_node) + sqrt(u_mid))
    g_other = -h / root ** 2 * (0.25 / math.sqrt(w))
    g_node = -h / root ** 2 * (0.5 / math.sqrt(x)) + g_other
    return value, g_node, g_other


def cycle_time(grid, u, gradient=False):
    """Time of the profile u and (gradient=True) its gradient in u."""
    root = np.sqrt(np.maximum(u, 0.0))
    rest_l, rest_r = grid.rest[:-1], grid.rest[1:]
    with np.errstate(divide="ignore", invalid="ignore"):
        regular = 2 * grid.h / (root[:-1] + root[1:])
        other = np.where(rest_l, root[1:], root[:-1])
        at_rest = 3 * grid.h / other
        t = np.where(rest_l | rest_r, at_rest, regular)
        total = float(np.sum(t)) if np.all(np.isfinite(t)) else math.inf
        if not gradient:
            return total
        rf = np.maximum(root, math.sqrt(U_FLOOR))
        g = np.zeros(len(u))
        pair = -grid.h / (rf[:-1] + rf[1:]) ** 2
        near = ~(rest_l | rest_r)
        np.add.at(g, np.arange(len(grid.h))[near], (pair / rf[:-1])[near])
        np.add.at(g, np.arange(1, len(u))[near], (pair / rf[1:])[near])
        of = np.maximum(other, math.sqrt(U_FLOOR))
        idx = np.where(rest_l, np.arange(1, len(u)), np.arange(len(grid.h)))
        np.add.at(g, idx[~near], (-1.5 * grid.h / of ** 3)[~near])
    return total, g


def jerk_matrix(grid, terms, u, jmax):
    """The jerk rows with dt replaced by its tangent at u (an inner approximation)."""
    n = len(grid.s)
    rows, cols, vals, rhs = [], [], [], []
    r = 0
    for k, coef in terms:
        # Tangent of dt_k at u: dt ~ dt0 + g . (u' - u).
        dt0, grad = 0.0, {}
        for other, h in ((k - 1, grid.h[k - 1] if k > 0 else 0.0), (k + 1, grid.h[k] if k < n - 1 else 0.0)):
            if h == 0.0:
                continue
            v, gn, go = half_time(h, u[k], u[other])
            dt0 += v
            # A rest node's u is fixed at 0: no gradient towards it (dt at the floor is below
            # dt at 0, so the tangent still lies below the true dt).
            if not grid.rest[k]:
                grad[k] = grad.get(k, 0.0) + gn
            if not grid.rest[other]:
                grad[other] = grad.get(other, 0.0) + go
        constant = jmax * (dt0 - sum(g * u[j] for j, g in grad.items()))
        for sign in (1.0, -1.0):
            merged = {j: sign * c for j, c in coef.items()}
            for j, g in grad.items():
                merged[j] = merged.get(j, 0.0) - jmax * g
            for j, c in merged.items():
                rows.append(r)
                cols.append(j)
                vals.append(c)
            rhs.append(constant)
            r += 1
    return sparse.csr_matrix((vals, (rows, cols)), shape=(r, n)), np.array(rhs)


def line_search(grid, u0, u1):
    """The point of the segment u0 -> u1 with the least time (convex along it): golden section."""
    lo, hi = 0.0, 1.0
    ratio = (math.sqrt(5) - 1) / 2
    a, b = hi - ratio * (hi - lo), lo + ratio * (hi - lo)
    ta, tb = cycle_time(grid, u0 + a * (u1 - u0)), cycle_time(grid, u0 + b * (u1 - u0))
    for _ in range(40):
        if ta <= tb:
            hi, b, tb = b, a, ta
            a = hi - ratio * (hi - lo)
            ta = cycle_time(grid, u0 + a * (u1 - u0))
        else:
            lo, a, ta = a, b, tb
            b = lo + ratio * (hi - lo)
            tb = cycle_time(grid, u0 + b * (u1 - u0))
    best = min((cycle_time(grid, u0 + x * (u1 - u0)), x) for x in (0.0, lo, hi, 1.0))
    return u0 + best[1] * (u1 - u0), best[0]


def solve(grid, vmax, amax, jmax, max_iterations=200, tolerance=1e-7):
    """Least time under the inner approximation, by a descent of its linearisation: each LP
    minimises the time's tangent at the iterate within the jerk rows linearised there; the
    next iterate is the best point between the two (both keep every constraint)."""
    n = len(grid.s)
    bounds = np.column_stack([np.zeros(n), node_bounds(grid, vmax)])
    rows, cols, vals, rhs, r0 = acceleration_rows(grid, amax)
    a_acc = sparse.csr_matrix((vals, (rows, cols)), shape=(r0, n))
    b_acc = np.array(rhs)

    def lp(weights, a_ub, b_ub):
        res = linprog(weights / np.max(np.abs(weights)), A_ub=a_ub, b_ub=b_ub, bounds=bounds, method="highs")
        if res.status != 0:
            raise RuntimeError(f"linprog: {res.message}")
        return np.clip(res.x, 0.0, bounds[:, 1])

    m = np.concatenate([[0.5 * grid.h[0]], 0.5 * (grid.h[:-1] + grid.h[1:]), [0.5 * grid.h[-1]]])
    u = lp(-m, a_acc, b_acc)  # the acceleration-limited profile: where the tangents start
    terms = jerk_terms(grid)
    t, feasible = math.inf, False
    iterations = 0
    for iterations in range(1, max_iterations + 1):
        _, g = cycle_time(grid, u, gradient=True)
        a_jerk, b_jerk = jerk_matrix(grid, terms, u, jmax)
        candidate = lp(g, sparse.vstack([a_acc, a_jerk]).tocsr(), np.concatenate([b_acc, b_jerk]))
        if feasible:
            u_next, t_next = line_search(grid, u, candidate)
        else:
            u_next, t_next, feasible = candidate, cycle_time(grid, candidate), True
        change = abs(t - t_next) / t_next if math.isfinite(t) else math.inf
        u, t = u_next, t_next
        if change < tolerance:
            break
    return t, iterations, u


def scurve_line_time(length, vmax, amax, jmax):
    """Closed-form time of the rest-to-rest 7-phase S-curve (jerk, constant acceleration and
    cruise phases, zero acceleration at both ends) over a straight move along one axis."""
    def ramp(v):  # time and distance from rest to speed v with zero acceleration at both ends
        if v * jmax >= amax * amax:
            t = v / amax + amax / jmax
        else:
            t = 2 * math.sqrt(v / jmax)
        return t, 0.5 * v * t  # the ramp is point-symmetric: mean speed v / 2
    t, d = ramp(vmax)
    if 2 * d <= length:
        return 2 * t + (length - 2 * d) / vmax
    lo, hi = 0.0, vmax
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if 2 * ramp(mid)[1] <= length else (lo, mid)
    return 2 * ramp(lo)[0]


def runs(pieces, stops):
    """The program cut at its rest points: lists of pieces that start and end at rest."""
    out, current = [], []
    for n, p in enumerate(pieces):
        if n in stops and current:
            out.append(current)
            current = []
        current.append(p)
    return out + [current]


def reference(pieces, vmax, amax, jmax, joins="pass", kink_rad=1e-3, curvature_tol=1e-4,
              start_points=2000, max_points=64000, tolerance=1e-4):
    """Time of the reference, grid doubled from start_points nodes (spread over the program by
    length, at least 64 a run at the start) until it moves by less than tolerance relative, or max_points.
    The runs between rest points are independent: each is solved on its own."""
    corners, jumps = classify_joins(pieces, kink_rad, curvature_tol)
    stops = {0} | corners | (jumps if joins == "stop" else set())
    total = sum(p.length for p in pieces)
    refinements, points = [], start_points
    while points <= max_points:
        t, nodes, iterations = 0.0, 0, 0
        for run in runs(pieces, stops):
            floor = 64 * points // start_points  # short runs are refined too
            grid = Grid(run, {0}, max(floor, round(points * sum(p.length for p in run) / total)))
            t_run, it, _ = solve(grid, vmax, amax, jmax)
            t, nodes, iterations = t + t_run, nodes + len(grid.s), max(iterations, it)
        refinements.append([nodes, t, iterations])
        if len(refinements) > 1 and abs(t - refinements[-2][1]) < tolerance * t:
            break
        points *= 2
    moved = abs(refinements[-1][1] - refinements[-2][1]) / refinements[-1][1] if len(refinements) > 1 else math.inf
    # The grid error falls as 1/nodes (measured on the straight line against the closed form):
    # Richardson's extrapolation of the last two grids.
    extrapolated = 2 * refinements[-1][1] - refinements[-2][1] if len(refinements) > 1 else None
    return {"time_s": refinements[-1][1], "extrapolated_s": extrapolated, "grid_points": refinements[-1][0],
            "refinements": refinements, "last_change": moved, "converged": moved < tolerance,
            "corners": len(corners), "curvature_jumps": len(jumps), "joins": joins}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("program")
    ap.add_argument("--vmax", type=float, default=100.0)
    ap.add_argument("--amax", type=float, default=500.0)
    ap.add_argument("--jmax", type=float, required=True)
    ap.add_argument("--joins", choices=["pass", "stop"], default="pass",
                    help="curvature jumps: passed with the jerk kept on either side, or exact stops")
    ap.add_argument("--kink-rad", type=float, default=1e-3)
    ap.add_argument("--curvature-tol", type=float, default=1e-4, help="/mm")
    ap.add_argument("--start-points", type=int, default=2000)
    ap.add_argument("--max-points", type=int, default=64000)
    args = ap.parse_args()
    pieces = [Piece(m) for m in parse(open(args.program).read())]
    result = reference(pieces, args.vmax, args.amax, args.jmax, args.joins, args.kink_rad,
                       args.curvature_tol, args.start_points, args.max_points)
    print(json.dumps({"program": args.program, **result}))


if __name__ == "__main__":
    sys.exit(main())
