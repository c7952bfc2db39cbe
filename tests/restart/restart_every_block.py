#!/usr/bin/env python3
"""`nckit restart` at every block: the rest of the restart program makes the original's moves.

For each program and each target block B (every block of a short program, an even stride of at
most --max-targets blocks of a long one) it runs `nckit restart PROGRAM --block B --json -o
r.ngc`, then `nckit moves --json` on the original and on r.ngc. The restart program's records
from its `rest_line` on must equal the original's records from `first_record` on: same kinds,
end points, arc centres, directions, planes and turns, feeds and exact stops within 1e-9 (mm,
deg, mm/min, mm/rev), dwells within 1e-9 s, same I/O codes (the comparison of
tests/macro_programs/expand_roundtrip.py). A target that restart refuses is accepted only when
the refusal is right: `restart-mid-thread` for a G32/G33 move that follows another,
`restart-cutter-comp` for a block inside compensation (the original record must follow a move).

For every target it also checks that the preamble alone (the restart program's lines before
`rest_line`) leaves the modal state the original had at the target: the preamble with two
`G4 P0` blocks after it is restarted at the second, and its `state` must equal the target's
(numbers within 1e-9): every key of the dump, from spindle, tool, coolant and latched codes to
units, distance and diameter mode, work system and offset, G92, G52, the tool length offset and
the mirror, scaling and rotation in force with their centres and factors, on mills and on lathes
in G-code system A alike.

With --rs274 it also checks that LinuxCNC's rs274 reads the restart programs of a few blocks per
program without an error (the linuxcnc-labelled test).

Exit status: 0 when every target restarts right, 1 otherwise.
"""

from __future__ import annotations

import argparse
import json
import re
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
sys.path.insert(0, str(REPO / "tests" / "macro_programs"))
sys.path.insert(0, str(REPO / "tests" / "programs"))
from expand_roundtrip import differ  # noqa: E402  (1e-9 comparison of two move records)
from per_program import Failure, run_each  # noqa: E402

# (program, machine file or None, library folder or None), relative to the repository.
PROGRAMS = [
    ("examples/02_lathe_shaft.ngc", "examples/machines/lathe.toml", None),
    ("examples/01_mill_pocket.ngc", "examples/machines/mill.toml", None),
    ("examples/notch/conrod.nc", "examples/machines/notcher.toml", None),
    ("examples/restart/bolt_circle_loop.nc", "examples/machines/mill.toml", None),
    ("examples/restart/inch_offsets.nc", "examples/machines/mill.toml", None),
    ("tests/macro_programs/04_nested_loops_grid.nc", None, None),
    ("tests/macro_programs/09_m98_subprograms.nc", None, None),
    ("tests/macro_programs/15_library_calls.nc", None, "tests/macro_programs/library"),
    ("tests/macro_programs/17_local_offsets_g52_g92.nc", None, None),
    ("tests/macro_programs/20_pattern_g51_g68.nc", None, None),
    ("examples/restart/rotated_slots.nc", "examples/machines/mill.toml", None),
    ("examples/restart/lathe_system_a.nc", "examples/machines/lathe.toml", None),
]
# Programs whose restart programs rs274 cannot read for a reason outside the restart itself.
RS274_SKIP = {
    "examples/notch/conrod.nc": "the notcher's M24-M28 are its own I/O codes, unknown to rs274 (user M-codes are M100-M199)",
    "examples/02_lathe_shaft.ngc": "a Fanuc system A lathe program: rs274 reads LinuxCNC's lathe codes (G7/G8, G94 feed)",
    "examples/restart/lathe_system_a.nc": "a Fanuc system A lathe program (G50 S, G98/G99), as above",
    "tests/macro_programs/20_pattern_g51_g68.nc": "Fanuc's G51/G51.1/G68, which LinuxCNC has not: the preamble sets them again",
    "examples/restart/rotated_slots.nc": "Fanuc's G51/G51.1/G68, as above",
}
# Every key of the state dump: the preamble alone must leave all of them as the target had them.
STATE_KEYS = ["tool", "tool_in_spindle", "spindle", "speed", "constant_surface_speed", "rpm_clamp", "mist", "flood",
              "latched_mcodes", "plane", "feed_mode", "feed", "path", "tolerance_mm", "units", "distance",
              "diameter_mode", "work_system", "work_offset", "g92_offset", "g52_offset", "length_offset", "h",
              "tool_offset", "transforms", "transform"]
BLOCKS_RUN_RE = re.compile(r"\((\d+) blocks run\)")


def run(cmd: list[str], cwd: Path) -> subprocess.CompletedProcess:
    return subprocess.run(cmd, cwd=cwd, stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=120)


def common(machine: str | None, library: str | None, vars_file: Path) -> list[str]:
    args = ["--vars", str(vars_file)]
    if machine:
        args += ["--machine", str(REPO / machine)]
    if library:
        args += ["--library", str(REPO / library)]
    return args


