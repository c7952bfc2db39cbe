#!/usr/bin/env python3
"""Axis limits and path deviation seen from outside: `nckit plan --trace --period 0.0001`.

Positions of the trace (not its analytic v/a/j columns) are differenced: per axis
|v| <= 1.001 vmax, |a| <= 1.005 amax and, for the S-curve, |j| <= 1.01 jmax. A finite difference
of order k over k+1 samples is a weighted mean of the k-th derivative over those samples, so a
trajectory that keeps its limits at every instant passes; a step in acceleration (a jerk spike)
shows up as a difference of size step / period. Every traced point also has to lie within the
program's G64 P tolerance of the programmed path (lines, arcs, helices in G17).

Programs: the planner benchmark programs (bench/planner_programs) and seeded random programs
mixing lines, arcs both ways, helices, end points rounded to 3 or 4 decimals and G64 tolerances.
Machine: X, Y, Z with 100 mm/s, 500 mm/s^2 and jerk 50,000 or 5,000 mm/s^3.

Usage: trace_limits_test.py NCKIT [--quick] [PROGRAM ...]
"""
import math
import pathlib
import random
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[2]
PROGRAMS = ROOT / "bench" / "planner_programs"
PERIOD_S = 1e-4
VMAX, AMAX = 100.0, 500.0
failures = []


def machine_file(folder, jerk):
    path = pathlib.Path(folder) / f"machine_j{int(jerk)}.toml"
    text = '[machine]\nname = "limits"\nservo_period_s = 0.001\n\n'
    for axis in "XYZ":
        text += (f'[[axis]]\nname = "{axis}"\nkind = "linear"\nmax_velocity = {VMAX}\n'
                 f"max_acceleration = {AMAX}\nmax_jerk = {jerk}\nmin = -1000.0\nmax = 1000.0\n"
                 "steps_per_unit = 1000.0\n\n")
    path.write_text(text)
    return path


# ---- the programmed path (the subset the programs here use: G17, absolute, G1/G2/G3, G64 P, G61)
def programmed_path(text):
    """[(kind, start, end, centre, clockwise, tolerance)] in program order."""
    pos = [0.0, 0.0, 0.0]
    mode, tolerance = 1, 0.0
    out = []
    for raw in text.splitlines():
        line = raw.split("(")[0].strip().upper()
        if not line or line.startswith("%"):
            continue
        words = {}
        gs = []
        i = 0
        while i < len(line):
            letter = line[i]
            j = i + 1
            while j < len(line) and (line[j].isdigit() or line[j] in ".-+"):
                j += 1
            if letter.isalpha():
                value = float(line[i + 1:j]) if j > i + 1 else 0.0
                if letter == "G":
                    gs.append(value)
                else:
                    words[letter] = value
            i = max(j, i + 1)
        for g in gs:
            if g in (0, 1, 2, 3):
                mode = int(g)
            if g == 64:
                tolerance = words.get("P", 0.0)
            if g == 61:
                tolerance = 0.0
        if not any(k in words for k in "XYZ"):
            continue
        end = [words.get("X", pos[0]), words.get("Y", pos[1]), words.get("Z", pos[2])]
        if mode in (0, 1):
            out.append(("line", pos[:], end, None, False, tolerance))
        else:
            centre = [pos[0] + words.get("I", 0.0), pos[1] + words.get("J", 0.0)]
            out.append(("arc", pos[:], end, centre, mode == 2, tolerance))
        pos = end
    return out


def distance(point, piece):
    kind, a, b, centre, clockwise, _ = piece
    if kind == "line":
        d = [b[k] - a[k] for k in range(3)]
        dd = sum(x * x for x in d)
        t = 0.0 if dd == 0 else max(0.0, min(1.0, sum((point[k] - a[k]) * d[k] for k in range(3)) / dd))
        return math.dist(point, [a[k] + t * d[k] for k in range(3)])
    r0 = math.hypot(a[0] - centre[0], a[1] - centre[1])
    a0 = math.atan2(a[1] - centre[1], a[0] - centre[0])
    a1 = math.atan2(b[1] - centre[1], b[0] - centre[0])
    sweep = (a0 - a1) if clockwise else (a1 - a0)
    while sweep <= 1e-12:
        sweep += 2 * math.pi
    ap = math.atan2(point[1] - centre[1], point[0] - centre[0])
    along = (a0 - ap) if clockwise else (ap - a0)
    along %= 2 * math.pi
    best = min(math.dist(point, a), math.dist(point, b))
    if along <= sweep:
        f = along / sweep
        r1 = math.hypot(b[0] - centre[0], b[1] - centre[1])
        r = r0 + f * (r1 - r0)
        z = a[2] + f * (b[2] - a[2])
        radial = math.hypot(point[0] - centre[0], point[1] - centre[1]) - r
        best = min(best, math.hypot(radial, point[2] - z))
    return best


