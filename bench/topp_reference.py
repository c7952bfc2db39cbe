#!/usr/bin/env python3
"""Time-optimal reference for the planner: grid TOPP with exact per-axis constraints.

For a program of G1/G2/G3 moves in G17 (absolute, mm, the programs in bench/planner_programs),
the path q(s) is taken exactly as programmed (lines and arcs, s = arc length). Along it the
axes must keep, at every s, for every axis i:
    |q_i'(s)| * sdot <= vmax,   |q_i''(s) * sdot^2 + q_i'(s) * sddot| <= amax,   |q'| * sdot <= F.
With u = sdot^2 these are linear in (u, sddot): at each grid point the largest feasible u (the
maximum velocity curve) follows in closed form from the pairwise intersections of the
per-axis bounds on sddot, and the fastest profile under it is the forward pass (accelerate as
hard as the point allows, u_{k+1} = u_k + 2 ds sddot_max) followed by the backward pass
(brake as hard as allowed), the classic reachability / numerical-integration TOPP. Its time
sum 2 ds / (sqrt(u_k) + sqrt(u_{k+1})) converges to the time-optimal cycle time as the grid is
refined; the grid is doubled until the time changes by less than 1e-4 relative.

Joins whose directions differ by more than --kink-rad (default 1e-3 rad: written decimals) are
corners: the reference stops there (exact path; a blend within G64 P would be faster, so for
programs with corners this is not the optimum and is reported as "exact-path").

With --jmax J the jerk the path itself takes at each point joins the constraints:
|q_i''' * sdot^3 + 3 q_i'' * sdot * sddot| <= J (turning jerk and coupling; the path jerk term
q_i' * sdddot is left out, so speed changes switch their acceleration at once). For a given u it
is linear in sddot; the maximum velocity curve is lowered by bisection where it leaves no sddot
(docs/planner.md, "The time-optimal reference"). Without the path jerk this is no jerk-limited
reference (at J 5,000 it equals the unlimited optimum on the circle): bench/jerk_reference.py
keeps the full per-axis jerk.

Usage: bench/topp_reference.py PROGRAM [--vmax 100] [--amax 500] [--jmax J] [--kink-rad 1e-3]
Prints JSON: {"program", "time_s", "grid_points", "refinements": [[points, time_s], ...],
"corners"}.
"""
import argparse
import json
import math
import sys


def parse(text):
    """[(kind, start, end, centre, clockwise, feed_mm_s)]"""
    pos, mode, feed = [0.0, 0.0, 0.0], 1, 0.0
    out = []
    for raw in text.splitlines():
        line = raw.split("(")[0].strip().upper()
        if not line or line.startswith("%"):
            continue
        words, gs, i = {}, [], 0
        while i < len(line):
            j = i + 1
            while j < len(line) and (line[j].isdigit() or line[j] in ".-+"):
                j += 1
            if line[i].isalpha():
                value = float(line[i + 1:j]) if j > i + 1 else 0.0
                (gs.append(value) if line[i] == "G" else words.__setitem__(line[i], value))
            i = max(j, i + 1)
        for g in gs:
            if g in (0, 1, 2, 3):
                mode = int(g)
        if "F" in words:
            feed = words["F"] / 60.0
        if not any(k in words for k in "XYZ"):
            continue
        end = [words.get("X", pos[0]), words.get("Y", pos[1]), words.get("Z", pos[2])]
        if end == pos and mode in (0, 1):
            continue  # a full circle (G2/G3 back to its start) is kept
        if mode in (0, 1):
            out.append(("line", pos, end, None, False, feed if mode == 1 else math.inf))
        else:
            out.append(("arc", pos, end, [pos[0] + words.get("I", 0.0), pos[1] + words.get("J", 0.0)], mode == 2, feed))
        pos = end
    return out


