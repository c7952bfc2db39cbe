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
Prints JSON: {"program", "time_s" (finest grid), "extrapolated_s" (Richardson, last two grids),
"grid_points", "refinements": [[points, time_s, LPs]], "last_change", "converged", "corners",
"curvature_jumps", "joins"}.
"""
import argparse
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
# jerk_reference_lp re-runs the script under Debian's python3 when scipy is missing.
from jerk_reference_lp import classify_joins, Grid, solve  # noqa: E402
from topp_reference import Piece, parse  # noqa: E402  (the same path model as the TOPP reference)


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


def run_key(run):
    """What a run's time depends on: lengths, feeds and the path's derivatives at a few points,
    each axis's sign taken from its first non-zero value (the limits are symmetric, so a run and
    its mirror image, like two semicircles G2 and G3 of one radius, take the same time)."""
    samples = []
    for p in run:
        for x in (0.0, 0.1, 0.25, 0.5, 0.75, 0.9, 1.0):
            samples.append(p.derivatives3(x * p.length))
    signs = []
    for i in range(3):
        first = next((d[i] for sample in samples for d in sample if abs(d[i]) > 1e-12), 1.0)
        signs.append(1.0 if first > 0 else -1.0)
    flat = tuple(round(d[i] * signs[i], 9) for sample in samples for d in sample for i in range(3))
    return tuple(round(p.length, 9) for p in run), tuple(p.feed for p in run), flat


def reference(pieces, vmax, amax, jmax, joins="pass", kink_rad=1e-3, curvature_tol=1e-4,
              start_points=2000, max_points=64000, tolerance=1e-4):
    """Time of the reference, grid doubled from start_points nodes (spread over the program by
    length, at least 64 a run at the start) until it moves by less than tolerance relative, or max_points.
    The runs between rest points are independent: each is solved on its own (once for runs
    that are the same up to the signs of the axes)."""
    corners, jumps = classify_joins(pieces, kink_rad, curvature_tol)
    stops = {0} | corners | (jumps if joins == "stop" else set())
    total = sum(p.length for p in pieces)
    refinements, points = [], start_points
    while points <= max_points:
        t, nodes, iterations, solved = 0.0, 0, 0, {}
        for run in runs(pieces, stops):
            floor = 64 * points // start_points  # short runs are refined too
            count = max(floor, round(points * sum(p.length for p in run) / total))
            key = (run_key(run), count)
            if key not in solved:
                grid = Grid(run, {0}, count)
                solved[key] = solve(grid, vmax, amax, jmax)[:2] + (len(grid.s),)
            t_run, it, n_run = solved[key]
            t, nodes, iterations = t + t_run, nodes + n_run, max(iterations, it)
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
