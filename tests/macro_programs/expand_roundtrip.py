#!/usr/bin/env python3
"""Round trip of `nckit expand`: the expanded program must make the same moves as the original.

For every program (`NN_name.nc` or `NN_name.ngc`) it runs `nckit expand PROGRAM -o expanded.ngc`,
then `nckit moves --json` on the original and on the expanded program (same machine), and
compares the two record streams in order: every record's kind; for rapids, feeds, arcs and
synchronised moves the end point on every axis, for arcs the centre, direction, plane and turns,
the feed (`feed_mm_min`, and `feed_mm_rev` under G95), all to 1e-9 (mm, deg, mm/min, mm/rev): expand
writes as many decimals as it takes to read back the same doubles; and
whether the move ends in an exact stop (G61, G9); for dwells the time (1e-9 s); for I/O events the
code and its spindle speed. Source lines differ by design and are not compared.

The machine comes from a `( nckit-machine: FILE )` comment in the program's first 5 lines
(resolved against examples/machines/), or from --machine for every program, block delete from
`( nckit-block-delete: on )`, as in tests/programs/compare_linuxcnc.py. Called programs are looked up in --library (default: the
programs folder's `library/` when there is one); retained variables go to scratch files.

Exit status: 0 when every program round-trips, 1 otherwise.
"""

from __future__ import annotations

import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
DEFAULT_NCKIT = REPO / "build" / "release" / "src" / "nckit"
DEFAULT_MACHINES = REPO / "examples" / "machines"

TOL = 1e-9
DWELL_TOL_S = 1e-9
MOTION_KINDS = {"rapid", "linear", "arc", "sync"}
DIRECTIVE_RE = re.compile(r"nckit-(machine|block-delete)\s*:\s*([^\s)]+)", re.IGNORECASE)


class Failure(Exception):
    pass


def setup_of(program: Path, machines: Path) -> tuple[Path | None, bool]:
    """(machine file or None, block delete) from the program's first 5 lines."""
    machine, block_delete = None, False
    with open(program, encoding="utf-8", errors="replace") as f:
        for _, text in zip(range(5), f):
            for key, value in DIRECTIVE_RE.findall(text):
                if key.lower() == "machine":
                    machine = machines / value
                    if not machine.is_file():
                        raise Failure(f"machine file {machine} does not exist")
                else:
                    block_delete = value.lower() == "on"
    return machine, block_delete