class Piece:
    """Exact q(s), q'(s), q''(s) of one move."""

    def __init__(self, move):
        kind, a, b, centre, clockwise, feed = move
        self.feed = feed
        self.kind = kind
        if kind == "line":
            d = [b[k] - a[k] for k in range(3)]
            self.length = math.sqrt(sum(x * x for x in d))
            self.dir = [x / self.length for x in d]
            return
        self.c = centre
        self.r = math.hypot(a[0] - centre[0], a[1] - centre[1])
        self.a0 = math.atan2(a[1] - centre[1], a[0] - centre[0])
        a1 = math.atan2(b[1] - centre[1], b[0] - centre[0])
        sweep = (self.a0 - a1) if clockwise else (a1 - self.a0)
        while sweep <= 1e-9:
            sweep += 2 * math.pi
        self.sign = -1.0 if clockwise else 1.0
        planar = self.r * sweep
        self.dz = b[2] - a[2]
        self.length = math.hypot(planar, self.dz)
        self.k = sweep / self.length  # rad per mm of s

    def derivatives(self, s):
        return self.derivatives3(s)[:2]

    def derivatives3(self, s):
        """First, second and third derivative of q at s."""
        if self.kind == "line":
            return self.dir, [0.0, 0.0, 0.0], [0.0, 0.0, 0.0]
        th = self.a0 + self.sign * self.k * s
        rk = self.r * self.k
        d1 = [-self.sign * rk * math.sin(th), self.sign * rk * math.cos(th), self.dz / self.length]
        d2 = [-rk * self.k * math.cos(th), -rk * self.k * math.sin(th), 0.0]
        d3 = [self.sign * rk * self.k * self.k * math.sin(th), -self.sign * rk * self.k * self.k * math.cos(th), 0.0]
        return d1, d2, d3


def bounds(d1, d2, amax):
    """sddot bounds as (alpha, beta) lines in u: lower_i = al + bl u, upper_i = au + bu u."""
    lows, ups, caps = [], [], []
    for i in range(3):
        if abs(d1[i]) > 1e-12:
            p = ((-amax) / d1[i], -d2[i] / d1[i])
            q = (amax / d1[i], -d2[i] / d1[i])
            lo, hi = (p, q) if d1[i] > 0 else (q, p)
            lows.append(lo)
            ups.append(hi)
        elif abs(d2[i]) > 1e-15:
            caps.append(amax / abs(d2[i]))
    return lows, ups, caps


def mvc(d1, d2, feed, vmax, amax):
    u = (feed / math.sqrt(sum(x * x for x in d1))) ** 2 if math.isfinite(feed) else math.inf
    for i in range(3):
        if abs(d1[i]) > 1e-12:
            u = min(u, (vmax / abs(d1[i])) ** 2)
    lows, ups, caps = bounds(d1, d2, amax)
    for c in caps:
        u = min(u, c)
    for al, bl in lows:
        for au, bu in ups:
            if bl - bu > 1e-15:
                u = min(u, (au - al) / (bl - bu))
    return u


def sddot_range(d1, d2, u, amax):
    lows, ups, _ = bounds(d1, d2, amax)
    return max(a + b * u for a, b in lows), min(a + b * u for a, b in ups)


def sddot_range_jerk(d1, d2, d3, u, amax, jmax):
    """sddot bounds at u, with (jmax given) the jerk the path itself takes at speed sqrt(u) and
    path acceleration sddot, the path jerk term q'(s) * sdddot left out:
    |d3_i * sdot^3 + 3 * d2_i * sdot * sddot| <= jmax, linear in sddot for a given u."""
    lo, hi = sddot_range(d1, d2, u, amax)
    if jmax is None or u <= 0:
        return lo, hi
    sdot = math.sqrt(u)
    for i in range(3):
        turning = d3[i] * sdot ** 3
        if abs(d2[i]) > 1e-15:
            b1 = (jmax - turning) / (3 * d2[i] * sdot)
            b2 = (-jmax - turning) / (3 * d2[i] * sdot)
            lo, hi = max(lo, min(b1, b2)), min(hi, max(b1, b2))
        elif abs(turning) > jmax:
            return 1.0, -1.0
    return lo, hi


