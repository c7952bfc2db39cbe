#!/usr/bin/python3
"""LinuxCNC's splines (G5, G5.1, G5.2/G5.3): nckit's biarcs against LinuxCNC's own curve points.

rs274 2.9 prints a spline only as `NURBS_FEED(n, ...)`. LinuxCNC's `gcode` Python module (its
preview's interpreter, Debian's python3 only) runs the same interpreter and evaluates the curve
with LinuxCNC's own NURBS code at 15 (n + 1) steps of its parameter; nckit's biarcs join at
4 (n + 1) steps. Every 15th preview point is a parameter value both use: there nckit's arcs
must join, to 1e-6 mm, and the curve must end where LinuxCNC's ends. Programs: G17 splines
(2.9 refuses G5.2 in G18/G19), each file one or more splines.
Exit status: 0 when every shared point matches, 1 otherwise.
"""

import argparse
import fcntl
import json
import math
import os
import subprocess
import tempfile
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
MACHINE = HERE / "linuxcnc_mill.toml"
TOLERANCE_MM = 1e-6


class PreviewCanon:
    """The callbacks LinuxCNC's gcode module calls; feeds are kept (inches, as it reports)."""

    parameter_file = ""

    def __init__(self):
        self.feeds = []  # (line, x, y)
        self.line = 0

    def __getattr__(self, name):
        if name.startswith("__"):
            raise AttributeError(name)
        return lambda *args, **kwargs: None

    def next_line(self, code):
        self.line = code.sequence_number

    def straight_feed(self, x, y, *rest):
        self.feeds.append((self.line, x * 25.4, y * 25.4))

    def get_tool(self, pocket):
        return (pocket, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0)

    def get_external_tool_table(self):
        return []

    def get_axis_mask(self):
        return 0x1FF

    def get_block_delete(self):
        return False

    def get_external_length_units(self):
        return 1.0 / 25.4

    def get_external_angular_units(self):
        return 1.0

    def check_abort(self):
        return False


def preview_points(program: Path) -> dict[int, list[tuple[float, float]]]:
    """LinuxCNC's curve points of every spline block, by source line, mm."""
    import gcode  # LinuxCNC's module (package linuxcnc-uspace), Debian's python3

    canon = PreviewCanon()
    path = str(program.resolve())
    here = os.getcwd()
    with tempfile.TemporaryDirectory(prefix="nckit-splines-") as scratch:
        os.chdir(scratch)  # LinuxCNC's interpreter writes its parameter file where it runs
        try:
            result = gcode.parse(path, canon, "G21", "")  # nckit's machine starts in mm
        finally:
            os.chdir(here)
    if result[0] > 5:  # INTERP_MIN_ERROR
        raise RuntimeError(f"LinuxCNC's interpreter refuses {program.name}: {result}")
    by_line: dict[int, list[tuple[float, float]]] = {}
    for line, x, y in canon.feeds:
        by_line.setdefault(line, []).append((x, y))
    return by_line


def nckit_ends(nckit: str, program: Path) -> dict[int, list[tuple[float, float]]]:
    proc = subprocess.run([nckit, "moves", str(program), "--json", "--machine", str(MACHINE)],
                          capture_output=True, text=True, timeout=60, check=False)
    if proc.returncode != 0:
        raise RuntimeError(f"nckit refuses {program.name}: {proc.stderr.strip()}")
    by_line: dict[int, list[tuple[float, float]]] = {}
    for text in proc.stdout.splitlines():
        move = json.loads(text)
        if move.get("kind") in ("arc", "linear"):
            by_line.setdefault(move["line"], []).append((move["end"]["X"], move["end"]["Y"]))
    return by_line


def check(program: Path, nckit: str) -> tuple[list[str], int]:
    failures = []
    compared = 0
    preview = preview_points(program)
    ours = nckit_ends(nckit, program)
    splines = 0
    for line, points in preview.items():
        # A spline block gives 15 (n + 1) points, the last one its end (one more when the
        # preview's summed parameter falls short of the end by a rounding error).
        if len(points) < 45 or len(points) % 15 > 1:
            continue
        splines += 1
        ends = ours.get(line, [])
        steps = 15 * (len(points) // 15)
        shared = [points[j - 1] for j in range(15, steps, 15)] + [points[-1]]
        compared += len(shared)
        for x, y in shared:
            nearest = min((math.hypot(x - ex, y - ey) for ex, ey in ends), default=math.inf)
            if nearest > TOLERANCE_MM:
                failures.append(f"{program.name}:{line}: LinuxCNC's point ({x:.6f}, {y:.6f}) is "
                                f"{nearest:.2e} mm from nckit's nearest arc end")
        if ends and math.hypot(ends[-1][0] - points[-1][0], ends[-1][1] - points[-1][1]) > TOLERANCE_MM:
            failures.append(f"{program.name}:{line}: the spline ends at {ends[-1]}, LinuxCNC's at {points[-1]}")
    if splines == 0:
        failures.append(f"{program.name}: no spline found in LinuxCNC's output")
    return failures, compared


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("programs", nargs="+", type=Path)
    ap.add_argument("--nckit", required=True)
    ap.add_argument("--lock", type=Path, default=None, help="hold an flock on this file for the run")
    args = ap.parse_args()
    if args.lock is not None:
        lock_file = open(args.lock, "a")  # noqa: SIM115 - held until the process exits
        fcntl.flock(lock_file, fcntl.LOCK_EX)
    failures = []
    for program in args.programs:
        compared = 0
        try:
            found, compared = check(program, args.nckit)
        except RuntimeError as e:
            found = [str(e)]
        print(("FAIL " if found else "ok ") + f"{program.name} ({compared} points compared)", flush=True)
        failures += found
    for f in failures:
        print(f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