def read_trace(path):
    rows = []
    with open(path) as f:
        next(f)
        for line in f:
            parts = line.split(",", 4)
            rows.append((float(parts[1]), float(parts[2]), float(parts[3])))
    return rows


def check(name, nckit, program, machine, profile, jerk, folder):
    trace = pathlib.Path(folder) / "trace.csv"
    run = subprocess.run([nckit, "plan", str(program), "--machine", str(machine), "--profile", profile,
                          "--trace", str(trace), "--period", str(PERIOD_S)],
                         capture_output=True, text=True, timeout=600)
    label = f"{name} {profile}" + (f" j{int(jerk)}" if profile == "scurve" else "")
    if run.returncode != 0:
        failures.append(f"{label}: nckit plan failed: {run.stderr.strip()}")
        print(f"FAIL {failures[-1]}")
        return
    rows = read_trace(trace)
    h = PERIOD_S
    worst = [0.0, 0.0, 0.0]  # v, a, j as fractions of the limits
    for axis in range(3):
        q = [r[axis] for r in rows]
        n = len(q)
        for k in range(n - 1):
            worst[0] = max(worst[0], abs(q[k + 1] - q[k]) / h / VMAX)
        for k in range(1, n - 1):
            worst[1] = max(worst[1], abs(q[k + 1] - 2 * q[k] + q[k - 1]) / (h * h) / AMAX)
        if profile == "scurve":
            for k in range(1, n - 2):
                worst[2] = max(worst[2], abs(q[k + 2] - 3 * q[k + 1] + 3 * q[k] - q[k - 1]) / (h ** 3) / jerk)
    path = programmed_path(program.read_text())
    deviation_excess = 0.0
    at = 0
    # A transition between moves i and i+1 uses move i's tolerance, so a point near move i may be
    # off it by the larger of its own and its predecessor's. Paths may cross themselves: the
    # excess is the smallest over the moves near the point's place in the program.
    allowed = [max(path[i][5], path[i - 1][5] if i > 0 else 0.0) for i in range(len(path))]
    for k in range(0, len(rows), 2):
        p = rows[k]
        lo, hi = max(0, at - 3), min(len(path), at + 12)
        best, best_i = math.inf, at
        for i in range(lo, hi):
            excess = distance(p, path[i]) - allowed[i]
            if excess < best:
                best, best_i = excess, i
        if best > 1e-3:  # lost the place (a crossing path took it): look at every move
            for i in range(len(path)):
                excess = distance(p, path[i]) - allowed[i]
                if excess < best:
                    best, best_i = excess, i
        at = best_i
        deviation_excess = max(deviation_excess, best)
    limits = [1.001, 1.005, 1.01]
    status = []
    for what, value, limit in zip("vaj", worst, limits):
        if value > limit:
            status.append(f"|{what}| {value:.4g}x limit")
    # An arc whose written end point is off its circle (rounded decimals) has no single exact
    # programmed path: nckit spreads the mismatch linearly along the arc, this check
    # interpolates the radius; the two differ by well under a micrometre.
    if deviation_excess > 1e-3:
        status.append(f"path deviation {deviation_excess * 1000:.4g} um beyond G64 P")
    print(f"{'FAIL' if status else 'ok  '} {label}: v {worst[0]:.4f} a {worst[1]:.4f} j {worst[2]:.4f} of the limits, "
          f"{len(rows)} samples" + (": " + ", ".join(status) if status else ""))
    if status:
        failures.append(f"{label}: " + ", ".join(status))


def rounded(value, decimals):
    return round(value, decimals)