def mvc_jerk(d1, d2, d3, feed, vmax, amax, jmax):
    """The largest u at which some sddot keeps every axis's speed, acceleration and (jmax
    given) jerk as in sddot_range_jerk: the acceleration-only curve, lowered by bisection."""
    u = mvc(d1, d2, feed, vmax, amax)
    if jmax is None or not any(abs(x) > 1e-15 for x in d2 + d3):
        return u
    low, high = sddot_range_jerk(d1, d2, d3, u, amax, jmax)
    if low <= high:
        return u
    lo_u, hi_u = 0.0, u
    for _ in range(50):
        mid = 0.5 * (lo_u + hi_u)
        low, high = sddot_range_jerk(d1, d2, d3, mid, amax, jmax)
        if low <= high:
            lo_u = mid
        else:
            hi_u = mid
    return lo_u


def topp_time(pieces, stops, points, vmax, amax, jmax=None):
    total = sum(p.length for p in pieces)
    ds_target = total / points
    grid = []  # (ds, d1, d2, d3, feed, forced_stop)
    for n, p in enumerate(pieces):
        m = max(2, math.ceil(p.length / ds_target))
        for k in range(m):
            s = p.length * k / m
            d1, d2, d3 = p.derivatives3(s)
            grid.append((p.length / m, d1, d2, d3, p.feed, k == 0 and n in stops))
    d1, d2, d3 = pieces[-1].derivatives3(pieces[-1].length)
    grid.append((0.0, d1, d2, d3, pieces[-1].feed, True))
    caps = [0.0 if g[5] else mvc_jerk(g[1], g[2], g[3], g[4], vmax, amax, jmax) for g in grid]
    caps[0] = 0.0
    u = caps[:]
    u[0] = 0.0
    for k in range(len(grid) - 1):
        _, hi = sddot_range_jerk(grid[k][1], grid[k][2], grid[k][3], u[k], amax, jmax)
        u[k + 1] = min(u[k + 1], max(0.0, u[k] + 2 * grid[k][0] * max(hi, 0.0)))
    for k in range(len(grid) - 2, -1, -1):
        lo, _ = sddot_range_jerk(grid[k + 1][1], grid[k + 1][2], grid[k + 1][3], u[k + 1], amax, jmax)
        u[k] = min(u[k], max(0.0, u[k + 1] - 2 * grid[k][0] * min(lo, 0.0)))
    t = 0.0
    for k in range(len(grid) - 1):
        denominator = math.sqrt(u[k]) + math.sqrt(u[k + 1])
        if grid[k][0] > 0:
            t += 2 * grid[k][0] / denominator if denominator > 0 else math.inf
    return t, len(grid)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("program")
    ap.add_argument("--vmax", type=float, default=100.0)
    ap.add_argument("--amax", type=float, default=500.0)
    ap.add_argument("--jmax", type=float, default=None,
                    help="also keep the jerk the path takes at each point (docs/planner.md)")
    ap.add_argument("--kink-rad", type=float, default=1e-3)
    ap.add_argument("--start-points", type=int, default=4000)
    ap.add_argument("--max-points", type=int, default=2_000_000)
    args = ap.parse_args()
    pieces = [Piece(m) for m in parse(open(args.program).read())]
    stops = {0}
    for n in range(1, len(pieces)):
        a, _ = pieces[n - 1].derivatives(pieces[n - 1].length)
        b, _ = pieces[n].derivatives(0.0)
        dot = max(-1.0, min(1.0, sum(x * y for x, y in zip(a, b))))
        if math.acos(dot) > args.kink_rad:
            stops.add(n)
    refinements = []
    points, previous = args.start_points, None
    while points <= args.max_points:
        t, n = topp_time(pieces, stops, points, args.vmax, args.amax, args.jmax)
        refinements.append([n, t])
        if previous is not None and abs(t - previous) < 1e-4 * t:
            break
        previous, points = t, points * 2
    print(json.dumps({"program": args.program, "time_s": refinements[-1][1], "grid_points": refinements[-1][0],
                      "refinements": refinements, "corners": len(stops) - 1,
                      "converged": len(refinements) > 1 and abs(refinements[-1][1] - refinements[-2][1]) < 1e-4 * refinements[-1][1]}))


if __name__ == "__main__":
    sys.exit(main())
