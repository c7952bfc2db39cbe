"""The grid and the LPs of the jerk-limited reference (bench/jerk_reference.py, whose docstring
and docs/planner.md "The jerk-limited reference" describe the formulation)."""
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
    sys.exit("jerk_reference: needs numpy and scipy (Debian python3-scipy: scripts/deps.sh bench)")

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
        try:
            candidate = lp(g, sparse.vstack([a_acc, a_jerk]).tocsr(), np.concatenate([b_acc, b_jerk]))
        except RuntimeError as error:
            # The current profile keeps every row: keep it when a later LP fails numerically
            # (grids graded to 1e-10 mm at rest points), and say so.
            if not feasible:
                raise
            print(f"jerk_reference: iteration {iterations} kept the profile before: {error}", file=sys.stderr)
            break
        if feasible:
            u_next, t_next = line_search(grid, u, candidate)
        else:
            u_next, t_next, feasible = candidate, cycle_time(grid, candidate), True
        change = abs(t - t_next) / t_next if math.isfinite(t) else math.inf
        u, t = u_next, t_next
        if change < tolerance:
            break
    return t, iterations, u