def run(cmd: list[str], workdir: Path, timeout: float, what: str) -> str:
    try:
        proc = subprocess.run(cmd, cwd=workdir, stdin=subprocess.DEVNULL, capture_output=True,
                              text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        raise Failure(f"{what} timed out") from None
    if proc.returncode != 0:
        err = " | ".join(proc.stderr.strip().splitlines()[:3]) or "(no message)"
        raise Failure(f"{what}: exit status {proc.returncode}: {err}")
    return proc.stdout


def moves(args, program: Path, machine: Path | None, block_delete: bool, workdir: Path,
          vars_name: str) -> list[dict]:
    cmd = [args.nckit, "moves", str(program), "--json", "--vars", str(workdir / vars_name)]
    if machine is not None:
        cmd += ["--machine", str(machine)]
    if block_delete:
        cmd.append("--block-delete")
    if args.library is not None:
        cmd += ["--library", str(args.library)]
    out = run(cmd, workdir, args.timeout, f"nckit moves {program.name}")
    records = []
    for n, text in enumerate(out.splitlines(), start=1):
        if text.strip():
            try:
                records.append(json.loads(text))
            except json.JSONDecodeError as e:
                raise Failure(f"nckit moves {program.name}: line {n} is not JSON ({e})") from None
    return records


def close(a, b, tol: float) -> bool:
    if a is None or b is None:
        return a is None and b is None
    return abs(float(a) - float(b)) <= tol


def differ(orig: dict, back: dict) -> str | None:
    """What differs between a record of the original and of the expanded program, or None."""
    kind = orig.get("kind")
    if kind != back.get("kind"):
        return f"kind {kind} vs {back.get('kind')}"
    if kind in MOTION_KINDS:
        if set(orig["end"]) != set(back["end"]):
            return f"end axes {sorted(orig['end'])} vs {sorted(back['end'])}"
        for axis, v in orig["end"].items():
            if not close(v, back["end"][axis], TOL):
                return f"end {axis} {v} vs {back['end'][axis]}"
        if kind == "arc":
            for axis, v in orig["center"].items():
                if not close(v, back["center"].get(axis), TOL):
                    return f"centre {axis} {v} vs {back['center'].get(axis)}"
            for key in ("dir", "plane", "turns"):
                if orig.get(key) != back.get(key):
                    return f"{key} {orig.get(key)} vs {back.get(key)}"
        if bool(orig.get("exact_stop")) != bool(back.get("exact_stop")):
            return f"exact_stop {orig.get('exact_stop', False)} vs {back.get('exact_stop', False)}"
        if kind != "rapid":
            for key in ("feed_mm_min", "feed_mm_rev"):
                if not close(orig.get(key), back.get(key), TOL):
                    return f"{key} {orig.get(key)} vs {back.get(key)}"
    elif kind == "dwell":
        if not close(orig.get("seconds"), back.get("seconds"), DWELL_TOL_S):
            return f"dwell {orig.get('seconds')} s vs {back.get('seconds')} s"
    elif kind == "io":
        for key in ("code", "rpm", "surface_speed_m_min", "rpm_clamp"):
            if orig.get(key) != back.get(key) and not (
                    isinstance(orig.get(key), (int, float)) and close(orig.get(key), back.get(key), TOL)):
                return f"{key} {orig.get(key)} vs {back.get(key)}"
    return None


def round_trip(program: Path, args, workdir: Path) -> str:
    machine, block_delete = setup_of(program, args.machines)
    if args.machine is not None:
        machine = args.machine
    expanded = workdir / "expanded.ngc"
    cmd = [args.nckit, "expand", str(program), "-o", str(expanded),
           "--vars", str(workdir / "expand.vars")]
    if machine is not None:
        cmd += ["--machine", str(machine)]
    if block_delete:
        cmd.append("--block-delete")
    if args.library is not None:
        cmd += ["--library", str(args.library)]
    run(cmd, workdir, args.timeout, "nckit expand")
    if args.keep_expanded is not None:
        args.keep_expanded.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(expanded, args.keep_expanded / (program.stem + ".ngc"))
    original = moves(args, program, machine, block_delete, workdir, "original.vars")
    back = moves(args, expanded, machine, False, workdir, "expanded.vars")
    lines = expanded.read_text(encoding="utf-8", errors="replace").splitlines()
    for i, (o, b) in enumerate(zip(original, back), start=1):
        diff = differ(o, b)
        if diff:
            where = b.get("line")
            text = lines[where - 1].strip() if isinstance(where, int) and 0 < where <= len(lines) else "?"
            raise Failure(f"record {i} (original line {o.get('line')}, expanded line {where} "
                          f"`{text}`): {diff}\n    original: {json.dumps(o)}\n"
                          f"    expanded: {json.dumps(b)}")
    if len(original) != len(back):
        raise Failure(f"record count: original {len(original)}, expanded {len(back)}")
    motions = sum(1 for r in original if r.get("kind") in MOTION_KINDS)
    return f"{len(original)} records, {motions} moves"


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("names", nargs="*", help="programs to run (file name, stem or NN prefix)")
    ap.add_argument("--nckit", default=str(DEFAULT_NCKIT), help="nckit binary (%(default)s)")
    ap.add_argument("--programs", type=Path, default=HERE,
                    help="folder of NN_name.nc / .ngc programs (default: this script's folder)")
    ap.add_argument("--machines", type=Path, default=DEFAULT_MACHINES,
                    help="folder the nckit-machine comments refer to (%(default)s)")
    ap.add_argument("--machine", type=Path, default=None,
                    help="machine file for every program, in place of their nckit-machine comments")
    ap.add_argument("--library", type=Path, default=None,
                    help="folder of called programs (default: PROGRAMS/library when it exists)")
    ap.add_argument("--keep-expanded", type=Path, default=None, metavar="DIR",
                    help="keep each expanded program as DIR/STEM.ngc")
    ap.add_argument("--timeout", type=float, default=300.0, help="seconds per run (%(default)s)")
    args = ap.parse_args()

    args.programs, args.machines = args.programs.resolve(), args.machines.resolve()
    if args.machine is not None:
        args.machine = args.machine.resolve()
    if args.library is None and (args.programs / "library").is_dir():
        args.library = args.programs / "library"
    if args.library is not None:
        args.library = args.library.resolve()
    if args.keep_expanded is not None:
        args.keep_expanded = args.keep_expanded.resolve()
    args.nckit = str(Path(args.nckit).resolve()) if os.sep in args.nckit else (
        shutil.which(args.nckit) or args.nckit)
    if not os.access(args.nckit, os.X_OK):
        print(f"error: nckit binary {args.nckit} not found or not executable; build it first "
              f"or pass --nckit", file=sys.stderr)
        return 1
    programs = sorted({p for pattern in ("*.nc", "*.ngc") for p in args.programs.glob(pattern)})
    if args.names:
        chosen = []
        for name in args.names:
            hits = [p for p in programs
                    if p.name == name or p.stem == name or p.stem.startswith(name + "_")]
            if not hits:
                print(f"error: no program {name!r} in {args.programs}", file=sys.stderr)
                return 1
            chosen += [h for h in hits if h not in chosen]
        programs = chosen
    if not programs:
        print(f"error: no *.nc or *.ngc programs in {args.programs}", file=sys.stderr)
        return 1

    passed = failed = 0
    with tempfile.TemporaryDirectory(prefix="nckit-roundtrip-") as tmp:
        for program in programs:
            workdir = Path(tempfile.mkdtemp(dir=tmp))
            try:
                summary = round_trip(program, args, workdir)
            except Failure as e:
                print(f"FAIL {program.stem}: {e}", flush=True)
                failed += 1
                continue
            print(f"ok {program.stem} ({summary})", flush=True)
            passed += 1
    print(f"{passed} passed, {failed} failed")
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