def random_program(seed):
    """About 25 moves: lines, G2/G3 arcs (some helical), 3- or 4-decimal end points, G64 P / G61."""
    rng = random.Random(seed)
    decimals = rng.choice([3, 4])
    lines = ["%", f"(random program, seed {seed})", "G21 G17 G90 G94", f"G64 P{rng.choice([0.005, 0.01, 0.05])}"]
    pos = [0.0, 0.0, 0.0]
    feed = rng.choice([3000, 6000])
    lines.append(f"G1 X0. Y0. Z0. F{feed}")
    heading = rng.uniform(0, 2 * math.pi)
    for _ in range(25):
        roll = rng.random()
        if roll < 0.05:
            lines.append("G61")
        elif roll < 0.12:
            lines.append(f"G64 P{rng.choice([0.002, 0.01, 0.02, 0.1])}")
        kind = rng.random()
        if kind < 0.45:
            # a line, often nearly along the last heading (CAM polylines), sometimes a corner
            heading += rng.choice([rng.uniform(-0.2, 0.2), rng.uniform(-2.5, 2.5)])
            length = rng.choice([rng.uniform(0.05, 1.0), rng.uniform(1, 15)])
            end = [pos[0] + length * math.cos(heading), pos[1] + length * math.sin(heading),
                   pos[2] + (rng.uniform(-1, 1) if rng.random() < 0.2 else 0.0)]
            end = [rounded(x, decimals) for x in end]
            if end == pos:
                continue
            lines.append(f"G1 X{end[0]:.{decimals}f} Y{end[1]:.{decimals}f} Z{end[2]:.{decimals}f}")
        else:
            # an arc starting (nearly) tangent to the last heading, either way, sometimes a helix
            r = rng.uniform(1.0, 12.0)
            clockwise = rng.random() < 0.5
            side = -1 if clockwise else 1
            normal = heading + side * math.pi / 2
            centre = [pos[0] + r * math.cos(normal), pos[1] + r * math.sin(normal)]
            sweep = rng.uniform(0.3, 3.5)
            start_angle = math.atan2(pos[1] - centre[1], pos[0] - centre[0])
            end_angle = start_angle - sweep if clockwise else start_angle + sweep
            z = pos[2] + (rng.uniform(-2, 2) if rng.random() < 0.3 else 0.0)
            end = [rounded(centre[0] + r * math.cos(end_angle), decimals),
                   rounded(centre[1] + r * math.sin(end_angle), decimals), rounded(z, decimals)]
            i, j = rounded(centre[0] - pos[0], decimals), rounded(centre[1] - pos[1], decimals)
            word = "G2" if clockwise else "G3"
            lines.append(f"{word} X{end[0]:.{decimals}f} Y{end[1]:.{decimals}f} Z{end[2]:.{decimals}f} "
                         f"I{i:.{decimals}f} J{j:.{decimals}f}")
            heading = end_angle - math.pi / 2 if clockwise else end_angle + math.pi / 2
        pos = end
    return "\n".join(lines + ["M2", "%"]) + "\n"


def main():
    nckit = sys.argv[1]
    args = sys.argv[2:]
    quick = "--quick" in args
    names = [a for a in args if not a.startswith("--")]
    fixed = names or ["semicircles_20.ngc", "square_100.ngc", "slot.ngc", "slot_f6000.ngc", "circle_g2.ngc",
                      "circle_2000.ngc", "circle_8arcs.ngc", "raster_3d.ngc"]
    with tempfile.TemporaryDirectory() as folder:
        programs = []
        for name in fixed:
            path = PROGRAMS / name
            if name == "semicircles_20.ngc":  # the first 20 of the 100, to keep the test short
                text = (PROGRAMS / "semicircles_100.ngc").read_text().splitlines()
                path = pathlib.Path(folder) / name
                path.write_text("\n".join(text[:24] + ["M2", "%"]) + "\n")
            programs.append((name, path))
        if not names:
            for seed in range(1, 3 if quick else 7):
                path = pathlib.Path(folder) / f"random_{seed}.ngc"
                path.write_text(random_program(seed))
                programs.append((path.name, path))
        for jerk in (50000.0, 5000.0):
            machine = machine_file(folder, jerk)
            for name, path in programs:
                if jerk == 50000.0:
                    check(name, nckit, path, machine, "trapezoid", jerk, folder)
                check(name, nckit, path, machine, "scurve", jerk, folder)
    print(f"{len(failures)} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
