#!/usr/bin/env python3
"""Jerk-limited reference on a path within G64 P: every curvature jump of a planar G1/G2/G3
program (line into arc, tangent arcs turning opposite ways) is replaced by a quintic that has
the programmed path's position, direction and curvature at both ends (quintic Hermite, like
nckit's transitions, docs/planner.md), trimmed symmetrically by the largest length whose quintic
stays within P of the programmed path (bisection, deviation sampled at 400 points against the
lines and the arcs' own spans). The new path has continuous curvature, so bench/jerk_reference.py
passes its joins at speed. Its time is that of a trajectory within P: an upper bound of the
jerk-limited optimum within P, up to the grid error (one curve of that family, not the best).

Usage: bench/jerk_reference_blend.py PROGRAM --jmax J [--tolerance 0.01] [--max-points 8000]
Prints the JSON of jerk_reference.reference with "transitions" and their "trim_mm".
"""
import argparse
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from jerk_reference import reference  # noqa: E402
from jerk_reference_lp import classify_joins, np  # noqa: E402  (re-runs under Debian's python3)
from topp_reference import Piece, parse  # noqa: E402


class Move:
    """A programmed move with its position as well as its derivatives (planar arcs)."""

    def __init__(self, move):
        self.piece = Piece(move)
        self.kind, self.a, self.b = move[0], np.array(move[1]), np.array(move[2])
        self.length, self.feed = self.piece.length, self.piece.feed
        self.derivatives3 = self.piece.derivatives3

    def position(self, s):
        p = self.piece
        if self.kind == "line":
            return self.a + (self.b - self.a) * s / p.length
        th = p.a0 + p.sign * p.k * s
        return np.array([p.c[0] + p.r * math.cos(th), p.c[1] + p.r * math.sin(th), self.a[2] + p.dz * s / p.length])

    def distance(self, x):
        """Distance of point x from this move (planar)."""
        p = self.piece
        if self.kind == "line":
            d = self.b - self.a
            f = min(1.0, max(0.0, float(np.dot(x - self.a, d) / np.dot(d, d))))
            return float(np.linalg.norm(x - self.a - f * d))
        phi = math.atan2(x[1] - p.c[1], x[0] - p.c[0])
        delta = (p.sign * (phi - p.a0)) % (2 * math.pi)
        if delta <= p.k * p.length:
            return abs(math.hypot(x[0] - p.c[0], x[1] - p.c[1]) - p.r)
        return min(float(np.linalg.norm(x - self.position(0.0))), float(np.linalg.norm(x - self.position(p.length))))


class Trimmed:
    def __init__(self, move, s0, s1):
        self.move, self.s0, self.length, self.feed, self.kind = move, s0, s1 - s0, move.feed, move.kind

    def derivatives3(self, s):
        return self.move.derivatives3(self.s0 + s)


class Quintic:
    """Quintic Hermite from A to B with given first and second derivatives, by arc length."""

    def __init__(self, pa, da, dda, pb, db, ddb, feed):
        scale = float(np.linalg.norm(pb - pa))
        d0, d1, dd0, dd1 = da * scale, db * scale, dda * scale ** 2, ddb * scale ** 2
        # Coefficients of p(l) = sum c_k l^k matching p, p', p'' at l = 0 and 1.
        c0, c1, c2 = pa, d0, dd0 / 2
        r0 = pb - (c0 + c1 + c2)
        r1 = d1 - (c1 + 2 * c2)
        r2 = dd1 - 2 * c2
        c3 = 10 * r0 - 4 * r1 + r2 / 2
        c4 = -15 * r0 + 7 * r1 - r2
        c5 = 6 * r0 - 3 * r1 + r2 / 2
        self.c = [c0, c1, c2, c3, c4, c5]
        self.feed, self.kind = feed, "quintic"
        lam = np.linspace(0.0, 1.0, 4001)
        speed = np.array([np.linalg.norm(self._d(x, 1)) for x in lam])
        self.s = np.concatenate([[0.0], np.cumsum(0.5 * (speed[1:] + speed[:-1]) * np.diff(lam))])
        self.lam, self.length = lam, float(self.s[-1])

    def _d(self, x, order):
        out = 0.0
        for k in range(order, 6):
            out = out + self.c[k] * math.factorial(k) / math.factorial(k - order) * x ** (k - order)
        return out

    def position(self, x):
        return self._d(x, 0)

    def _q12(self, x):
        p1, p2 = self._d(x, 1), self._d(x, 2)
        g = float(np.linalg.norm(p1))
        t = p1 / g
        return t, (p2 - np.dot(t, p2) * t) / (g * g), g

    def derivatives3(self, s):
        x = float(np.interp(s, self.s, self.lam))
        d1, d2, g = self._q12(x)
        step = 1e-5
        d3 = (self._q12(min(1.0, x + step))[1] - self._q12(max(0.0, x - step))[1]) / ((min(1.0, x + step) - max(0.0, x - step)) * g)
        return list(d1), list(d2), list(d3)


def blend(moves, n, trim):
    """The quintic replacing the join before moves[n], trimmed by `trim` on both sides."""
    a, b = moves[n - 1], moves[n]
    da = a.derivatives3(a.length - trim)
    db = b.derivatives3(trim)
    return Quintic(a.position(a.length - trim), np.array(da[0]), np.array(da[1]),
                   b.position(trim), np.array(db[0]), np.array(db[1]), b.feed)


def deviation(moves, n, quintic):
    near = [moves[n - 1], moves[n]]
    return max(min(m.distance(quintic.position(x)) for m in near) for x in np.linspace(0.0, 1.0, 401))


def blended_pieces(text, tolerance):
    """The program's path with each curvature jump blended within tolerance; and the trims."""
    moves = [Move(m) for m in parse(text)]
    _, jumps = classify_joins([m.piece for m in moves], 1e-3, 1e-4)
    trims = {}
    for n in sorted(jumps):
        lo, hi = 0.0, 0.45 * min(moves[n - 1].length, moves[n].length)
        for _ in range(40):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if deviation(moves, n, blend(moves, n, mid)) <= tolerance else (lo, mid)
        trims[n] = lo
    pieces = []
    for n, m in enumerate(moves):
        if n in trims:
            pieces.append(blend(moves, n, trims[n]))
        pieces.append(Trimmed(m, trims.get(n, 0.0), m.length - trims.get(n + 1, 0.0)))
    return pieces, trims


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("program")
    ap.add_argument("--jmax", type=float, required=True)
    ap.add_argument("--vmax", type=float, default=100.0)
    ap.add_argument("--amax", type=float, default=500.0)
    ap.add_argument("--tolerance", type=float, default=0.01, help="G64 P, mm")
    ap.add_argument("--start-points", type=int, default=2000)
    ap.add_argument("--max-points", type=int, default=8000)
    args = ap.parse_args()
    pieces, trims = blended_pieces(open(args.program).read(), args.tolerance)
    result = reference(pieces, args.vmax, args.amax, args.jmax, "pass",
                       start_points=args.start_points, max_points=args.max_points)
    print(json.dumps({"program": args.program, "transitions": len(trims),
                      "trim_mm": [min(trims.values(), default=0.0), max(trims.values(), default=0.0)], **result}))


if __name__ == "__main__":
    sys.exit(main())