def records(nckit: str, program: Path, extra: list[str], cwd: Path) -> list[dict]:
    proc = run([nckit, "moves", str(program), "--json", *extra], cwd)
    if proc.returncode != 0:
        raise Failure(f"nckit moves {program.name}: exit {proc.returncode}: {proc.stderr.strip()}")
    return [json.loads(t) for t in proc.stdout.splitlines() if t.strip()]


def check_program(args, name: str, machine: str | None, library: str | None, work: Path) -> str:
    program = REPO / name
    extra = common(machine, library, work / "vars")
    original = records(args.nckit, program, extra, work)
    probe = run([args.nckit, "restart", str(program), "--block", "999999999", *extra], work)
    found = BLOCKS_RUN_RE.search(probe.stderr)
    if probe.returncode != 2 or "not reached" not in probe.stderr or not found:
        raise Failure(f"a block beyond the end is not refused as restart-not-reached: {probe.stderr.strip()}")
    blocks = int(found.group(1))
    stride = max(1, -(-blocks // args.max_targets))
    targets = list(range(1, blocks + 1, stride))
    checked = refused = 0
    restart = work / "r.ngc"
    for block in targets:
        proc = run([args.nckit, "restart", str(program), "--block", str(block), "--json", "-o", str(restart), *extra], work)
        if proc.returncode != 0:
            if proc.returncode == 2 and ("middle of a thread pass" in proc.stderr or "inside cutter compensation" in proc.stderr):
                refused += 1
                continue
            raise Failure(f"block {block}: exit {proc.returncode}: {proc.stderr.strip()}")
        report = json.loads(proc.stdout)
        rest = [r for r in records(args.nckit, restart, extra, work) if r["line"] >= report["rest_line"]]
        expected = original[report["first_record"]:]
        if len(rest) != len(expected):
            raise Failure(f"block {block}: {len(rest)} records after the approach, the original has {len(expected)}")
        for i, (o, r) in enumerate(zip(expected, rest)):
            diff = differ(o, r)
            if diff:
                raise Failure(f"block {block}, record {report['first_record'] + i}: {diff}")
        check_preamble_state(args, restart, report, machine, extra, work)
        if args.rs274 and name not in RS274_SKIP and block in targets[:: max(1, len(targets) // 3)][:3]:
            check_rs274(args, restart, work)
        checked += 1
    if checked == 0:
        raise Failure("no block restarted")
    return f"{blocks} blocks, {checked} restarts checked, {refused} refused"


def same_value(a, b) -> bool:
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(same_value(a[k], b[k]) for k in a)
    if isinstance(a, (int, float)) and isinstance(b, (int, float)) and not isinstance(a, bool):
        return abs(a - b) <= 1e-9 * max(1.0, abs(a))
    return a == b


def check_preamble_state(args, restart: Path, report: dict, machine: str | None, extra: list[str], work: Path) -> None:
    """The preamble alone leaves the target's modal state (see the module's docstring)."""
    lines = restart.read_text().splitlines(keepends=True)[: report["rest_line"] - 1]
    preamble = work / "preamble.ngc"
    # Restarting at the second G4 reports the state in force for the first: every block of the
    # preamble has run by then.
    preamble.write_text("".join(lines) + "G4 P0\nG4 P0\nM30\n")
    proc = run([args.nckit, "restart", str(preamble), "--line", str(len(lines) + 2), "--json", "-o",
                str(work / "p.ngc"), *extra], work)
    if proc.returncode != 0:
        raise Failure(f"the preamble alone does not run: {proc.stderr.strip()}")
    state, want = json.loads(proc.stdout)["state"], report["state"]
    for key in STATE_KEYS:
        if not same_value(want[key], state[key]):
            raise Failure(f"after the preamble alone {key} is {state[key]}, at the target {want[key]}")


def check_rs274(args, restart: Path, work: Path) -> None:
    from compare_linuxcnc import run_rs274, tool_table_for, ProgramError
    try:
        out = run_rs274(args.rs274, restart, False, work, 60, tool_table_for(restart, work))
    except ProgramError as e:
        raise Failure(f"rs274 rejects {restart.name}: {e}") from None
    if "STRAIGHT_FEED" not in out and "ARC_FEED" not in out and "STRAIGHT_TRAVERSE" not in out:
        raise Failure("rs274 read the restart program but made no motion")


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--nckit", required=True)
    ap.add_argument("--max-targets", type=int, default=25, help="targets per program (%(default)s)")
    ap.add_argument("--rs274", default=None, help="also have this rs274 read a few restart programs")
    args = ap.parse_args()
    return run_each(PROGRAMS, "nckit-restart-", lambda p, work: check_program(args, *p, work))


if __name__ == "__main__":
    sys.exit(main())
