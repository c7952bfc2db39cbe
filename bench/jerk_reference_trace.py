#!/usr/bin/env python3
"""Checks a jerk-limited reference profile from outside: the profile of bench/jerk_reference.py
for PROGRAM taken as one run (from rest to rest, joins passed) is turned into positions at a fixed
time step (s(t) exact for u linear on each interval: constant path acceleration there), and
the per-axis speed, acceleration and jerk are taken as finite differences of those positions
(a k-th difference is a weighted mean of the k-th derivative, so a trajectory that keeps its
limits at every instant stays within them).

Usage: bench/jerk_reference_trace.py PROGRAM --jmax J [--points 2000] [--blend P] [--vmax 100] [--amax 500]
(--blend: on the path of jerk_reference_blend.py; without it the joins are passed as programmed,
so a curvature jump shows as a step in acceleration).
Prints, per time step, the largest |v|, |a|, |j| over the axes and their ratio to the limits.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from jerk_reference_lp import Grid, np, solve  # noqa: E402  (re-runs under Debian's python3)
from topp_reference import Piece, parse  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("program")
    ap.add_argument("--jmax", type=float, required=True)
    ap.add_argument("--vmax", type=float, default=100.0)
    ap.add_argument("--amax", type=float, default=500.0)
    ap.add_argument("--points", type=int, default=2000)
    ap.add_argument("--blend", type=float, default=None, metavar="P",
                    help="the path of jerk_reference_blend.py: curvature jumps blended within P mm")
    args = ap.parse_args()
    text = open(args.program).read()
    if args.blend is None:
        pieces = [Piece(m) for m in parse(text)]
    else:
        from jerk_reference_blend import blended_pieces
        pieces = blended_pieces(text, args.blend)[0]
    grid = Grid(pieces, {0}, args.points)
    t, _, u = solve(grid, args.vmax, args.amax, args.jmax)
    root = np.sqrt(np.maximum(u, 0.0))
    accel = (u[1:] - u[:-1]) / (2 * grid.h)
    rest = grid.rest[:-1] | grid.rest[1:]
    # Time of each interval under constant path acceleration (u linear in s): 2 h / (sqrt(u_k) +
    # sqrt(u_k+1)), exact, and free of the cancellation of (sqrt(u_k+1) - sqrt(u_k)) / A.
    dt = 2 * grid.h / (root[:-1] + root[1:])
    nodes_t = np.concatenate([[0.0], np.cumsum(dt)])
    # The path between nodes: the quintic with the path's position, q' and q'' at both ends
    # (error O(h^6), continuous curvature: linear interpolation of positions would add kinks of
    # its own that the differences see); node positions by the corrected trapezoid rule.
    t0 = np.array([g[0] for g in grid.right[:-1]])
    t1 = np.array([g[0] for g in grid.left[1:]])
    c0 = np.array([g[1] for g in grid.right[:-1]])
    c1 = np.array([g[1] for g in grid.left[1:]])
    hh = grid.h[:, None]
    steps = hh * (t0 + t1) / 2 + hh ** 2 * (c0 - c1) / 12
    q = np.concatenate([np.zeros((1, 3)), np.cumsum(steps, axis=0)])

    def position(s):
        k = np.clip(np.searchsorted(grid.s, s, side="right") - 1, 0, len(grid.h) - 1)
        h = hh[k]
        x = ((s - grid.s[k]) / grid.h[k])[:, None]
        h0 = 1 - 10 * x ** 3 + 15 * x ** 4 - 6 * x ** 5
        h1 = x - 6 * x ** 3 + 8 * x ** 4 - 3 * x ** 5
        h2 = (x ** 2 - 3 * x ** 3 + 3 * x ** 4 - x ** 5) / 2
        h5 = 10 * x ** 3 - 15 * x ** 4 + 6 * x ** 5
        h4 = -4 * x ** 3 + 7 * x ** 4 - 3 * x ** 5
        h3 = (x ** 3 - 2 * x ** 4 + x ** 5) / 2
        return (h0 * q[k] + h1 * h * t0[k] + h2 * h ** 2 * c0[k]
                + h5 * q[k + 1] + h4 * h * t1[k] + h3 * h ** 2 * c1[k])
    print(f"reference {t:.6f} s, profile {nodes_t[-1]:.6f} s, {len(grid.s)} nodes, {int(rest.sum())} rest intervals")
    for h in (0.01, 0.005, 0.0025):
        ts = np.arange(0.0, nodes_t[-1], h)
        k = np.clip(np.searchsorted(nodes_t, ts, side="right") - 1, 0, len(grid.h) - 1)
        tau = ts - nodes_t[k]
        s = np.minimum(grid.s[k] + root[k] * tau + 0.5 * accel[k] * tau ** 2, grid.s[k + 1])
        pos = position(s)
        v = np.abs(np.diff(pos, 1, axis=0)).max() / h
        a = np.abs(np.diff(pos, 2, axis=0)).max() / h ** 2
        j = np.abs(np.diff(pos, 3, axis=0)).max() / h ** 3
        print(f"step {h * 1000:g} ms: v {v:.3f} ({v / args.vmax:.4f}), a {a:.2f} ({a / args.amax:.4f}), "
              f"j {j:.1f} ({j / args.jmax:.4f})")


if __name__ == "__main__":
    sys.exit(main())
