#!/usr/bin/env python3
"""Runs every real lathe program beside this file through `nckit moves --json` on the machine
programs.csv names for it (corpus_lathe.toml: the example lathe, Fanuc G-code system A, with
longer travel; corpus_lathe_b.toml: the same in system B; corpus_lathe_haas.toml: the Haas lathe,
system A read as a Haas control reads it) and reports how many nckit accepts,
in all and per source repository. For each accepted program the
moves are checked: every cutting move has a positive feed, and every roughing feed of a G71 or
G73 (lines and arcs, the arcs in chords) stays on or outside the finished shape that its G70
cuts (the cycle never cuts into the finishing allowance). Exit status 1 when fewer than --min-accepted programs pass or a check
fails. `--list` prints each program's status (the table in BENCHMARKS.md)."""
import argparse
import csv
import json
import math
import pathlib
import re
import subprocess
import sys

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parents[1]
# G71 (stock removal) and G73 (pattern repeating) with their shape: P before Q, as written.
CYCLE_RE = re.compile(r"G0?7[13]\s*(?:[UW][-+.\d]*\s*)*P0*(\d+)\s*Q0*(\d+)", re.I)
SEQ_RE = re.compile(r"^\s*N0*(\d+)", re.I)


def shape_lines(text: str, p: str, q: str):
    first = last = None
    for number, line in enumerate(text.splitlines(), 1):
        m = SEQ_RE.match(line)
        if m and m.group(1) == p and first is None:
            first = number
        if m and m.group(1) == q and first is not None:
            last = number
            break
    return first, last


def profile_x_at(segments, z):
    """X (radius) of the finished shape at z, from its feed lines; None where it does not reach."""
    best = None
    for (z0, x0), (z1, x1) in segments:
        lo, hi = min(z0, z1), max(z0, z1)
        if z < lo - 1e-9 or z > hi + 1e-9:
            continue
        x = max(x0, x1) if abs(z1 - z0) < 1e-12 else x0 + (z - z0) / (z1 - z0) * (x1 - x0)
        best = x if best is None else min(best, x)  # on a face: its low end bounds the part
    return best


def segments_of(move: dict) -> list:
    """A feed move as (Z, X) segments: a line as itself, an arc in 16 chords (in the ZX plane,
    counterclockwise is the angle from +Z towards +X increasing)."""
    a = (move["start"]["Z"], move["start"]["X"])
    b = (move["end"]["Z"], move["end"]["X"])
    if move["kind"] != "arc":
        return [(a, b)]
    cz, cx = move["center"]["Z"], move["center"]["X"]
    t0 = math.atan2(a[1] - cx, a[0] - cz)
    sweep = math.atan2(b[1] - cx, b[0] - cz) - t0
    if move["dir"] == "ccw":
        while sweep <= 0:
            sweep += 2 * math.pi
    else:
        while sweep >= 0:
            sweep -= 2 * math.pi
    r = math.hypot(a[0] - cz, a[1] - cx)
    points = [a] + [(cz + r * math.cos(t0 + sweep * k / 16), cx + r * math.sin(t0 + sweep * k / 16))
                    for k in range(1, 16)] + [b]
    return list(zip(points, points[1:]))


