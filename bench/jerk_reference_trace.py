#!/usr/bin/env python3
"""Checks a jerk-limited reference profile from outside: the profile of bench/jerk_reference.py
for one run of PROGRAM (from rest to rest, joins passed) is turned into positions at a fixed
time step (s(t) exact for u linear on each interval: constant path acceleration there), and
the per-axis speed, acceleration and jerk are taken as finite differences of those positions
(a k-th difference is a weighted mean of the k-th derivative, so a trajectory that keeps its
limits at every instant stays within them).

Usage: bench/jerk_reference_trace.py PROGRAM --jmax J [--points 2000] [--vmax 100] [--amax 500]
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
    args = ap.parse_args()
    grid = Grid([Piece(m) for m in parse(open(args.program).read())], {0}, args.points)
    t, _, u = solve(grid, args.vmax, args.amax, args.jmax)
    root = np.sqrt(np.maximum(u, 0.0))
    accel = (u[1:] - u[:-1]) / (2 * grid.h)
    rest = grid.rest[:-1] | grid.rest[1:]
    # Time of each interval under constant path acceleration (u linear in s).
    dt = np.where(np.abs(accel) > 1e-12, (root[1:] - root[:-1]) / np.where(np.abs(accel) > 1e-12, accel, 1.0),
                  2 * grid.h / np.maximum(root[:-1] + root[1:], 1e-300))
    nodes_t = np.concatenate([[0.0], np.cumsum(dt)])
    # Positions at the nodes: q' integrated at the interval midpoints.
    d1 = np.array([m[0] for m in grid.mids])
    q = np.concatenate([np.zeros((1, 3)), np.cumsum(d1 * grid.h[:, None], axis=0)])
    print(f"reference {t:.6f} s, profile {nodes_t[-1]:.6f} s, {len(grid.s)} nodes, {int(rest.sum())} rest intervals")
    for h in (0.01, 0.005, 0.0025):
        ts = np.arange(0.0, nodes_t[-1], h)
        k = np.clip(np.searchsorted(nodes_t, ts, side="right") - 1, 0, len(grid.h) - 1)
        tau = ts - nodes_t[k]
        s = np.minimum(grid.s[k] + root[k] * tau + 0.5 * accel[k] * tau ** 2, grid.s[k + 1])
        pos = np.stack([np.interp(s, grid.s, q[:, i]) for i in range(3)], axis=1)
        v = np.abs(np.diff(pos, 1, axis=0)).max() / h
        a = np.abs(np.diff(pos, 2, axis=0)).max() / h ** 2
        j = np.abs(np.diff(pos, 3, axis=0)).max() / h ** 3
        print(f"step {h * 1000:g} ms: v {v:.3f} ({v / args.vmax:.4f}), a {a:.2f} ({a / args.amax:.4f}), "
              f"j {j:.1f} ({j / args.jmax:.4f})")


if __name__ == "__main__":
    sys.exit(main())
