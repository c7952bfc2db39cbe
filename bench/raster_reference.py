#!/usr/bin/env python3
"""Jerk-limited reference for bench/planner_programs/raster_3d.ngc on a curve within its G64 P.

The raster's 2,000 G1 moves are chords (0.5 mm, Z written with 4 decimals) of 20 rows over the
surface z = 2 sin(x/8) cos(y/6) (gen_limit_programs.py). Its exact path turns by about 0.016 rad
at every vertex, where a jerk-limited machine would have to stop; the rows of the surface
itself lie within 1e-3 mm of the chords (sagitta 0.5² · 0.031 / 8, plus 5e-5 of rounding),
inside P0.01. This takes each row as that smooth curve, and the 1 mm steps between rows as the
program's lines; the 90° corners at the row ends stop (on the exact path a corner must). The
time is a trajectory within P: an upper bound of the optimum within P (up to the grid error
and the local method of jerk_reference.py), except that the corners are not blended.

Usage: bench/raster_reference.py --jmax J [--vmax 100] [--amax 500] [--max-points 4000]
Prints the JSON of jerk_reference.reference.
"""
import argparse
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import jerk_reference  # noqa: E402  (re-runs itself under Debian's python3 when scipy is missing)
from jerk_reference_lp import np  # noqa: E402
from topp_reference import Piece  # noqa: E402

ROWS, COLS, STEP_X, STEP_Y, FEED = 20, 99, 0.5, 1.0, 3000.0 / 60.0


def z_at(x, y):
    return 2.0 * math.sin(x / 8.0) * math.cos(y / 6.0)


class SurfaceRow:
    """The row y of the surface from x0 to x1, by arc length s (the interface of Piece)."""

    def __init__(self, x0, x1, y):
        self.kind, self.feed, self.y, self.x0 = "row", FEED, y, x0
        self.sign = 1.0 if x1 > x0 else -1.0
        lam = np.linspace(0.0, abs(x1 - x0), 20001)
        speed = np.sqrt(1.0 + self._dz(x0 + self.sign * lam) ** 2)
        self.s = np.concatenate([[0.0], np.cumsum(0.5 * (speed[1:] + speed[:-1]) * np.diff(lam))])
        self.lam = lam
        self.length = float(self.s[-1])

    def _dz(self, x):
        return 2.0 / 8.0 * np.cos(x / 8.0) * math.cos(self.y / 6.0)

    def _d2(self, lam):
        """q' and q'' at parameter lam (x = x0 + sign lam)."""
        x = self.x0 + self.sign * lam
        fz1 = 2.0 / 8.0 * math.cos(x / 8.0) * math.cos(self.y / 6.0)
        fz2 = -2.0 / 64.0 * math.sin(x / 8.0) * math.cos(self.y / 6.0)
        p1 = np.array([self.sign, 0.0, self.sign * fz1])
        p2 = np.array([0.0, 0.0, fz2])
        g = math.sqrt(1.0 + fz1 * fz1)
        t = p1 / g
        return t, (p2 - np.dot(t, p2) * t) / (g * g), g

    def derivatives3(self, s):
        lam = float(np.interp(s, self.s, self.lam))
        d1, d2, g = self._d2(lam)
        step = 1e-4  # q''' by a central difference of q'' in lam, divided by ds/dlam = g
        d3 = (self._d2(lam + step)[1] - self._d2(lam - step)[1]) / (2 * step * g)
        return list(d1), list(d2), list(d3)

    def derivatives(self, s):
        return self.derivatives3(s)[:2]


def pieces():
    out, pos = [], None
    for row in range(ROWS):
        y = row * STEP_Y
        x0, x1 = (0.0, COLS * STEP_X) if row % 2 == 0 else (COLS * STEP_X, 0.0)
        start = [x0, y, round(z_at(x0, y), 4)]
        if pos is not None:  # the program's step to the next row
            out.append(Piece(("line", pos, start, None, False, FEED)))
        out.append(SurfaceRow(x0, x1, y))
        pos = [x1, y, round(z_at(x1, y), 4)]
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--vmax", type=float, default=100.0)
    ap.add_argument("--amax", type=float, default=500.0)
    ap.add_argument("--jmax", type=float, required=True)
    ap.add_argument("--start-points", type=int, default=2000)
    ap.add_argument("--max-points", type=int, default=4000)
    args = ap.parse_args()
    result = jerk_reference.reference(pieces(), args.vmax, args.amax, args.jmax, "stop",
                                      start_points=args.start_points, max_points=args.max_points)
    print(json.dumps({"program": "raster_3d.ngc (rows as the surface curve)", **result}))


if __name__ == "__main__":
    sys.exit(main())