def check_program(path: pathlib.Path, moves: list) -> list:
    problems = []
    for m in moves:
        if m["kind"] in ("linear", "arc", "sync"):
            if not (m.get("feed_mm_min", 0) > 0 or m.get("feed_mm_rev", 0) > 0):
                problems.append(f"line {m['line']}: cutting move without a feed")
    text = path.read_text(errors="replace")
    for number, line in enumerate(text.splitlines(), 1):
        cycle = CYCLE_RE.search(line.split("(")[0])
        if not cycle:
            continue
        first, last = shape_lines(text, cycle.group(1), cycle.group(2))
        if first is None or last is None:
            continue
        shape = [seg for m in moves if first <= m["line"] <= last and m["kind"] in ("linear", "arc")
                 for seg in segments_of(m)]
        rough = [m for m in moves if m["line"] == number and m["kind"] in ("linear", "arc")]
        if not shape or not rough:
            continue
        # Outside turning when the cycle starts above the shape: for G71 where its first feed
        # begins (on A's level), for G73 at A itself (its first feed begins on the moved shape).
        pattern = re.search(r"G0?73", line.split("(")[0], re.I) is not None
        start_x = (next(m for m in moves if m["line"] == number and "start" in m) if pattern else rough[0])["start"]["X"]
        if start_x < max(max(a[1], b[1]) for a, b in shape) - 1e-9:
            continue  # an inside shape or a start below it: the check is for outside turning
        for m in rough:
            for _, (z, x) in segments_of(m):
                limit = profile_x_at(shape, z)
                if limit is not None and x < limit - 1e-6:
                    problems.append(
                        f"line {number}: roughing reaches X{x:.4f} at Z{z:.4f}, inside the shape (X{limit:.4f})")
                    break
    return problems


def read_list() -> dict:
    """programs.csv: file -> (machine file, source repository); every *.nc must be listed."""
    with open(HERE / "programs.csv", newline="", encoding="utf-8") as f:
        return {row["file"]: (row["machine"], row["repository"]) for row in csv.DictReader(f)}


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("nckit")
    parser.add_argument("--min-accepted", type=int, default=0)
    parser.add_argument("--list", action="store_true")
    args = parser.parse_args()
    listed = read_list()
    programs = sorted(HERE.glob("*.nc"))
    accepted = 0
    # The corpus as it grew: the first 32 programs (01-34), the 41 after heu-icicles (to 43), the
    # 47 after enier290188/cnc's history (to 49), all.
    stages = {34: [0, 0], 43: [0, 0], 49: [0, 0]}
    failures = [f"{p.name}: not in programs.csv" for p in programs if p.name not in listed]
    per_source = {}
    for program in programs:
        machine, source = listed.get(program.name, ("corpus_lathe.toml", "?"))
        tally = per_source.setdefault(source, [0, 0])
        tally[1] += 1
        number = int(program.name.split("_")[0])
        in_stages = [stage for last, stage in stages.items() if number <= last]
        for stage in in_stages:
            stage[1] += 1
        run = subprocess.run([args.nckit, "moves", str(program), "--machine", str(HERE / machine), "--json"],
                             capture_output=True, text=True, timeout=120)
        if run.returncode != 0:
            lines = run.stderr.strip().splitlines()
            errors = [line for line in lines if ": error:" in line]  # warnings (a tape leader) may come first
            first = (errors or lines or [f"exit {run.returncode}"])[0]
            if args.list:
                print(f"| {program.name} | refused | {first.replace(str(HERE) + '/', '')} |")
            continue
        accepted += 1
        tally[0] += 1
        for stage in in_stages:
            stage[0] += 1
        moves = [json.loads(line) for line in run.stdout.splitlines() if line.strip()]
        problems = check_program(program, moves)
        failures += [f"{program.name}: {p}" for p in problems]
        if args.list:
            print(f"| {program.name} | accepted | {len(moves)} moves{'; ' + problems[0] if problems else ''} |")
    for source, (n_ok, n_all) in per_source.items():
        print(f"{source}: accepted {n_ok} of {n_all}")
    for last, (n_ok, n_all) in stages.items():
        print(f"programs 01-{last}: accepted {n_ok} of {n_all} ({100.0 * n_ok / max(1, n_all):.0f} %)")
    print(f"accepted {accepted} of {len(programs)} ({100.0 * accepted / max(1, len(programs)):.1f} %)")
    for f in failures:
        print(f"FAIL {f}")
    if accepted < args.min_accepted:
        print(f"FAIL fewer than {args.min_accepted} programs accepted")
        return 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
